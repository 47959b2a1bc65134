// The layering docs/architecture.md describes ("Layers") is the one the code keeps: every #include
// in core/, ui/, app/ and tests/core/ is checked against IncludeRules, the doc's tables are
// compared with the rules' own, and made-up violating includes prove the checker catches each rule.
#include "classcycles.h"
#include "includerules.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtTest/QtTest>

#include <utility>

using namespace mbscope::testdocs;

namespace {

const QString kSourceDir = QStringLiteral(MBSCOPE_SOURCE_DIR);

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

// The "## Layers" section of docs/architecture.md, up to the next "## " heading.
QString layersSection()
{
    const QString doc = readText(kSourceDir + QStringLiteral("/docs/architecture.md"));
    const qsizetype start = doc.indexOf(QLatin1String("\n## Layers\n"));
    if (start < 0)
        return {};
    const qsizetype end = doc.indexOf(QLatin1String("\n## "), start + 1);
    return doc.mid(start, end < 0 ? -1 : end - start);
}

// Table rows "| `core/protocol` | 0 | ..." of one part, as folder -> number.
QMap<QString, int> tableOf(const QString &section, const QString &part)
{
    const QRegularExpression row(QStringLiteral(R"(^\|\s*`%1/(\w+)`\s*\|\s*(\d+)\s*\|)").arg(part),
                                 QRegularExpression::MultilineOption);
    QMap<QString, int> table;
    for (auto it = row.globalMatch(section); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        table.insert(m.captured(1), m.captured(2).toInt());
    }
    return table;
}

// The folders holding sources directly under core/ or ui/.
QStringList foldersOf(const QString &part)
{
    QStringList folders;
    const QDir dir(kSourceDir + QLatin1Char('/') + part);
    for (const QString &name : dir.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        if (!QDir(dir.filePath(name)).entryList({QStringLiteral("*.h"), QStringLiteral("*.cpp")}, QDir::Files)
                 .isEmpty())
            folders.append(name);
    }
    return folders;
}

// "core/protocol=0" per folder, so that a difference reads in the failure message.
QStringList entries(const QMap<QString, int> &table)
{
    QStringList out;
    for (auto it = table.cbegin(); it != table.cend(); ++it)
        out.append(it.key() + QLatin1Char('=') + QString::number(it.value()));
    return out;
}

QString listed(const QList<IncludeViolation> &violations)
{
    QStringList lines;
    for (const IncludeViolation &v : violations)
        lines.append(v.toString());
    return lines.join(QLatin1Char('\n'));
}

} // namespace

class TestLayers : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void treeKeepsTheLayers();
    void noClassesDependOnEachOther();
    void cyclesFound_data();
    void cyclesFound();
    void docStatesTheSameRules();
    void everyFolderHasALayer_data();
    void everyFolderHasALayer();
    void checkerCatches_data();
    void checkerCatches();
    void checkerAllows_data();
    void checkerAllows();

private:
    QSet<QString> m_known;
    QStringList m_sources;
};

void TestLayers::initTestCase()
{
    m_known = IncludeRules::knownFiles(kSourceDir);
    m_sources = IncludeRules::sourceFiles(kSourceDir);
    // A scan that finds nothing would pass everything.
    QVERIFY2(m_sources.contains(QStringLiteral("core/protocol/dissector.cpp")), qPrintable(kSourceDir));
    QVERIFY(m_sources.contains(QStringLiteral("ui/shell/mainwindow.cpp")));
    QVERIFY(m_sources.contains(QStringLiteral("app/main.cpp")));
    QVERIFY(m_sources.size() > 500);
}

