// The window as a daily tool (issue 14): what a day of use against the simulator ran into, each
// checked through the window as a user drives it.
#include "guitestsupport.h"
#include "link/connectionbar.h"
#include "link/linkcontroller.h"
#include "session/sessioncontroller.h"
#include "shell/mainwindow.h"
#include "decode/decodeview.h"
#include "decode/fieldtreeview.h"
#include "decode/frameinspector.h"
#include "decode/hexview.h"
#include "decode/transactionview.h"
#include "analysis/latencyanalysis.h"
#include "analysis/latencyhistogrampanel.h"
#include <qcustomplot.h>
#include "registers/registertable.h"
#include "registers/registertablemodel.h"
#include "shell/translationloader.h"
#include "shell/preferencesdialog.h"
#include "traffic/trafficmonitor.h"
#include "compose/requestcomposer.h"
#include "compose/rawrequesteditor.h"
#include "sim/embeddedsimulator.h"
#include "sim/simulatorhost.h"
#include "sim/simtrafficrecord.h"
#include "common/lastfolder.h"

#include <QtCore/QFile>
#include <QtCore/QTimer>
#include <QtCore/QSettings>
#include <QtWidgets/QSpinBox>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtTest/QSignalSpy>
#include <QtWidgets/QAbstractButton>
#include <QtWidgets/QApplication>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QTabBar>
#include <QtWidgets/QTreeView>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

const QString kAnyPort = QStringLiteral("rtu-tcp://127.0.0.1:0");
constexpr int kWaitMs = 5000;

bool writeFile(const QString &path, const QByteArray &text)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(text) == text.size();
}

// The register table's row of a PDU address, or -1.
int rowOf(const RegisterTableModel *model, int address)
{
    for (int r = 0; r < model->rowCount(); ++r) {
        if (model->index(r, 0).data(RegisterTableModel::AddressRole).toInt() == address)
            return r;
    }
    return -1;
}

} // namespace

class TestDailyUse : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void openedSessionIsTheTargetUsed();
    void saveAsAddsTheSuffix();
    void laterStartsPutBackTheLastTarget();
    void mnemonicsAreUnique_data();
    void mnemonicsAreUnique();
    void sendAndPollKeysWorkFromTheTrafficList();
    void ctrlFInTheTrafficDockFocusesItsSearch();
    void f6MovesBetweenDocks();
    void tableWriteIsReadBack();
    void transactionIdsAreUniqueOnTheConnection();
    void histogramFollowsTheLivePoll();
    void smallScreens_data();
    void smallScreens();
    void resavedExampleIsWhatWasLoaded();
    void fileDialogsOpenWhereTheUserWas_data();
    void fileDialogsOpenWhereTheUserWas();
    void openSessionDialogStartsInTheLastFolder();
};

void TestDailyUse::initTestCase()
{
    guitest::isolateSettings();
}

// Item 1: the bar shows the session's target and Send goes there, not to the previous link.
void TestDailyUse::openedSessionIsTheTargetUsed()
{
    MainWindow window;
    window.session()->setProblemReport([](const QString &, const QStringList &problems) { qWarning() << problems; });
    QVERIFY(window.startWithSimulator(kAnyPort));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kWaitMs);
    EmbeddedSimulator plc;
    const EmbeddedSimulator::Started started = plc.start(QStringLiteral("rosrao-gamma"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plc.mbscope.json"));
    QVERIFY(writeFile(path, QStringLiteral(R"({"format": "mbscope-session", "version": 1,
        "target": {"url": "%1", "timeoutMs": 500},
        "requests": [{"name": "read", "hex": "00 01 00 00 00 06 01 03 00 79 00 01"}]})")
                                .arg(started.url.toString()).toUtf8()));
    QVERIFY(window.session()->open(path));
    const std::optional<LinkUrl> shown = window.connectionBar()->url();
    QVERIFY(shown.has_value());
    QCOMPARE(shown->kind, LinkKind::Tcp);
    QCOMPARE(window.controller()->url().toString(), shown->toString());
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kWaitMs);
    QVERIFY(window.connectionBar()->isConnected());
}

