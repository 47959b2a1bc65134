// "Save Traffic As" in the traffic dock and the File menu: a poll of the embedded simulator
// (rosrao-gamma on RTU over TCP, with an exception and a frame of garbage) fed to the list as the
// window feeds it, then saved as a journal (read back frame for frame), pcapng (decoded by tshark
// with the option the message prints), pcap, CSV and JSON lines (a row per transaction), all of
// it or only what the filter shows; and the whole path a user takes: the button, the question
// about the filter, the file dialog with a name typed without its ending, the message.
#include "guitestsupport.h"
#include "sim/embeddedsimulator.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"
#include "traffic/trafficsaver.h"

#include "engine/transactionengine.h"
#include "exchange/requestitem.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QToolButton>

using namespace mbscope;

namespace {

const QByteArray kRosRaoRead = QByteArray::fromHex("01 03 00 79 00 16 15 DD");
// Register 0xFFF0 is outside rosrao-gamma's table: exception 02 (CRC computed by hand).
const QByteArray kOutside = QByteArray::fromHex("01 03 FF F0 00 01 B4 2D");
constexpr int kReads = 20;

QStringList lines(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

// Calls check on the next modal widget of type T once it is shown.
template<typename T>
void whenShown(const std::function<void(T *)> &check)
{
    QTimer::singleShot(0, qApp, [check] {
        QTRY_VERIFY(qobject_cast<T *>(QApplication::activeModalWidget()));
        check(qobject_cast<T *>(QApplication::activeModalWidget()));
    });
}

} // namespace

class TestTrafficSave : public QObject
{
    Q_OBJECT

private:
    EmbeddedSimulator m_simulator;
    QString m_url;
    std::unique_ptr<TrafficMonitor> m_monitor;
    QTemporaryDir m_dir;
    int m_transactions = 0;

private Q_SLOTS:
    void initTestCase();
    void journalHoldsTheFrames();
    void pcapngDecodedByTshark();
    void csvAndJsonLines_data();
    void csvAndJsonLines();
    void shownFramesOnly();
    void throughTheDialogs();
    void typedEndingChoosesTheFormat();
    void cleanupTestCase();
};

void TestTrafficSave::initTestCase()
{
    guitest::isolateSettings();
    QVERIFY(m_dir.isValid());
    const EmbeddedSimulator::Started started = m_simulator.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    m_url = started.url.toString();
    m_monitor = std::make_unique<TrafficMonitor>();
    TransactionEngine engine;
    engine.setTarget(started.url);
    engine.setFramesPublished(true);
    QObject::connect(&engine, &TransactionEngine::framesLogged, m_monitor.get(), &TrafficMonitor::appendLinkFrames);
    for (int i = 0; i < kReads; ++i) {
        const std::optional<Transaction> t = engine.sendAndWait(RequestItem::forLink(i == 7 ? kOutside : kRosRaoRead, started.url));
        QVERIFY(t);
        QCOMPARE(t->status, i == 7 ? TransactionStatus::Exception : TransactionStatus::Ok);
    }
    m_transactions = kReads;
    QTRY_COMPARE(m_monitor->model()->frameCount(), 2 * kReads);
}

void TestTrafficSave::journalHoldsTheFrames()
{
    const QString path = m_dir.filePath(QStringLiteral("all.mbscope.journal"));
    const TrafficSaver::Result r = m_monitor->saveTo(path, TrafficFormat::Journal, false);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.frames, quint64(2 * kReads));
    QList<TrafficFrame> frames;
    const TrafficJournalRecovery recovery = TrafficJournalReader::readAll(path, &frames);
    QVERIFY(recovery.isClean());
    QCOMPARE(frames.size(), 2 * kReads);
    const TrafficModel &model = *m_monitor->model();
    for (int i = 0; i < frames.size(); ++i) {
        const TrafficEntry listed = model.frameAt(i);
        QCOMPARE(frames.at(i).bytes, listed.bytes.toByteArray());
        QCOMPARE(frames.at(i).verdict, listed.verdict);
        QCOMPARE(frames.at(i).transactionId, listed.transactionId);
        QCOMPARE(frames.at(i).tNs, listed.tNs);
    }
    QVERIFY(recovery.metadata.contains(m_url.toUtf8()));
    // The status line says what was written.
    QVERIFY(m_monitor->findChild<QLabel *>(QStringLiteral("statusLabel"))->text().contains(QStringLiteral("40 frame(s) saved")));
}

