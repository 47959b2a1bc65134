// The Simulator dock's Script tab with a real client on loopback: a profile file with a script
// started from the panel answers as its script says; the tab lists the script and shows its log
// (log(...) lines, the load); Reload scripts picks up an edited file; a broken edit is logged
// with file, line and column and the unit answers as its profile says; a profile whose script
// does not compile is refused with the located error. A screenshot of the tab goes to the output.
// The tab's editor: the script highlighted in the theme's colours (light and dark, each rendered
// to a PNG), Ctrl+S saves and the simulator answers as the saved script says, a broken save marks
// the error's line, an edit made by another program on disk is followed and loaded.
#include "guitestsupport.h"
#include "windowfit.h"

#include "common/theme.h"
#include "sim/scripteditor.h"
#include "sim/scripthighlighter.h"
#include "sim/simscriptpanel.h"
#include "sim/simulatorpanel.h"

#include "protocol/adubuilder.h"
#include "sim/simulatorhost.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QtTest>
#include <QtGui/QTextBlock>
#include <QtGui/QTextLayout>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTabWidget>

using namespace mbscope;

namespace {

void writeFile(const QString &path, const QByteArray &text)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        qFatal("cannot write %s", qPrintable(path));
    file.write(text);
}

// Reads holding register 0 of unit 1: its value, or -1 when the answer is no normal one.
int readRegister0(quint16 port)
{
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), port);
    if (!socket.waitForConnected(5000))
        return -2;
    socket.write(AduBuilder::mbap(QByteArray::fromHex("0300000001"), 1, 1));
    QByteArray answer;
    QDeadlineTimer deadline(5000);
    while (answer.size() < 9 && !deadline.hasExpired() && socket.waitForReadyRead(500))
        answer += socket.readAll();
    if (answer.size() < 11)
        return -1;
    return quint8(answer.at(9)) << 8 | quint8(answer.at(10));
}

const QByteArray kProfile = R"({"name": "scripted", "units": [{"id": 1, "script": "s.js",
    "tables": {"holding": [{"address": 0, "values": [5]}]}}]})";

} // namespace

class TestSimScriptPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void loadReloadAndLog();
    void brokenScriptRefusedAtStart();
    void editorSavesMarksAndFollows();
};