// Item 9: a name without .json gets .mbscope.json, the suffix the Open dialog lists.
void TestDailyUse::saveAsAddsTheSuffix()
{
    MainWindow window;
    QTemporaryDir dir;
    QVERIFY(window.session()->saveAs(dir.filePath(QStringLiteral("bench"))));
    QVERIFY(QFile::exists(dir.filePath(QStringLiteral("bench.mbscope.json"))));
    QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("bench"))));
    QCOMPARE(window.session()->filePath(), dir.filePath(QStringLiteral("bench.mbscope.json")));
}

// Item 9: re-saving the example keeps its poll block and adds neither the built-in presets nor
// a "composer" request.
void TestDailyUse::resavedExampleIsWhatWasLoaded()
{
    const QString example = QStringLiteral(MBSCOPE_SOURCE_DIR "/docs/examples/rosrao-gamma.mbscope.json");
    MainWindow window;
    QVERIFY(window.session()->open(example));
    QVERIFY(!window.session()->isModified());
    QTemporaryDir dir;
    const QString copy = dir.filePath(QStringLiteral("copy.mbscope.json"));
    QVERIFY(window.session()->saveAs(copy));
    auto read = [](const QString &path) {
        QFile file(path);
        file.open(QIODevice::ReadOnly);
        return QJsonDocument::fromJson(file.readAll()).object();
    };
    const QJsonObject before = read(example);
    const QJsonObject after = read(copy);
    QVERIFY(after.contains(QLatin1String("poll")));
    QCOMPARE(after.value(QLatin1String("poll")), before.value(QLatin1String("poll")));
    auto names = [](const QJsonObject &o) {
        QStringList list;
        for (const QJsonValue &r : o.value(QLatin1String("requests")).toArray())
            list << r.toObject().value(QLatin1String("name")).toString();
        return list;
    };
    QCOMPARE(names(after), names(before));
}


void TestDailyUse::mnemonicsAreUnique_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("id") << QStringLiteral("id");
}

// Item 4: Alt+R/S/V/T opened no menu: "Raw", "Send", "Verdict", "Timeout" held the same letters.
// Every accelerator of the shown window, in both languages, belongs to one thing only.
void TestDailyUse::mnemonicsAreUnique()
{
    QFETCH(QString, language);
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(*TranslationLoader::parse(language)));
    {
        MainWindow window;
        QVERIFY(window.startWithSimulator(kAnyPort));
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QMultiMap<QChar, QString> found = guitest::visibleMnemonics(&window);
        QStringList clashes;
        for (const QChar letter : found.uniqueKeys()) {
            const QStringList owners = found.values(letter);
            if (owners.size() > 1)
                clashes << QStringLiteral("Alt+%1: %2").arg(letter.toUpper(), owners.join(QLatin1String(", ")));
        }
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
    }
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
}

// Item 4: Ctrl+Return and Ctrl+Shift+Return act from anywhere in the window, not only the composer.
void TestDailyUse::sendAndPollKeysWorkFromTheTrafficList()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kWaitMs);
    QWidget *list = window.trafficMonitor()->view();
    window.activateWindow();
    list->setFocus();
    QTRY_VERIFY(list->hasFocus());
    QSignalSpy latest(window.controller(), &LinkController::latestTransaction);
    QTest::keyClick(list, Qt::Key_Return, Qt::ControlModifier);
    QVERIFY(latest.wait(kWaitMs));
    QTest::keyClick(list, Qt::Key_Return, Qt::ControlModifier | Qt::ShiftModifier);
    QTRY_VERIFY_WITH_TIMEOUT(window.controller()->isPolling(), kWaitMs);
    list->setFocus();
    QTest::keyClick(list, Qt::Key_Return, Qt::ControlModifier | Qt::ShiftModifier);
    QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isPolling(), kWaitMs);
}

