// Tools > Conformance (ConformanceDialog) offscreen against the embedded simulator's shipped
// conformance profile: the battery's rows fill the table as checks are decided, the progress bar
// follows, nothing fails, write checks are skipped unless Writable names addresses (and pass when
// it does), Stop ends a run early, bad fields are said, the verdict colours follow the level, the
// scorecard is saved as HTML, PDF, JSON and JUnit, the window's Tools menu opens the dialog on its
// target, a run's frames reach the window's traffic list, and against devices that deviate (the
// simulator with a fault, pymodbus) the window gives every check the verdict mbscope conform gives.

#include "conformance/conformancedialog.h"
#include "conformance/conformanceresultmodel.h"
#include "common/severitystyle.h"
#include "guitestsupport.h"
#include "link/connectionbar.h"
#include "shell/mainwindow.h"
#include "sim/embeddedsimulator.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"
#include "peerprocess.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>
#include <QtCore/QSet>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtCore/QTimer>
#include <QtCore/QXmlStreamReader>
#include <QtGui/QAction>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>

using namespace mbscope;

namespace {

// The verdicts of the model, by check id.
QMap<QString, QString> verdicts(const ConformanceResultModel *model)
{
    QMap<QString, QString> out;
    for (const CheckResult &r : model->results())
        out.insert(r.id, QLatin1String(checkVerdictName(r.verdict)));
    return out;
}

} // namespace

class TestConformanceDialog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void runFillsTheScorecard_data();
    void runFillsTheScorecard();
    void stopEndsTheRun();
    void badFieldsAreSaid_data();
    void badFieldsAreSaid();
    void verdictColours_data();
    void verdictColours();
    void toolsMenuOpensIt();
    void runReachesTheTrafficList();
    void windowAgreesWithTheCommandLine_data();
    void windowAgreesWithTheCommandLine();

private:
    void fill(ConformanceDialog &dialog, const QString &writable, const QString &only);

    EmbeddedSimulator m_sim;
    LinkUrl m_url;
    QTemporaryDir m_dir;
};