void TestLayers::treeKeepsTheLayers()
{
    const IncludeRules rules(m_known);
    static const QRegularExpression include(QStringLiteral(R"(^\s*#\s*include\s*["<])"),
                                            QRegularExpression::MultilineOption);
    QList<IncludeViolation> violations;
    qsizetype includes = 0;
    for (const QString &file : std::as_const(m_sources)) {
        const QString text = readText(kSourceDir + QLatin1Char('/') + file);
        for (auto it = include.globalMatch(text); it.hasNext(); it.next())
            ++includes;
        violations.append(rules.check(file, text));
    }
    QVERIFY2(includes > 3000, qPrintable(QString::number(includes)));
    QVERIFY2(violations.isEmpty(),
             qPrintable(QStringLiteral("%1 includes break the layering (docs/architecture.md, Layers):\n%2")
                            .arg(violations.size())
                            .arg(listed(violations))));
}

// No two classes of core/, ui/ or app/ depend on each other (docs/architecture.md, Layers).
void TestLayers::noClassesDependOnEachOther()
{
    const IncludeRules rules(m_known);
    QMap<QString, QStringList> includes;
    for (const QString &file : std::as_const(m_sources)) {
        if (!file.startsWith(QLatin1String("tests/")))
            includes.insert(file, rules.includedFiles(file, readText(kSourceDir + QLatin1Char('/') + file)));
    }
    QVERIFY(includes.size() > 500);
    QStringList groups;
    for (const QStringList &cycle : classCycles(includes))
        groups.append(cycle.join(QLatin1String(" <-> ")));
    QVERIFY2(groups.isEmpty(), qPrintable(QStringLiteral("classes that depend on each other (move what one needs of "
                                                         "the other into a file of its own):\n")
                                          + groups.join(QLatin1Char('\n'))));
}

void TestLayers::cyclesFound_data()
{
    QTest::addColumn<QStringList>("edges"); // "from.cpp>to.h"
    QTest::addColumn<QStringList>("cycles");
    QTest::newRow("a factory in the base class")
        << QStringList{QStringLiteral("t/link.cpp>t/link.h"), QStringLiteral("t/link.cpp>t/tcplink.h"),
                       QStringLiteral("t/tcplink.h>t/link.h"), QStringLiteral("t/tcplink.cpp>t/tcplink.h")}
        << QStringList{QStringLiteral("t/link t/tcplink")};
    QTest::newRow("the factory in a file of its own")
        << QStringList{QStringLiteral("t/link.cpp>t/link.h"), QStringLiteral("t/linkfactory.cpp>t/link.h"),
                       QStringLiteral("t/linkfactory.cpp>t/tcplink.h"), QStringLiteral("t/tcplink.h>t/link.h")}
        << QStringList{};
    QTest::newRow("three around")
        << QStringList{QStringLiteral("a.cpp>b.h"), QStringLiteral("b.cpp>c.h"), QStringLiteral("c.cpp>a.h"),
                       QStringLiteral("d.cpp>a.h")}
        << QStringList{QStringLiteral("a b c")};
    QTest::newRow("two apart") << QStringList{QStringLiteral("a.cpp>b.h"), QStringLiteral("b.cpp>a.h"),
                                              QStringLiteral("x.h>y.h"), QStringLiteral("y.cpp>x.h")}
                               << QStringList{QStringLiteral("a b"), QStringLiteral("x y")};
}

void TestLayers::cyclesFound()
{
    QFETCH(QStringList, edges);
    QFETCH(QStringList, cycles);
    QMap<QString, QStringList> includes;
    for (const QString &edge : std::as_const(edges))
        includes[edge.section(QLatin1Char('>'), 0, 0)].append(edge.section(QLatin1Char('>'), 1));
    QStringList found;
    for (const QStringList &cycle : classCycles(includes))
        found.append(cycle.join(QLatin1Char(' ')));
    QCOMPARE(found, cycles);
}