// Item 4: Ctrl+F with the focus in the Traffic dock goes to its search field.
void TestDailyUse::ctrlFInTheTrafficDockFocusesItsSearch()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QWidget *list = window.trafficMonitor()->view();
    list->setFocus();
    QTRY_VERIFY(list->hasFocus());
    QTest::keyClick(list, Qt::Key_F, Qt::ControlModifier);
    QTRY_VERIFY(qobject_cast<QLineEdit *>(QApplication::focusWidget()));
    QVERIFY(window.trafficMonitor()->isAncestorOf(QApplication::focusWidget()));
    // And from the composer, the window's Find in traffic goes there too.
    window.composer()->rawEditor()->editor()->setFocus();
    QTRY_VERIFY(window.composer()->rawEditor()->editor()->hasFocus());
    QTest::keyClick(window.composer()->rawEditor()->editor(), Qt::Key_F, Qt::ControlModifier);
    QTRY_VERIFY(window.trafficMonitor()->isAncestorOf(QApplication::focusWidget()));
}

// Item 4: F6 moves the keyboard from dock to dock.
void TestDailyUse::f6MovesBetweenDocks()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    window.composer()->rawEditor()->editor()->setFocus();
    QTRY_VERIFY(window.composer()->rawEditor()->editor()->hasFocus());
    // Every open dock in turn, tabbed ones brought forward, then round again.
    const int open = int(window.findChildren<QDockWidget *>().size());
    QVERIFY(open >= 6);
    QSet<QDockWidget *> visited;
    for (int i = 0; i < open; ++i) {
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_F6);
        QTest::qWait(20);
        QWidget *focus = QApplication::focusWidget();
        QVERIFY(focus);
        QDockWidget *dock = nullptr;
        for (QWidget *w = focus; w && !dock; w = w->parentWidget())
            dock = qobject_cast<QDockWidget *>(w);
        QVERIFY2(dock, focus->metaObject()->className());
        QVERIFY2(!visited.contains(dock), qPrintable(dock->objectName() + QStringLiteral(" again after %1").arg(visited.size())));
        visited.insert(dock);
    }
    QCOMPARE(int(visited.size()), open);
}

// Item 3: only the first run starts the simulator; a later start puts back the last target
// (disconnected) and poll interval; Preferences can ask for the simulator at every start.
void TestDailyUse::laterStartsPutBackTheLastTarget()
{
    QSettings().remove(QStringLiteral("startup"));
    QSettings().remove(QStringLiteral("session/last"));
    QString target;
    {
        MainWindow first;
        first.session()->setChangesPrompt([](const QString &) { return SessionController::Choice::Discard; });
        QVERIFY(first.startAsConfigured(kAnyPort));
        QVERIFY(first.simulator()->isRunning());
        QTRY_COMPARE_WITH_TIMEOUT(first.controller()->state(), LinkController::State::Connected, kWaitMs);
        target = first.controller()->url().toString();
        first.composer()->intervalSpin()->setValue(250);
        first.registerTable()->model()->setValueFormats({RegisterFormat::parse(QStringLiteral("f32-cdab")).format,
                                                         RegisterFormat::parse(QStringLiteral("hex")).format});
        first.show();
        QVERIFY(first.close());
    }
    {
        MainWindow later;
        QVERIFY(!later.startAsConfigured(kAnyPort));
        QVERIFY(!later.simulator()->isRunning());
        QVERIFY(!later.controller()->isConnected());
        QCOMPARE(later.connectionBar()->url()->toString(), target);
        QCOMPARE(later.composer()->intervalSpin()->value(), 250);
        const QList<RegisterFormat> formats = later.registerTable()->model()->valueFormats();
        QCOMPARE(formats.size(), 2);
        QCOMPARE(formats.at(0).name(), QStringLiteral("f32-cdab"));
        QCOMPARE(formats.at(1).name(), QStringLiteral("hex"));
    }
    QSettings().setValue(QLatin1String(PreferencesDialog::kStartSimulatorKey), true);
    {
        MainWindow always;
        QVERIFY(always.startAsConfigured(kAnyPort));
        QVERIFY(always.simulator()->isRunning());
        // Issue 31: the poll interval comes back when every start is on the simulator too.
        QCOMPARE(always.composer()->intervalSpin()->value(), 250);
    }
    QSettings().remove(QLatin1String(PreferencesDialog::kStartSimulatorKey));
}