void TestConformanceDialog::initTestCase()
{
    guitest::isolateSettings();
    QVERIFY(m_dir.isValid());
    const EmbeddedSimulator::Started started = m_sim.start(QStringLiteral("conformance"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    m_url = started.url;
}

void TestConformanceDialog::fill(ConformanceDialog &dialog, const QString &writable, const QString &only)
{
    dialog.setTarget(m_url);
    dialog.findChild<QSpinBox *>(QStringLiteral("conformTimeout"))->setValue(300);
    dialog.findChild<QLineEdit *>(QStringLiteral("conformProfile"))->setText(QStringLiteral("conformance"));
    dialog.findChild<QLineEdit *>(QStringLiteral("conformWritable"))->setText(writable);
    dialog.findChild<QLineEdit *>(QStringLiteral("conformOnly"))->setText(only);
}

void TestConformanceDialog::runFillsTheScorecard_data()
{
    QTest::addColumn<QString>("writable");
    QTest::addColumn<QString>("only");
    QTest::addColumn<QString>("writeVerdict"); // write.06.echo's
    QTest::addColumn<QString>("screenshot");
    QTest::newRow("reads only") << "" << "" << "skipped" << "";
    QTest::newRow("writes where allowed") << "holding:10-13, coils:10-17" << "read.03,read.01,mbap,exception,write,ident,diag" << "passed"
                                          << "conformance.png";
}

void TestConformanceDialog::runFillsTheScorecard()
{
    QFETCH(QString, writable);
    QFETCH(QString, only);
    QFETCH(QString, writeVerdict);
    QFETCH(QString, screenshot);
    ConformanceDialog dialog;
    QAbstractItemModelTester tester(dialog.model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    fill(dialog, writable, only);
    dialog.show();
    auto *save = dialog.findChild<QPushButton *>(QStringLiteral("conformSave"));
    QVERIFY(!save->isEnabled());
    QSignalSpy finished(&dialog, &ConformanceDialog::finished);
    QSignalSpy decided(&dialog, &ConformanceDialog::checkDecided);
    QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("conformStart")), Qt::LeftButton);
    QVERIFY(dialog.isRunning());
    QVERIFY(!dialog.findChild<QPushButton *>(QStringLiteral("conformStart"))->isEnabled());
    QVERIFY(dialog.findChild<QPushButton *>(QStringLiteral("conformStop"))->isEnabled());
    QVERIFY(finished.wait(240000));
    QCOMPARE(finished.first().first().toBool(), true);
    QVERIFY(!dialog.isRunning());

    // A row per check decided, the bar at its end, nothing failed.
    const int rows = dialog.model()->rowCount();
    QVERIFY(rows > 10);
    QCOMPARE(decided.size(), rows);
    QCOMPARE(decided.last().at(1).toInt(), rows);
    auto *bar = dialog.findChild<QProgressBar *>(QStringLiteral("conformProgress"));
    QCOMPARE(bar->value(), rows);
    QCOMPARE(bar->maximum(), rows);
    const QMap<QString, QString> v = verdicts(dialog.model());
    QVERIFY2(!v.values().contains(QStringLiteral("failed")), qPrintable(QStringList(v.keys(QStringLiteral("failed"))).join(QLatin1Char(' '))));
    QCOMPARE(v.value(QStringLiteral("write.06.echo")), writeVerdict);
    QVERIFY(dialog.findChild<QLabel *>(QStringLiteral("conformStatus"))->text().contains(QStringLiteral("Every mandatory check passed")));
    // The table shows what the model holds: a pass is green, its request and answer as hex.
    int row = -1;
    for (int i = 0; i < rows && row < 0; ++i)
        row = dialog.model()->results().at(i).id == QLatin1String("read.03.quantity-zero") ? i : -1;
    QVERIFY(row >= 0);
    const QAbstractItemModel *m = dialog.model();
    QCOMPARE(m->index(row, ConformanceResultModel::VerdictColumn).data().toString(), QStringLiteral("PASS"));
    QVERIFY(m->index(row, ConformanceResultModel::VerdictColumn).data(Qt::BackgroundRole).value<QColor>().isValid());
    QVERIFY(m->index(row, ConformanceResultModel::ClauseColumn).data().toString().contains(QStringLiteral("V1.1b3")));
    QVERIFY(m->index(row, ConformanceResultModel::RequestColumn).data().toString().endsWith(QStringLiteral("00 00")));
    QVERIFY(m->index(row, ConformanceResultModel::AnswerColumn).data().toString().contains(QStringLiteral("83 03")));

    // Saved in the three formats, by suffix.
    QVERIFY(save->isEnabled());
    const QString tag = QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-'));
    QString error;
    const QString json = m_dir.filePath(tag + QStringLiteral(".json"));
    QVERIFY2(dialog.saveReport(json, &error), qPrintable(error));
    QFile jf(json);
    QVERIFY(jf.open(QIODevice::ReadOnly));
    const QJsonObject card = QJsonDocument::fromJson(jf.readAll()).object();
    QCOMPARE(card.value(QStringLiteral("checks")).toArray().size(), rows);
    QCOMPARE(card.value(QStringLiteral("passed")).toBool(), true);
    for (const QString &suffix : {QStringLiteral(".html"), QStringLiteral(".xml")}) {
        const QString path = m_dir.filePath(tag + suffix);
        QVERIFY2(dialog.saveReport(path, &error), qPrintable(error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QXmlStreamReader reader(&f);
        int items = 0;
        while (!reader.atEnd()) {
            reader.readNext();
            if (reader.isStartElement()
                && (reader.name() == QLatin1String("testcase")
                    || (reader.name() == QLatin1String("section") && reader.attributes().value(QStringLiteral("class")) == QLatin1String("check"))))
                ++items;
        }
        QVERIFY2(!reader.hasError(), qPrintable(reader.errorString()));
        QCOMPARE(items, rows);
    }
    // And as a PDF (the HTML page printed): pdftotext reads the summary and a check's clause back.
    const QString pdf = m_dir.filePath(tag + QStringLiteral(".pdf"));
    QVERIFY2(dialog.saveReport(pdf, &error), qPrintable(error));
    QFile pf(pdf);
    QVERIFY(pf.open(QIODevice::ReadOnly));
    QCOMPARE(pf.read(5), QByteArray("%PDF-"));
    if (const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext")); !pdftotext.isEmpty()) {
        QProcess text;
        text.start(pdftotext, {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
        QVERIFY(text.waitForFinished(60000));
        const QString words = QString::fromUtf8(text.readAllStandardOutput()).simplified();
        QVERIFY2(words.contains(QStringLiteral("every mandatory check passed")), qPrintable(words.left(400)));
        QVERIFY2(words.contains(QStringLiteral("read.03.quantity-zero")), qPrintable(words.left(400)));
        QVERIFY2(words.contains(QStringLiteral("clause Application Protocol V1.1b3, 6.3")), qPrintable(words.left(400)));
    }
    QVERIFY(!dialog.saveReport(m_dir.filePath(tag + QStringLiteral(".txt")), &error));
    QVERIFY2(error.contains(QStringLiteral(".html, .pdf, .json or .xml")), qPrintable(error));

    // scripts/screenshots.sh renders the guide's picture from here.
    if (const QString path = qEnvironmentVariable("MBSCOPE_CONFORMANCE_SCREENSHOT"); !path.isEmpty() && !screenshot.isEmpty()) {
        dialog.resize(1400, 760);
        QCoreApplication::sendPostedEvents();
        QVERIFY(dialog.grab().save(path, "PNG"));
    }
}

void TestConformanceDialog::stopEndsTheRun()
{
    ConformanceDialog dialog;
    fill(dialog, QString(), QString());
    dialog.show();
    QSignalSpy finished(&dialog, &ConformanceDialog::finished);
    connect(&dialog, &ConformanceDialog::checkDecided, &dialog, [&dialog](int done) {
        if (done == 3)
            QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("conformStop")), Qt::LeftButton);
    });
    // The battery runs in the job's thread: the window's own loop is never nested meanwhile (a
    // 2 ms timer on it sees loop level 1 throughout; the battery on it made that 2).
    int deepest = 0;
    QTimer probe;
    connect(&probe, &QTimer::timeout, this, [&deepest] { deepest = qMax(deepest, QThread::currentThread()->loopLevel()); });
    probe.start(2);
    QTimer::singleShot(0, &dialog, [&dialog] { dialog.start(); });
    QVERIFY(finished.wait(60000));
    probe.stop();
    QCOMPARE(deepest, 1);
    QCOMPARE(finished.first().first().toBool(), false); // interrupted is not a pass
    // Stop reaches the run after the third check is shown: the checks decided meanwhile are kept,
    // the rest are not run.
    const int rows = dialog.model()->rowCount();
    QVERIFY2(rows >= 3 && rows < dialog.findChild<QProgressBar *>()->maximum(), qPrintable(QString::number(rows)));
    QCOMPARE(dialog.result()->checks.size(), rows);
    QVERIFY(dialog.result()->interrupted);
    QVERIFY(dialog.findChild<QLabel *>(QStringLiteral("conformStatus"))->text().contains(QStringLiteral("Interrupted")));
    QVERIFY(dialog.findChild<QPushButton *>(QStringLiteral("conformStart"))->isEnabled());
}

void TestConformanceDialog::badFieldsAreSaid_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("says");
    QTest::newRow("no target") << "conformTarget" << "" << "Type the link of the slave under test";
    QTest::newRow("bad target") << "conformTarget" << "tcpp://1.2.3.4" << "tcpp";
    QTest::newRow("bad writable") << "conformWritable" << "holdings:1" << "'holdings' is not a table";
    QTest::newRow("only selects nothing") << "conformOnly" << "nosuch" << "nosuch selects no check";
    QTest::newRow("unknown profile") << "conformProfile" << "nosuch-profile" << "Profile nosuch-profile";
}

void TestConformanceDialog::badFieldsAreSaid()
{
    QFETCH(QString, field);
    QFETCH(QString, text);
    QFETCH(QString, says);
    ConformanceDialog dialog;
    fill(dialog, QString(), QString());
    dialog.findChild<QLineEdit *>(field)->setText(text);
    QSignalSpy finished(&dialog, &ConformanceDialog::finished);
    dialog.start();
    QVERIFY(!dialog.isRunning());
    QVERIFY(!dialog.settings());
    const QString status = dialog.findChild<QLabel *>(QStringLiteral("conformStatus"))->text();
    QVERIFY2(status.contains(says.toHtmlEscaped()), qPrintable(status));
    QCOMPARE(dialog.model()->rowCount(), 0);
}

void TestConformanceDialog::verdictColours_data()
{
    QTest::addColumn<int>("verdict");
    QTest::addColumn<int>("level");
    QTest::addColumn<QString>("label");
    QTest::addColumn<int>("severity"); // -1: green (a pass), -2: no colour
    QTest::newRow("mandatory failed") << int(CheckVerdict::Failed) << int(CheckLevel::Mandatory) << "FAIL" << int(Severity::Error);
    QTest::newRow("recommended failed") << int(CheckVerdict::Failed) << int(CheckLevel::Recommended) << "WARN" << int(Severity::Warning);
    QTest::newRow("error") << int(CheckVerdict::Error) << int(CheckLevel::Mandatory) << "ERROR" << int(Severity::Error);
    QTest::newRow("measured") << int(CheckVerdict::Passed) << int(CheckLevel::Informational) << "INFO" << int(Severity::Info);
    QTest::newRow("passed") << int(CheckVerdict::Passed) << int(CheckLevel::Mandatory) << "PASS" << -1;
    QTest::newRow("skipped") << int(CheckVerdict::Skipped) << int(CheckLevel::Mandatory) << "SKIP" << -2;
}

void TestConformanceDialog::verdictColours()
{
    QFETCH(int, verdict);
    QFETCH(int, level);
    QFETCH(QString, label);
    QFETCH(int, severity);
    ConformanceResultModel model;
    CheckResult r;
    r.id = QStringLiteral("x.y");
    r.verdict = CheckVerdict(verdict);
    r.level = CheckLevel(level);
    model.append(r);
    const QModelIndex cell = model.index(0, ConformanceResultModel::VerdictColumn);
    QCOMPARE(cell.data().toString(), label);
    const QColor colour = cell.data(Qt::BackgroundRole).value<QColor>();
    if (severity >= 0) {
        QCOMPARE(colour, SeverityStyle::backgroundColor(Severity(severity)));
    } else if (severity == -1) {
        QVERIFY(colour.isValid());
        QVERIFY(colour.green() > colour.red());
    } else {
        QVERIFY(!colour.isValid());
    }
}

void TestConformanceDialog::toolsMenuOpensIt()
{
    MainWindow window;
    window.connectionBar()->setUrl(m_url);
    auto *action = window.findChild<QAction *>(QStringLiteral("conformanceAction"));
    QVERIFY(action);
    action->trigger();
    auto *dialog = window.findChild<ConformanceDialog *>();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    const std::optional<ConformanceSettings> settings = dialog->settings();
    QVERIFY(settings);
    QCOMPARE(settings->url.port, m_url.port);
    QCOMPARE(settings->url.kind, m_url.kind);
    QVERIFY(settings->writable.isEmpty()); // never writes unless told where
    dialog->close();
}

// A run from Tools > Conformance puts its frames in the window's traffic list, as a scan does
// (before session 14 the list stayed empty): each request the scorecard shows is there, sent.
void TestConformanceDialog::runReachesTheTrafficList()
{
    MainWindow window;
    window.connectionBar()->setUrl(m_url);
    window.findChild<QAction *>(QStringLiteral("conformanceAction"))->trigger();
    auto *dialog = window.findChild<ConformanceDialog *>();
    QVERIFY(dialog);
    fill(*dialog, QString(), QStringLiteral("read.03"));
    const TrafficModel *traffic = window.trafficMonitor()->model();
    const qsizetype before = traffic->frameCount();
    QSignalSpy finished(dialog, &ConformanceDialog::finished);
    QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("conformStart")), Qt::LeftButton);
    QVERIFY(finished.wait(120000));
    const std::optional<ConformanceResult> &result = dialog->result();
    QVERIFY(result && !result->checks.isEmpty());
    QSet<QByteArray> sent;
    QTRY_VERIFY_WITH_TIMEOUT(traffic->frameCount() > before, 5000);
    for (qsizetype i = before; i < traffic->frameCount(); ++i) {
        const TrafficEntry e = traffic->frameAt(i);
        if (e.direction == TrafficDirection::Out)
            sent.insert(e.bytes.toByteArray());
    }
    int requests = 0;
    for (const CheckResult &c : result->checks) {
        if (c.request.isEmpty())
            continue;
        ++requests;
        QVERIFY2(sent.contains(c.request), qPrintable(c.id + QStringLiteral(": ") + QString::fromLatin1(c.request.toHex(' '))));
    }
    QVERIFY(requests > 3);
    dialog->close();
}

