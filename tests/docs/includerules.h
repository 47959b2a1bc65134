#pragma once

// The layering of the source tree as rules over #include lines: which core folder may include
// which, which ui wing may include which, which Qt modules each part may use. docs/architecture.md
// ("Layers") states the same rules in words and tables; tst_layers checks that both agree and that
// the tree keeps them.
//
// The checker works on paths relative to the source root ("core/protocol/dissector.cpp") and a set
// of the files that exist, so a test can feed it made-up files as well as the real tree. A quoted
// include is resolved the way the compiler does it: the including file's folder first, then the
// include roots (ui/ before core/ for ui and app, as their targets list them).

#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QSet>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope::testdocs {

struct IncludeViolation {
    QString file;    // relative to the source root
    int line = 0;    // 1-based
    QString include; // as written, "time/duration.h" or <QtWidgets/QWidget>
    QString reason;  // the rule it breaks

    [[nodiscard]] QString toString() const;
};

class IncludeRules
{
public:
    // knownFiles: every .h and .cpp under core/, ui/, app/ and tests/, relative to the source root.
    explicit IncludeRules(QSet<QString> knownFiles);

    // The layers of core's folders: a folder includes only folders of a lower layer.
    [[nodiscard]] static QMap<QString, int> coreLayers();
    // The tiers of ui's wings: a wing includes only wings of a lower tier.
    [[nodiscard]] static QMap<QString, int> uiTiers();
    // Core headers included against the layers, each by the one file that may ("core/profile/delayspec.cpp
    // -> core/sim/simrandom.h"): named one by one so that no other such include slips in.
    [[nodiscard]] static QStringList coreExceptions();

    // The violations of one file's text; file is where it lives (it need not be in knownFiles).
    [[nodiscard]] QList<IncludeViolation> check(const QString &file, const QString &text) const;

    // The files a file's quoted includes reach (resolved as the compiler does; names that reach no
    // file and the file's own moc are left out).
    [[nodiscard]] QStringList includedFiles(const QString &file, const QString &text) const;

    // Every .h and .cpp under the folders checked (core/, ui/, app/, tests/core/), relative.
    [[nodiscard]] static QStringList sourceFiles(const QString &sourceDir);
    // Every file the includes may name: sourceFiles plus the rest of tests/.
    [[nodiscard]] static QSet<QString> knownFiles(const QString &sourceDir);

private:
    struct Resolution {
        QString target;     // the file the compiler would take, empty when none
        QStringList others; // other files the same name reaches from another root
    };
    [[nodiscard]] Resolution resolve(const QString &file, const QString &name) const;
    void checkQuoted(const QString &file, int line, const QString &name, bool uiGuarded,
                     QList<IncludeViolation> &out) const;
    void checkAngled(const QString &file, int line, const QString &name, bool uiGuarded,
                     QList<IncludeViolation> &out) const;

    QSet<QString> m_known;
};

} // namespace mbscope::testdocs