// Item 14: a register written from the table is read back: the table shows the device's value.
void TestDailyUse::tableWriteIsReadBack()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kWaitMs);
    QSignalSpy transactions(window.controller(), &LinkController::transactionsFinished);
    window.composer()->send();
    RegisterTableModel *model = window.registerTable()->model();
    QTRY_VERIFY_WITH_TIMEOUT(model->hasAnswer(), kWaitMs);
    model->setValueFormats({RegisterFormat(RegisterType::UInt16)});
    // 0x007F, the measuring time (1000).
    const int row = rowOf(model, 0x7F);
    QVERIFY(row >= 0);
    const QModelIndex cell = model->index(row, RegisterTableModel::FirstValueColumn);
    QCOMPARE(cell.data(RegisterTableModel::RawRole).toInt(), 1000);
    transactions.clear();
    QVERIFY(model->setData(cell, QStringLiteral("2000")));
    // The write, then the read again: two transactions, the table showing what the device holds.
    QTRY_VERIFY_WITH_TIMEOUT([&] {
        int count = 0;
        for (const QList<QVariant> &batch : std::as_const(transactions))
            count += int(batch.first().value<QList<Transaction>>().size());
        return count >= 2;
    }(), kWaitMs);
    QList<Transaction> all;
    for (const QList<QVariant> &batch : std::as_const(transactions))
        all += batch.first().value<QList<Transaction>>();
    const quint8 write = quint8(all.at(0).request.at(1));
    QVERIFY(write == 0x06 || write == 0x10);
    QCOMPARE(quint8(all.at(1).request.at(1)), quint8(0x03));
    QTRY_COMPARE_WITH_TIMEOUT(model->index(row, RegisterTableModel::FirstValueColumn).data(RegisterTableModel::RawRole).toInt(),
                              2000, kWaitMs);
}

// Issue 26, item 2: every request on one Modbus/TCP connection, whoever makes it (the composer's
// Send and Poll, the register table's write and the read back after it), carries a transaction
// id of its own, as the server sees them: they were 1, 1, 1... (each producer numbered from 1).
void TestDailyUse::transactionIdsAreUniqueOnTheConnection()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(QStringLiteral("tcp://127.0.0.1:0")));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kWaitMs);
    SimulatorHost *host = window.simulator()->host();
    QVERIFY(host);
    QList<quint16> seen; // the transaction ids of the requests the simulator answered, in order
    connect(host, &SimulatorHost::trafficRecorded, this, [&seen](const QList<SimTrafficRecord> &records, int) {
        for (const SimTrafficRecord &r : records) {
            if (r.entry.verdict == SimLogEntry::Verdict::Answered && r.entry.request.size() >= 8)
                seen.append(quint16(quint8(r.entry.request.at(0)) << 8 | quint8(r.entry.request.at(1))));
        }
    });
    window.composer()->rawEditor()->setText(QStringLiteral("00 01 00 00 00 06 01 03 00 79 00 16"));
    window.composer()->send();
    RegisterTableModel *model = window.registerTable()->model();
    QTRY_VERIFY_WITH_TIMEOUT(model->hasAnswer(), kWaitMs);
    model->setValueFormats({RegisterFormat(RegisterType::UInt16)});
    const int row = rowOf(model, 0x7F);
    QVERIFY(row >= 0);
    // The table's write and its read back.
    QVERIFY(model->setData(model->index(row, RegisterTableModel::FirstValueColumn), QStringLiteral("2000")));
    QTRY_COMPARE_WITH_TIMEOUT(seen.size(), 3, kWaitMs);
    // A poll of three.
    QSignalSpy finished(window.controller(), &LinkController::pollFinished);
    window.composer()->intervalSpin()->setValue(0);
    window.composer()->countSpin()->setValue(3);
    window.composer()->pollAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(seen.size(), 6, kWaitMs);
    // Another write from the table, then Send once more.
    QVERIFY(model->setData(model->index(row, RegisterTableModel::FirstValueColumn), QStringLiteral("1000")));
    QTRY_COMPARE_WITH_TIMEOUT(seen.size(), 8, kWaitMs);
    window.composer()->send();
    QTRY_COMPARE_WITH_TIMEOUT(seen.size(), 9, kWaitMs);
    for (qsizetype i = 1; i < seen.size(); ++i)
        QVERIFY2(seen.at(i) > seen.at(i - 1), qPrintable(QStringLiteral("transaction ids as the server saw them: %1")
                                                            .arg([&seen] {
                                                                QStringList ids;
                                                                for (const quint16 id : seen)
                                                                    ids << QString::number(id);
                                                                return ids.join(QStringLiteral(", "));
                                                            }())));
}