void TestTrafficSave::pcapngDecodedByTshark()
{
    const QString path = m_dir.filePath(QStringLiteral("all.pcapng"));
    const TrafficSaver::Result r = m_monitor->saveTo(path, TrafficFormat::Pcapng, false);
    QVERIFY2(r.ok, qPrintable(r.error));
    // One option for the RTU port; the traffic list does not keep the connection's client address
    // (the engine's journal does), so the capture says which address stands for it.
    const QStringList options = r.decodeOptions.filter(QStringLiteral("-o mbrtu.tcp.port:"));
    QVERIFY2(options.size() == 1, qPrintable(r.decodeOptions.join(QStringLiteral(" / "))));
    QVERIFY2(r.decodeOptions.size() == 1 || r.decodeOptions.filter(QStringLiteral("stands for it")).size() == 1,
             qPrintable(r.decodeOptions.join(QStringLiteral(" / "))));
    const QString summary = r.summary(TrafficFormat::Pcapng, path);
    QVERIFY2(summary.contains(QStringLiteral("-o mbrtu.tcp.port:")), qPrintable(summary));
    if (QStandardPaths::findExecutable(QStringLiteral("tshark")).isEmpty())
        QSKIP("tshark is not installed (Debian: apt-get install tshark)");
    QStringList arguments{QStringLiteral("-r"), path};
    arguments << options.constFirst().section(QStringLiteral(": "), 1).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    arguments << QStringLiteral("-Y") << QStringLiteral("mbrtu") << QStringLiteral("-T") << QStringLiteral("fields") << QStringLiteral("-e")
              << QStringLiteral("modbus.func_code") << QStringLiteral("-e") << QStringLiteral("modbus.exception_code");
    QProcess tshark;
    tshark.start(QStringLiteral("tshark"), arguments);
    QVERIFY(tshark.waitForFinished(120000));
    QVERIFY2(tshark.exitCode() == 0, tshark.readAllStandardError().constData());
    const QList<QByteArray> out = tshark.readAllStandardOutput().split('\n');
    int frames = 0;
    int exceptions = 0;
    for (const QByteArray &line : out) {
        if (line.isEmpty())
            continue;
        ++frames;
        exceptions += line.split('\t').value(1).trimmed() == "2"; // Illegal Data Address
    }
    QCOMPARE(frames, 2 * kReads);
    QCOMPARE(exceptions, 1);
}

void TestTrafficSave::csvAndJsonLines_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("header");
    QTest::addColumn<QString>("exception"); // how the exception's row says so
    QTest::newRow("csv") << int(TrafficFormat::Csv) << QStringLiteral("all.csv") << 1 << QStringLiteral(",exception,0x02");
    QTest::newRow("json lines") << int(TrafficFormat::JsonLines) << QStringLiteral("all.jsonl") << 0
                                << QStringLiteral("\"status\":\"exception\"");
}

void TestTrafficSave::csvAndJsonLines()
{
    QFETCH(int, format);
    QFETCH(QString, name);
    QFETCH(int, header);
    QFETCH(QString, exception);
    const QString path = m_dir.filePath(name);
    const TrafficSaver::Result r = m_monitor->saveTo(path, TrafficFormat(format), false);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.written, quint64(m_transactions));
    const QStringList rows = lines(path);
    QCOMPARE(rows.size(), m_transactions + header);
    QCOMPARE(rows.filter(exception).size(), 1);
}

void TestTrafficSave::shownFramesOnly()
{
    // Only the answers: the CSV has the exception's row, no request, so every row is an answer
    // without its request; the journal has the 20 frames in.
    auto *direction = m_monitor->findChild<QComboBox *>(QStringLiteral("directionFilter"));
    direction->setCurrentIndex(2);
    QCOMPARE(m_monitor->model()->rowCount(), kReads);
    const QString path = m_dir.filePath(QStringLiteral("answers.mbscope.journal"));
    const TrafficSaver::Result r = m_monitor->saveTo(path, TrafficFormat::Journal, true);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.frames, quint64(kReads));
    QList<TrafficFrame> frames;
    QVERIFY(TrafficJournalReader::readAll(path, &frames).isClean());
    for (const TrafficFrame &f : std::as_const(frames))
        QCOMPARE(f.direction, TrafficDirection::In);
    direction->setCurrentIndex(0);
}