void TestLayers::docStatesTheSameRules()
{
    const QString section = layersSection();
    QVERIFY2(!section.isEmpty(), "docs/architecture.md has no \"## Layers\" section");
    QCOMPARE(entries(tableOf(section, QStringLiteral("core"))), entries(IncludeRules::coreLayers()));
    QCOMPARE(entries(tableOf(section, QStringLiteral("ui"))), entries(IncludeRules::uiTiers()));

    // The exceptions, written "`core/profile/delayspec.cpp` -> `core/sim/simrandom.h`".
    static const QRegularExpression exception(QStringLiteral(R"(`(core/[^`]+)` -> `(core/[^`]+)`)"));
    QStringList stated;
    for (auto it = exception.globalMatch(section); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        stated.append(m.captured(1) + QLatin1String(" -> ") + m.captured(2));
    }
    stated.sort();
    QStringList exceptions = IncludeRules::coreExceptions();
    exceptions.sort();
    QCOMPARE(stated, exceptions);
    for (const QString &pair : std::as_const(exceptions)) {
        for (const QString &path : pair.split(QLatin1String(" -> ")))
            QVERIFY2(m_known.contains(path), qPrintable(path));
    }
}

void TestLayers::everyFolderHasALayer_data()
{
    QTest::addColumn<QString>("part");
    QTest::newRow("core") << QStringLiteral("core");
    QTest::newRow("ui") << QStringLiteral("ui");
}

void TestLayers::everyFolderHasALayer()
{
    QFETCH(QString, part);
    const QMap<QString, int> table =
        part == QLatin1String("core") ? IncludeRules::coreLayers() : IncludeRules::uiTiers();
    QStringList folders = foldersOf(part);
    QStringList named = table.keys();
    folders.sort();
    named.sort();
    QCOMPARE(folders, named);
}