void TestSimScriptPanel::loadReloadAndLog()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString script = dir.filePath(QStringLiteral("s.js"));
    writeFile(script, "log('first version');\nfunction onRequest(r) { log('asked for', r.address); return [111]; }\n");
    const QString profile = dir.filePath(QStringLiteral("p.json"));
    writeFile(profile, kProfile);

    SimulatorPanel panel;
    panel.resize(900, 600);
    panel.show();
    SimulatorHost *host = panel.startSimulator(profile, QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    QCOMPARE(host->scripts(), QStringList{QStringLiteral("unit 1: s.js")});
    SimScriptPanel *scripts = panel.scriptPanel();
    QTabWidget *tabs = panel.tabs();
    const int tab = tabs->indexOf(scripts);
    QVERIFY(tab >= 0);
    QCOMPARE(tabs->tabText(tab), QStringLiteral("Script"));
    tabs->setCurrentIndex(tab);
    QCOMPARE(scripts->findChild<QLabel *>(QStringLiteral("simScripts"))->text(), QStringLiteral("Scripts: unit 1: s.js"));
    QVERIFY(scripts->reloadButton()->isEnabled());

    const quint16 port = host->boundUrls().first().port;
    QCOMPARE(readRegister0(port), 111);
    QTRY_VERIFY_WITH_TIMEOUT(scripts->logText().contains(QLatin1String("unit 1: s.js  asked for 0")), 5000);
    QVERIFY2(scripts->logText().contains(QLatin1String("unit 1: s.js  first version")), qPrintable(scripts->logText()));
    QVERIFY2(scripts->logText().contains(QLatin1String("unit 1: s.js  loaded")), qPrintable(scripts->logText()));

    // Edited and reloaded: the new answer.
    writeFile(script, "function onRequest(r) { return [222]; }\n");
    QTest::mouseClick(scripts->reloadButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(scripts->logText().contains(QLatin1String("unit 1: s.js  reloaded")), 5000);
    QCOMPARE(readRegister0(port), 222);

    // A broken edit: the error located in the log; the profile answers meanwhile.
    writeFile(script, "function onRequest(r) {\n  return [333;\n}\n");
    QTest::mouseClick(scripts->reloadButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(scripts->logText().contains(QLatin1String("unit 1: s.js  error: s.js:2:")), 5000);
    QVERIFY2(scripts->logText().contains(QLatin1String("SyntaxError")), qPrintable(scripts->logText()));
    QVERIFY2(scripts->logText().contains(QLatin1String("(the profile answers until the next reload)")), qPrintable(scripts->logText()));
    QCOMPARE(readRegister0(port), 5);

    const QString shot = QDir(QString::fromLocal8Bit(qgetenv("MBSCOPE_TEST_OUTPUT"))).filePath(QStringLiteral("sim-script-tab.png"));
    if (qEnvironmentVariableIsSet("MBSCOPE_TEST_OUTPUT"))
        panel.grab().save(shot);
    panel.stopSimulator(host);
    QCOMPARE(scripts->findChild<QLabel *>(QStringLiteral("simScripts"))->text(), QStringLiteral("No simulator selected."));
}

void TestSimScriptPanel::brokenScriptRefusedAtStart()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeFile(dir.filePath(QStringLiteral("s.js")), "var x = ;\n");
    const QString profile = dir.filePath(QStringLiteral("p.json"));
    writeFile(profile, kProfile);
    SimulatorPanel panel;
    QVERIFY(!panel.startSimulator(profile, QStringLiteral("tcp://127.0.0.1:0")));
    QVERIFY2(panel.message().contains(QStringLiteral("%1: units[0].script: s.js:1:").arg(profile)), qPrintable(panel.message()));
    QVERIFY2(panel.message().contains(QLatin1String("SyntaxError")), qPrintable(panel.message()));
}

namespace {

// The colour the highlighter gave the text at column of line (0-based), invalid when none.
QColor colourAt(QPlainTextEdit *edit, int line, int column)
{
    const QTextBlock block = edit->document()->findBlockByNumber(line);
    for (const QTextLayout::FormatRange &r : block.layout()->formats()) {
        if (column >= r.start && column < r.start + r.length)
            return r.format.foreground().color();
    }
    return {};
}

void typeOver(QPlainTextEdit *edit, const QString &text)
{
    edit->setFocus();
    edit->selectAll();
    QTextCursor cursor = edit->textCursor();
    cursor.insertText(text);
    edit->setTextCursor(cursor);
}

} // namespace

void TestSimScriptPanel::editorSavesMarksAndFollows()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString script = dir.filePath(QStringLiteral("s.js"));
    writeFile(script, "// answers 111\nfunction onRequest(r) { log(\"asked\", 0x10); return [111]; }\n");
    const QString profile = dir.filePath(QStringLiteral("p.json"));
    writeFile(profile, kProfile);

    Theme::apply(Theme::Choice::Light);
    SimulatorPanel panel;
    panel.resize(1100, 600);
    panel.show();
    panel.activateWindow(); // Ctrl+S reaches the active window only
    QVERIFY(QTest::qWaitForWindowActive(&panel));
    SimulatorHost *host = panel.startSimulator(profile, QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    const quint16 port = host->boundUrls().first().port;
    SimScriptPanel *scripts = panel.scriptPanel();
    panel.tabs()->setCurrentWidget(scripts);
    ScriptEditor *editor = scripts->editor();
    QPlainTextEdit *edit = editor->editor();
    QCOMPARE(editor->scriptChoice()->currentText(), QStringLiteral("unit 1: s.js"));
    QCOMPARE(editor->path(), script);
    QVERIFY(edit->toPlainText().startsWith(QStringLiteral("// answers 111\nfunction onRequest")));
    QVERIFY(!edit->isReadOnly());
    // The editor beside the log.
    QVERIFY(edit->isVisible());
    QVERIFY(scripts->findChild<QPlainTextEdit *>(QStringLiteral("simScriptLog"))->isVisible());

    // Highlighted in the light theme's colours, each readable on the editor's background.
    using Kind = ScriptHighlighter::Kind;
    const auto checkContrast = [&](const char *theme) {
        const QColor base = edit->palette().color(QPalette::Base);
        for (Kind kind : {Kind::Keyword, Kind::String, Kind::Number, Kind::Comment}) {
            const double ratio = windowfit::contrast(ScriptHighlighter::format(kind).foreground().color(), base);
            QVERIFY2(ratio >= 4.5, qPrintable(QStringLiteral("%1: kind %2 at %3:1").arg(QLatin1String(theme)).arg(int(kind)).arg(ratio)));
        }
    };
    QCOMPARE(colourAt(edit, 0, 3), ScriptHighlighter::format(Kind::Comment).foreground().color());
    QCOMPARE(colourAt(edit, 1, 0), ScriptHighlighter::format(Kind::Keyword).foreground().color());
    QCOMPARE(colourAt(edit, 1, 29), ScriptHighlighter::format(Kind::String).foreground().color()); // "asked"
    QCOMPARE(colourAt(edit, 1, 38), ScriptHighlighter::format(Kind::Number).foreground().color()); // 0x10
    QVERIFY(!colourAt(edit, 1, 10).isValid());                                                    // onRequest
    checkContrast("light");
    const QColor lightKeyword = colourAt(edit, 1, 0);
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("sim-script-editor-light.png")));

    // Saved with Ctrl+S: the simulator answers as the saved script says.
    QCOMPARE(readRegister0(port), 111);
    typeOver(edit, QStringLiteral("function onRequest(r) { return [444]; }\n"));
    QVERIFY(editor->saveButton()->isEnabled());
    QTest::keyClick(edit, Qt::Key_S, Qt::ControlModifier);
    QCOMPARE(QString::fromUtf8([&] { QFile f(script); f.open(QIODevice::ReadOnly); return f.readAll(); }()),
             QStringLiteral("function onRequest(r) { return [444]; }\n"));
    QVERIFY(!editor->saveButton()->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(scripts->logText().contains(QLatin1String("unit 1: s.js  reloaded")), 5000);
    QCOMPARE(readRegister0(port), 444);

    // A broken save: the error's line marked, the cursor on it, the status line saying it.
    typeOver(edit, QStringLiteral("function onRequest(r) {\n  return [333;\n}\n"));
    QVERIFY(editor->save());
    QTRY_COMPARE_WITH_TIMEOUT(editor->errorLine(), 2, 5000);
    QCOMPARE(edit->extraSelections().size(), 1);
    QCOMPARE(edit->extraSelections().first().cursor.blockNumber(), 1);
    QCOMPARE(edit->textCursor().blockNumber(), 1);
    QVERIFY2(editor->statusText().startsWith(QStringLiteral("Line 2: ")) && editor->statusText().contains(QStringLiteral("SyntaxError")),
             qPrintable(editor->statusText()));
    QCOMPARE(readRegister0(port), 5); // the profile answers meanwhile

    // In the dark theme: other colours, still readable, the mark still there.
    Theme::apply(Theme::Choice::Dark);
    QCoreApplication::processEvents();
    // Rehighlighted: "function" and 333 of the broken script in the dark theme's colours.
    QCOMPARE(colourAt(edit, 0, 0), ScriptHighlighter::format(Kind::Keyword).foreground().color());
    QCOMPARE(colourAt(edit, 1, 10), ScriptHighlighter::format(Kind::Number).foreground().color());
    QVERIFY(colourAt(edit, 0, 0) != lightKeyword);
    checkContrast("dark");
    QCOMPARE(edit->extraSelections().size(), 1);
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("sim-script-editor-dark.png")));
    Theme::apply(Theme::Choice::Light);

    // Fixed by another program: the editor follows the file, the simulator loads it, the mark goes.
    writeFile(script, "function onRequest(r) { return [555]; }\n");
    QTRY_COMPARE_WITH_TIMEOUT(edit->toPlainText(), QStringLiteral("function onRequest(r) { return [555]; }\n"), 5000);
    QTRY_COMPARE_WITH_TIMEOUT(editor->errorLine(), 0, 5000);
    QVERIFY(edit->extraSelections().isEmpty());
    QCOMPARE(readRegister0(port), 555);

    // Edits of its own are kept when the file changes under them, and said.
    typeOver(edit, QStringLiteral("// mine\n"));
    writeFile(script, "function onRequest(r) { return [666]; }\n");
    QTRY_VERIFY_WITH_TIMEOUT(editor->statusText().contains(QStringLiteral("changed on disk")), 5000);
    QCOMPARE(edit->toPlainText(), QStringLiteral("// mine\n"));
    panel.stopSimulator(host);
    QVERIFY(edit->toPlainText().isEmpty());
}

QTEST_MAIN(TestSimScriptPanel)
#include "tst_simscriptpanel.moc"