void TestTrafficSave::throughTheDialogs()
{
    // A filter hides some frames: the save asks which, the user picks the shown ones.
    auto *verdict = m_monitor->findChild<QComboBox *>(QStringLiteral("verdictFilter"));
    verdict->setCurrentIndex(verdict->findData(int(TrafficVerdict::Exception)));
    QCOMPARE(m_monitor->model()->rowCount(), 1);
    whenShown<QMessageBox>([this](QMessageBox *ask) {
        QCOMPARE(ask->objectName(), QStringLiteral("saveWhichFrames"));
        QVERIFY(ask->text().contains(QStringLiteral("1 of the 40")));
        for (QAbstractButton *b : ask->buttons()) {
            if (b->text().contains(QStringLiteral("Shown")))
                b->click();
        }
        // Then the file dialog: CSV picked, a name typed without its ending.
        whenShown<QFileDialog>([this](QFileDialog *dialog) {
            dialog->setOption(QFileDialog::DontUseNativeDialog);
            dialog->selectNameFilter(TrafficSaver::nameFilters().at(int(TrafficFormat::Csv)));
            dialog->selectFile(m_dir.filePath(QStringLiteral("picked")));
            QMetaObject::invokeMethod(dialog, "accept");
        });
    });
    m_monitor->findChild<QToolButton *>(QStringLiteral("saveTrafficButton"))->click();
    const QString saved = m_dir.filePath(QStringLiteral("picked.csv"));
    QTRY_VERIFY(QFile::exists(saved));
    QCOMPARE(lines(saved).size(), 1 + 1); // the header and the exception's row
    QTRY_VERIFY(m_monitor->findChild<QMessageBox *>(QStringLiteral("trafficSavedMessage")));
    auto *message = m_monitor->findChild<QMessageBox *>(QStringLiteral("trafficSavedMessage"));
    QVERIFY2(message->text().contains(QStringLiteral("1 frame(s) saved")), qPrintable(message->text()));
    message->close();
    verdict->setCurrentIndex(0);
}

// Issue 26 item 14: a name typed as "typed.pcapng" while the filter said journal was written as
// "typed.pcapng.mbscope.journal". The typed ending chooses the format; a name without one still
// gets the filter's.
void TestTrafficSave::typedEndingChoosesTheFormat()
{
    QCOMPARE(m_monitor->model()->rowCount(), 2 * kReads);
    QTRY_VERIFY(!m_monitor->findChild<QMessageBox *>(QStringLiteral("trafficSavedMessage")));
    whenShown<QFileDialog>([this](QFileDialog *dialog) {
        dialog->setOption(QFileDialog::DontUseNativeDialog);
        QCOMPARE(dialog->selectedNameFilter(), TrafficSaver::nameFilters().at(int(TrafficFormat::Journal)));
        dialog->selectFile(m_dir.filePath(QStringLiteral("typed.pcapng")));
        QMetaObject::invokeMethod(dialog, "accept");
    });
    m_monitor->findChild<QToolButton *>(QStringLiteral("saveTrafficButton"))->click();
    const QString saved = m_dir.filePath(QStringLiteral("typed.pcapng"));
    QTRY_VERIFY(QFile::exists(saved) || QFile::exists(saved + QStringLiteral(".mbscope.journal")));
    QVERIFY(!QFile::exists(saved + QStringLiteral(".mbscope.journal")));
    QFile file(saved);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.read(4), QByteArray::fromHex("0A0D0D0A")); // a pcapng section header block
    QTRY_VERIFY(m_monitor->findChild<QMessageBox *>(QStringLiteral("trafficSavedMessage")));
    auto *message = m_monitor->findChild<QMessageBox *>(QStringLiteral("trafficSavedMessage"));
    QVERIFY2(message->text().contains(QStringLiteral("typed.pcapng")), qPrintable(message->text()));
    message->close();
    QTRY_VERIFY(!m_monitor->findChild<QMessageBox *>(QStringLiteral("trafficSavedMessage")));

    // A name without an ending: the filter's format (pcap) and its ending.
    whenShown<QFileDialog>([this](QFileDialog *dialog) {
        dialog->setOption(QFileDialog::DontUseNativeDialog);
        dialog->selectNameFilter(TrafficSaver::nameFilters().at(int(TrafficFormat::Pcap)));
        dialog->selectFile(m_dir.filePath(QStringLiteral("plain")));
        QMetaObject::invokeMethod(dialog, "accept");
    });
    m_monitor->findChild<QToolButton *>(QStringLiteral("saveTrafficButton"))->click();
    QTRY_VERIFY(QFile::exists(m_dir.filePath(QStringLiteral("plain.pcap"))));
    QTRY_VERIFY(m_monitor->findChild<QMessageBox *>(QStringLiteral("trafficSavedMessage")));
    m_monitor->findChild<QMessageBox *>(QStringLiteral("trafficSavedMessage"))->close();
}

void TestTrafficSave::cleanupTestCase()
{
    m_monitor.reset();
    m_simulator.stop();
}

QTEST_MAIN(TestTrafficSave)
#include "tst_trafficsave.moc"