void TestLayers::checkerCatches_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("reason");
    QTest::addColumn<QStringList>("madeUp"); // files that exist for this row only

    const QString head = QStringLiteral("// made up\n#include <QtCore/QString>\n");
    const auto row = [&](const char *name, const char *file, const char *include, const char *reason,
                         const QStringList &madeUp = {}) {
        QTest::newRow(name) << QString::fromLatin1(file) << head + QString::fromLatin1(include) + QLatin1Char('\n')
                            << 3 << QString::fromLatin1(reason) << madeUp;
    };
    row("core/protocol includes core/time", "core/protocol/made.cpp", "#include \"time/duration.h\"",
        "core/protocol (layer 0) includes only lower layers, and core/time is layer 0");
    row("core/transport includes core/engine", "core/transport/made.cpp", "#include \"engine/transactionengine.h\"",
        "core/transport (layer 1) includes only lower layers");
    row("core/transport includes core/exchange", "core/transport/made.cpp", "#include \"exchange/transaction.h\"",
        "core/transport (layer 1) includes only lower layers");
    row("core/transport includes core/session", "core/transport/made.cpp", "#include \"session/sessiondocument.h\"",
        "core/transport (layer 1) includes only lower layers");
    row("core/exchange includes core/engine", "core/exchange/made.cpp", "#include \"engine/poller.h\"",
        "core/exchange (layer 2) includes only lower layers");
    row("core/engine includes core/capture", "core/engine/made.cpp", "#include \"capture/exchangepairer.h\"",
        "core/engine (layer 4) includes only lower layers, and core/capture is layer 4");
    row("core/profile includes another sim header", "core/profile/delayspec.cpp", "#include \"sim/simulator.h\"",
        "core/profile (layer 4) includes only lower layers, and core/sim is layer 5");
    row("core includes ui", "core/engine/made.cpp", "#include \"common/tablecsv.h\"",
        "core includes nothing from ui/");
    row("core includes app", "core/session/made.cpp", "#include \"../../app/common/cli.h\"", "core includes nothing from app/");
    row("core includes QtWidgets", "core/sim/made.cpp", "#include <QtWidgets/QWidget>",
        "core uses QtCore, QtNetwork, QtSerialPort, QtSerialBus and QtQml only, not QtWidgets");
    row("core includes QtGui", "core/protocol/made.h", "#include <QtGui/QColor>",
        "core uses QtCore, QtNetwork, QtSerialPort, QtSerialBus and QtQml only, not QtGui");
    row("core includes qcustomplot", "core/engine/made.cpp", "#include <qcustomplot.h>", "not QCustomPlot");
    row("core/engine includes QtNetwork", "core/engine/made.cpp", "#include <QtNetwork/QTcpSocket>",
        "QtNetwork is used in core only by core/transport, core/sim, core/capture, not core/engine");
    row("core/capture includes QtSerialBus", "core/capture/made.cpp", "#include <QtSerialBus/QModbusPdu>",
        "QtSerialBus is used in core only by core/sim, not core/capture");
    row("Qt header without its module", "core/protocol/made.cpp", "#include <QWidget>",
        "Qt headers are named with their module");
    row("core folder with no layer", "core/newthing/made.cpp", "#include \"protocol/hextext.h\"",
        "core/newthing has no layer");
    row("name nothing", "core/engine/made.cpp", "#include \"engine/nosuchfile.h\"",
        "names no file under core/, ui/ or app/");
    row("the moc of a header that is not there", "core/sim/made.cpp", "#include \"moc_nosuchheader.cpp\"",
        "includes the meta-object code of core/sim/nosuchheader.h, which does not exist");
    row("name reaching two roots", "ui/sim/made.cpp", "#include \"sim/simunit.h\"",
        "reaches both ui/sim/simunit.h and core/sim/simunit.h", {QStringLiteral("ui/sim/simunit.h")});
    row("ui/common includes a wing", "ui/common/made.cpp", "#include \"decode/hexview.h\"",
        "ui/common (tier 0) includes only wings of a lower tier, and ui/decode is tier 1");
    row("ui/common includes core/engine", "ui/common/made.cpp", "#include \"engine/transactionengine.h\"",
        "ui/common includes of core only the values");
    row("ui/decode includes ui/traffic", "ui/decode/made.cpp", "#include \"traffic/trafficmodel.h\"",
        "ui/decode (tier 1) includes only wings of a lower tier, and ui/traffic is tier 1");
    row("ui/analysis includes ui/session", "ui/analysis/made.cpp", "#include \"session/planpanel.h\"",
        "ui/analysis (tier 2) includes only wings of a lower tier, and ui/session is tier 2");
    row("ui/link includes ui/shell", "ui/link/made.cpp", "#include \"shell/mainwindow.h\"",
        "ui/link (tier 1) includes only wings of a lower tier, and ui/shell is tier 3");
    row("ui wing with no tier", "ui/newwing/made.cpp", "#include \"common/tablecsv.h\"", "ui/newwing has no tier");
    row("ui includes app", "ui/shell/made.cpp", "#include \"../../app/common/cli.h\"", "ui includes nothing from app/");
    row("app includes ui unguarded", "app/made.cpp", "#include \"common/tablecsv.h\"",
        "app includes ui/ only in gui.cpp or under #ifdef MBSCOPE_HAVE_UI");
    row("app includes QtWidgets unguarded", "app/made.cpp", "#include <QtWidgets/QApplication>",
        "app uses QtWidgets only in gui.cpp or under #ifdef MBSCOPE_HAVE_UI");
    row("tests of core include ui", "tests/core/engine/tst_made.cpp", "#include \"decode/hexview.h\"",
        "tests of core include core only");
    row("tests of core include QtGui", "tests/core/engine/tst_made.cpp", "#include <QtGui/QImage>",
        "tests of core use core's Qt modules and QtTest only, not QtGui");

    // The window's guard: the branch without it, and an #ifndef, are not guarded.
    QTest::newRow("app: #else of the guard")
        << QStringLiteral("app/made.cpp")
        << QStringLiteral("#ifdef MBSCOPE_HAVE_UI\n#include \"common/tablecsv.h\"\n#else\n#include "
                          "\"common/plotsaver.h\"\n#endif\n")
        << 4 << QStringLiteral("app includes ui/ only in gui.cpp") << QStringList();
    QTest::newRow("app: #ifndef of the guard")
        << QStringLiteral("app/made.cpp")
        << QStringLiteral("#include \"common/cli.h\"\n#ifndef MBSCOPE_HAVE_UI\n#include <QtGui/QColor>\n#endif\n") << 3
        << QStringLiteral("app uses QtGui only in gui.cpp") << QStringList();
    QTest::newRow("app: after the guard closed")
        << QStringLiteral("app/made.cpp")
        << QStringLiteral("#if defined(MBSCOPE_HAVE_UI)\n#endif\n#include \"shell/mainwindow.h\"\n") << 3
        << QStringLiteral("app includes ui/ only in gui.cpp") << QStringList();
}

