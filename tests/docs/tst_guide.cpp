// The user guide stays true: scripts/screenshots.sh renders every image docs/guide/*.md shows
// (none blank), and every image and relative link in the guide and the README resolves, down to
// the heading an #anchor names.
#include "markdownlinks.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QProcess>
#include <QtCore/QSet>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtGui/QImage>
#include <QtTest/QtTest>

using namespace mbscope::testdocs;

namespace {

const QString kSourceDir = QStringLiteral(MBSCOPE_SOURCE_DIR);

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

// The Markdown pages checked: the guide's pages and the README.
QStringList markdownFiles()
{
    QStringList files;
    const QDir guide(kSourceDir + QStringLiteral("/docs/guide"));
    for (const QString &name : guide.entryList({QStringLiteral("*.md")}, QDir::Files, QDir::Name))
        files.append(guide.filePath(name));
    files.append(kSourceDir + QStringLiteral("/README.md"));
    return files;
}

bool isExternal(const QString &target)
{
    return target.contains(QLatin1String("://")) || target.startsWith(QLatin1String("mailto:"));
}

// How many colours the image has, counting up to limit.
int distinctColours(const QImage &image, int limit)
{
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            colours.insert(image.pixel(x, y));
            if (colours.size() >= limit)
                return limit;
        }
    }
    return int(colours.size());
}

} // namespace

class TestGuide : public QObject
{
    Q_OBJECT

private slots:
    void guideExists();
    void links_data();
    void links();
    void screenshotsGenerated();
    void screenshots_data();
    void screenshots();

private:
    QTemporaryDir m_shots;
    bool m_generated = false;
};

void TestGuide::guideExists()
{
    const QStringList files = markdownFiles();
    QVERIFY2(files.size() >= 2, "docs/guide/ has no Markdown page");
    QVERIFY(QFileInfo::exists(kSourceDir + QStringLiteral("/docs/guide/README.md")));
}

void TestGuide::links_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("target");
    int rows = 0;
    for (const QString &file : markdownFiles()) {
        const QString relative = QDir(kSourceDir).relativeFilePath(file);
        for (const MarkdownLink &link : markdownLinks(readText(file))) {
            if (isExternal(link.target))
                continue;
            QTest::addRow("%s:%d %s", qPrintable(relative), link.line, qPrintable(link.target)) << file << link.target;
            ++rows;
        }
    }
    // An empty table would abort QtTest; no link at all is itself the failure (the guide's
    // contents page links its pages).
    if (rows == 0)
        QTest::newRow("no relative link found") << QString() << QString();
}

void TestGuide::links()
{
    QFETCH(QString, file);
    QFETCH(QString, target);
    QVERIFY2(!file.isEmpty(), "docs/guide/*.md and README.md link to nothing: the guide's pages are not linked");
    const qsizetype hash = target.indexOf(QLatin1Char('#'));
    const QString path = hash < 0 ? target : target.left(hash);
    const QString anchor = hash < 0 ? QString() : target.mid(hash + 1);
    const QString resolved = path.isEmpty() ? file : QFileInfo(file).dir().filePath(path);
    QVERIFY2(QFileInfo::exists(resolved), qPrintable(QStringLiteral("%1 does not exist").arg(QDir::cleanPath(resolved))));
    if (!anchor.isEmpty()) {
        QVERIFY2(resolved.endsWith(QLatin1String(".md")), "an #anchor into a file that is not Markdown");
        const QSet<QString> anchors = markdownAnchors(readText(resolved));
        QVERIFY2(anchors.contains(anchor), qPrintable(QStringLiteral("no heading of %1 has the anchor #%2")
                                                          .arg(QFileInfo(resolved).fileName(), anchor)));
    }
}

void TestGuide::screenshotsGenerated()
{
    QVERIFY(m_shots.isValid());
    const QString bash = QStandardPaths::findExecutable(QStringLiteral("bash"));
    QVERIFY2(!bash.isEmpty(), "bash is needed to run scripts/screenshots.sh");
    QProcess script;
    script.setProcessChannelMode(QProcess::MergedChannels);
    script.start(bash, {kSourceDir + QStringLiteral("/scripts/screenshots.sh"), QStringLiteral(MBSCOPE_BUILD_DIR), m_shots.path()});
    QVERIFY2(script.waitForFinished(240000), "scripts/screenshots.sh did not finish in 4 minutes");
    const QByteArray output = script.readAll();
    QVERIFY2(script.exitStatus() == QProcess::NormalExit && script.exitCode() == 0,
             qPrintable(QStringLiteral("scripts/screenshots.sh failed:\n") + QString::fromLocal8Bit(output)));
    m_generated = true;
}

// Every image of the guide's pages under images/: the script must make it.
void TestGuide::screenshots_data()
{
    QTest::addColumn<QString>("name");
    QSet<QString> names;
    for (const QString &file : markdownFiles()) {
        if (!file.contains(QLatin1String("/docs/guide/")))
            continue;
        for (const MarkdownLink &link : markdownLinks(readText(file))) {
            if (link.image && link.target.startsWith(QLatin1String("images/")))
                names.insert(link.target.mid(7));
        }
    }
    QVERIFY2(!names.isEmpty(), "the guide shows no images/ picture");
    QStringList sorted = names.values();
    sorted.sort();
    for (const QString &name : sorted)
        QTest::newRow(qPrintable(name)) << name;
}

void TestGuide::screenshots()
{
    QFETCH(QString, name);
    QVERIFY2(m_generated, "scripts/screenshots.sh did not run");
    const QString path = m_shots.filePath(name);
    QVERIFY2(QFileInfo::exists(path), qPrintable(QStringLiteral("scripts/screenshots.sh does not make %1").arg(name)));
    const QImage image(path);
    QVERIFY2(!image.isNull(), qPrintable(QStringLiteral("%1 is no readable PNG").arg(name)));
    QVERIFY2(image.width() >= 400 && image.height() >= 300,
             qPrintable(QStringLiteral("%1 is only %2x%3").arg(name).arg(image.width()).arg(image.height())));
    // A window or a plot has text, lines and fills: far more than a few colours.
    QVERIFY2(distinctColours(image, 16) >= 16, qPrintable(QStringLiteral("%1 is blank (fewer than 16 colours)").arg(name)));
}

QTEST_GUILESS_MAIN(TestGuide)
#include "tst_guide.moc"