// Item 11: the histogram leaves an opened capture when a poll starts; one sample, one label.
void TestDailyUse::histogramFollowsTheLivePoll()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kWaitMs);
    LatencyHistogramPanel *histogram = window.latencyAnalysis()->histogramPanel();
    Transaction t;
    t.status = TransactionStatus::Ok;
    t.request = QByteArray::fromHex("01030079001615DD");
    t.response = QByteArray::fromHex("0103020000b844");
    t.sentNs = 1000000000;
    t.firstByteNs = t.sentNs + 1000000;
    t.doneNs = t.sentNs + 1500000;
    window.latencyAnalysis()->showTransactions(QStringLiteral("plant.pcapng"), {t});
    QCOMPARE(histogram->run(), LatencyRuns::Capture);
    histogram->redrawNow();
    int labels = 0;
    for (int i = 0; i < histogram->findChild<QCustomPlot *>()->itemCount(); ++i)
        labels += qobject_cast<QCPItemText *>(histogram->findChild<QCustomPlot *>()->item(i)) ? 1 : 0;
    QCOMPARE(labels, 1); // "min = median = p95 = p99 = max 1.500 ms", not five labels on one spot
    window.composer()->countSpin()->setValue(3);
    window.composer()->intervalSpin()->setValue(10);
    window.composer()->togglePoll();
    QTRY_VERIFY_WITH_TIMEOUT(window.controller()->isPolling(), kWaitMs);
    QCOMPARE(histogram->run(), LatencyRuns::Current);
}

namespace {

// Rows of a field tree the viewport shows whole.
int visibleRows(QTreeView *tree)
{
    const int row = qMax(1, tree->sizeHintForRow(0) > 0 ? tree->sizeHintForRow(0) : tree->fontMetrics().height() + 4);
    return tree->viewport()->height() / row;
}

} // namespace

void TestDailyUse::smallScreens_data()
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("1400x900 (default)") << QSize(1400, 900);
    QTest::newRow("1366x768 laptop") << QSize(1366, 768);
    QTest::newRow("1280x720") << QSize(1280, 720);
    QTest::newRow("1024x700") << QSize(1024, 700);
}

// Item 5: the window fits small screens (1024x700 and up) and the answer keeps room: eight rows
// of fields at least in the decode trees, eight bytes a line in the hex view.
void TestDailyUse::smallScreens()
{
    QFETCH(QSize, size);
    QSettings().remove(QStringLiteral("window"));
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.resize(size);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const QSize minimum = window.minimumSizeHint().expandedTo(window.minimumSize());
    QVERIFY2(minimum.width() <= 1024 && minimum.height() <= 700,
             qPrintable(QStringLiteral("minimum %1x%2").arg(minimum.width()).arg(minimum.height())));
    if (minimum.width() <= size.width() && minimum.height() <= size.height())
        QCOMPARE(window.size(), size);
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kWaitMs);
    window.composer()->send();
    QTRY_VERIFY_WITH_TIMEOUT(window.answerView()->shown().has_value(), kWaitMs);
    QCoreApplication::sendPostedEvents();
    QTest::qWait(50);
    FrameInspector *response = window.answerView()->decodeView()->responseInspector();
    const int rows = visibleRows(response->treeView());
    QVERIFY2(guitest::saveShot(&window, QStringLiteral("dailyuse-%1x%2.png").arg(size.width()).arg(size.height())), "shot");
    qInfo("%dx%d: %d field rows, %d hex bytes a line", size.width(), size.height(), rows,
          response->hexView()->bytesPerLine());
    // The answer keeps eight rows of fields at every size (its decode view gives the response two
    // thirds of the height: halved, a 720 px window showed six), and eight hex bytes a line
    // where the window is wider than 1024 px.
    QVERIFY2(rows >= 8, qPrintable(QStringLiteral("%1 field rows shown").arg(rows)));
    if (size.width() > 1024)
        QVERIFY2(response->hexView()->bytesPerLine() >= 8,
                 qPrintable(QStringLiteral("%1 bytes a line").arg(response->hexView()->bytesPerLine())));
    // The docks keep a usable share: the traffic list is not squeezed out.
    QVERIFY(window.trafficMonitor()->view()->viewport()->height() >= 60);
}