void TestLayers::checkerCatches()
{
    QFETCH(QString, file);
    QFETCH(QString, text);
    QFETCH(int, line);
    QFETCH(QString, reason);
    QFETCH(QStringList, madeUp);

    QSet<QString> known = m_known;
    for (const QString &path : std::as_const(madeUp))
        known.insert(path);
    const QList<IncludeViolation> violations = IncludeRules(known).check(file, text);
    QVERIFY2(violations.size() == 1, qPrintable(listed(violations)));
    QCOMPARE(violations.first().file, file);
    QCOMPARE(violations.first().line, line);
    QVERIFY2(violations.first().reason.contains(reason), qPrintable(violations.first().reason));
}

void TestLayers::checkerAllows_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("text");

    QTest::newRow("same folder, bare") << QStringLiteral("core/protocol/made.cpp")
                                       << QStringLiteral("#include \"dissector.h\"\n");
    QTest::newRow("same folder, spelled out") << QStringLiteral("core/sim/made.cpp")
                                              << QStringLiteral("#include \"sim/simunit.h\"\n");
    QTest::newRow("lower layer") << QStringLiteral("core/replay/made.cpp")
                                 << QStringLiteral("#include \"sim/simulator.h\"\n#include \"time/duration.h\"\n");
    QTest::newRow("the exception, by its file") << QStringLiteral("core/profile/delayspec.cpp")
                                                << QStringLiteral("#include \"sim/simrandom.h\"\n");
    QTest::newRow("its own header's moc") << QStringLiteral("core/sim/simmodbusserver.cpp")
                                          << QStringLiteral("#include \"moc_simmodbusserver.cpp\"\n");
    QTest::newRow("core/sim uses QtSerialBus") << QStringLiteral("core/sim/made.cpp")
                                               << QStringLiteral("#include <QtSerialBus/QModbusServer>\n");
    QTest::newRow("ui/session includes core/sim") << QStringLiteral("ui/session/made.cpp")
                                                  << QStringLiteral("#include \"sim/simulator.h\"\n");
    QTest::newRow("ui/shell includes every wing")
        << QStringLiteral("ui/shell/made.cpp")
        << QStringLiteral("#include \"analysis/analysisdock.h\"\n#include \"session/planpanel.h\"\n"
                          "#include \"common/tablecsv.h\"\n");
    QTest::newRow("app under the guard")
        << QStringLiteral("app/made.cpp")
        << QStringLiteral("#ifdef MBSCOPE_HAVE_UI\n#if 1\n#endif\n#include \"common/plotsaver.h\"\n"
                          "#include <QtWidgets/QApplication>\n#include <qcustomplot.h>\n#endif\n");
    QTest::newRow("app/gui.cpp") << QStringLiteral("app/gui.cpp")
                                 << QStringLiteral("#include \"shell/mainwindow.h\"\n#include <QtGui/QIcon>\n");
    QTest::newRow("the standard library") << QStringLiteral("core/protocol/made.cpp")
                                          << QStringLiteral("#include <vector>\n#include <sys/socket.h>\n");
    QTest::newRow("a test's moc file") << QStringLiteral("tests/core/protocol/tst_made.cpp")
                                       << QStringLiteral("#include \"tst_made.moc\"\n#include <QtTest/QtTest>\n");
}

void TestLayers::checkerAllows()
{
    QFETCH(QString, file);
    QFETCH(QString, text);
    const QList<IncludeViolation> violations = IncludeRules(m_known).check(file, text);
    QVERIFY2(violations.isEmpty(), qPrintable(listed(violations)));
}

QTEST_GUILESS_MAIN(TestLayers)
#include "tst_layers.moc"