void TestConformanceDialog::windowAgreesWithTheCommandLine_data()
{
    QTest::addColumn<QString>("device"); // "pymodbus", or a fault rule the simulator commits
    QTest::addColumn<QStringList>("failing"); // the mandatory checks both must fail
    QTest::newRow("simulator, transaction id not echoed")
        << R"({"kind": "wrongTransactionId"})" << QStringList{QStringLiteral("mbap.transaction-id"), QStringLiteral("mbap.pipelined")};
    QTest::newRow("pymodbus") << "pymodbus"
                              << QStringList{QStringLiteral("mbap.foreign-protocol"), QStringLiteral("mbap.unit-ff"),
                                             QStringLiteral("diag.echo"), QStringLiteral("write.05.bad-value")};
}

// The same device judged by mbscope conform --json and by the window: the same verdict for every
// check, the same overall verdict in the status line; the window's picture is saved (to
// MBSCOPE_CONFORMANCE_COMPARE_DIR when set) for a person to look at.
void TestConformanceDialog::windowAgreesWithTheCommandLine()
{
    QFETCH(QString, device);
    QFETCH(QStringList, failing);
    testpeers::PeerProcess peer;
    QProcess sim; // killed when it goes
    QString target;
    if (device == QLatin1String("pymodbus")) {
        QString why;
        if (!testpeers::pymodbusAvailable(&why))
            QSKIP(qPrintable(why));
        QVERIFY2(peer.start(testpeers::systemPython(), {testpeers::peersDir() + QStringLiteral("/pymodbus_server.py"), QStringLiteral("tcp")}),
                 qPrintable(peer.error()));
        target = QStringLiteral("tcp://127.0.0.1:%1").arg(peer.port());
    } else {
        const QString faults = m_dir.filePath(QStringLiteral("faults.json"));
        QFile f(faults);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(QStringLiteral(R"({"seed": 1, "rules": [%1]})").arg(device).toUtf8());
        f.close();
        sim.setProcessChannelMode(QProcess::SeparateChannels);
        sim.start(QStringLiteral(MBSCOPE_BINARY), {QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"),
                                                   QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--faults"), faults});
        QByteArray seen;
        while (!seen.contains("listening tcp://") || !seen.mid(seen.indexOf("listening tcp://")).contains('\n')) {
            QVERIFY2(sim.waitForReadyRead(30000), qPrintable(QString::fromUtf8(seen + sim.readAllStandardError())));
            seen += sim.readAllStandardOutput();
        }
        const QByteArray line = seen.mid(seen.indexOf("listening tcp://") + 10);
        target = QString::fromUtf8(line.left(line.indexOf('\n'))).section(QLatin1Char(' '), 0, 0);
    }
    const QString writable = QStringLiteral("holding:10-13, coils:10-17");

    QProcess cli;
    cli.start(QStringLiteral(MBSCOPE_BINARY),
              {QStringLiteral("conform"), QStringLiteral("--target"), target, QStringLiteral("--timeout"), QStringLiteral("1500ms"),
               QStringLiteral("--writable"), QStringLiteral("holding:10-13"), QStringLiteral("--writable"), QStringLiteral("coils:10-17"),
               QStringLiteral("--json")});
    QVERIFY(cli.waitForFinished(240000));
    QCOMPARE(cli.exitCode(), 1);
    const QJsonObject card = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
    QMap<QString, QString> byCli;
    for (const QJsonValue &c : card.value(QStringLiteral("checks")).toArray())
        byCli.insert(c[QStringLiteral("id")].toString(), c[QStringLiteral("verdict")].toString());
    QVERIFY(byCli.size() > 10);

    ConformanceDialog dialog;
    fill(dialog, writable, QString());
    const LinkUrl::Result url = LinkUrl::parse(target);
    QVERIFY2(url.url, qPrintable(target + QStringLiteral(": ") + url.error));
    dialog.setTarget(*url.url);
    dialog.findChild<QSpinBox *>(QStringLiteral("conformTimeout"))->setValue(1500);
    dialog.findChild<QLineEdit *>(QStringLiteral("conformProfile"))->clear();
    dialog.show();
    QSignalSpy finished(&dialog, &ConformanceDialog::finished);
    QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("conformStart")), Qt::LeftButton);
    QVERIFY(finished.wait(240000));
    QCOMPARE(finished.first().first().toBool(), false);
    const QMap<QString, QString> byWindow = verdicts(dialog.model());
    QCOMPARE(byWindow, byCli);
    for (const QString &id : failing)
        QVERIFY2(byWindow.value(id) == QLatin1String("failed"), qPrintable(id + QStringLiteral(": ") + byWindow.value(id)));
    const QString status = dialog.findChild<QLabel *>(QStringLiteral("conformStatus"))->text();
    const int failedMandatory = card.value(QStringLiteral("counts"))[QStringLiteral("failed_mandatory")].toInt();
    QVERIFY(failedMandatory >= failing.size());
    const QString cliVerdict = QStringLiteral("%1 mandatory check(s) failed").arg(failedMandatory);
    QVERIFY2(status.contains(cliVerdict, Qt::CaseInsensitive), qPrintable(status + QStringLiteral(" | ") + cliVerdict));

    const QString dir = qEnvironmentVariable("MBSCOPE_CONFORMANCE_COMPARE_DIR", m_dir.path());
    dialog.resize(1400, 760);
    QCoreApplication::sendPostedEvents();
    const QString tag = QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-')).remove(QLatin1Char(','));
    QVERIFY(dialog.grab().save(dir + QStringLiteral("/conformance-") + tag + QStringLiteral(".png"), "PNG"));
    dialog.close();
}

QTEST_MAIN(TestConformanceDialog)
#include "tst_conformancedialog.moc"