void TestDailyUse::fileDialogsOpenWhereTheUserWas_data()
{
    QTest::addColumn<QStringList>("picked"); // what the user picked, in order ("" cancelled); relative to a temporary folder
    QTest::addColumn<QString>("suggested");
    QTest::addColumn<QString>("opensAt"); // relative to the temporary folder; "~" the home folder
    QTest::newRow("nothing picked yet") << QStringList{} << QStringLiteral("traffic.csv") << QStringLiteral("~/traffic.csv");
    QTest::newRow("a file picked") << QStringList{QStringLiteral("bench/a.json")} << QStringLiteral("traffic.csv")
                                   << QStringLiteral("bench/traffic.csv");
    QTest::newRow("a folder picked") << QStringList{QStringLiteral("bench")} << QString() << QStringLiteral("bench");
    QTest::newRow("a save as, new file") << QStringList{QStringLiteral("bench/new.mbscope.json")} << QString()
                                         << QStringLiteral("bench");
    QTest::newRow("cancelled after") << QStringList{QStringLiteral("bench/a.json"), QString()} << QString()
                                     << QStringLiteral("bench");
    QTest::newRow("the last pick wins") << QStringList{QStringLiteral("bench/a.json"), QStringLiteral("a.json")}
                                        << QString() << QString();
    QTest::newRow("folder gone since") << QStringList{QStringLiteral("gone/a.json")} << QString() << QStringLiteral("~");
}

// Issue 31: file dialogs open where the user last picked or saved a file, in any of them and
// across starts (QSettings), not in the working directory.
void TestDailyUse::fileDialogsOpenWhereTheUserWas()
{
    QFETCH(QStringList, picked);
    QFETCH(QString, suggested);
    QFETCH(QString, opensAt);
    QSettings().remove(QLatin1String(LastFolder::kSettingsKey));
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("bench")));
    for (const QString &path : std::as_const(picked))
        LastFolder::remember(path.isEmpty() ? QString() : dir.filePath(path));
    if (picked.contains(QStringLiteral("gone/a.json")))
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("gone"))));
    const QString expected = opensAt.startsWith(QLatin1Char('~'))
        ? QDir::cleanPath(QDir::homePath() + opensAt.mid(1))
        : QDir::cleanPath(dir.filePath(opensAt));
    QCOMPARE(QDir::cleanPath(LastFolder::start(suggested)), expected);
    QSettings().remove(QLatin1String(LastFolder::kSettingsKey));
}

// The File menu's Open session dialog of an untitled session opens in the folder last used.
void TestDailyUse::openSessionDialogStartsInTheLastFolder()
{
    QTemporaryDir dir;
    LastFolder::remember(dir.filePath(QStringLiteral("elsewhere.pcapng")));
    MainWindow window;
    window.show();
    QAction *open = nullptr;
    for (QAction *menu : window.menuBar()->actions()) {
        for (QAction *a : menu->menu()->actions()) {
            if (a->shortcut() == QKeySequence(QKeySequence::Open))
                open = a;
        }
    }
    QVERIFY(open);
    QString shownDirectory;
    QTimer::singleShot(0, &window, [&] {
        QTRY_VERIFY(QApplication::activeModalWidget() || window.findChild<QFileDialog *>());
        auto *dialog = window.findChild<QFileDialog *>();
        if (!dialog)
            dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        shownDirectory = dialog->directory().absolutePath();
        dialog->reject();
    });
    open->trigger();
    QCOMPARE(QDir::cleanPath(shownDirectory), QDir::cleanPath(dir.path()));
    QSettings().remove(QLatin1String(LastFolder::kSettingsKey));
}

QTEST_MAIN(TestDailyUse)
#include "tst_dailyuse.moc"
