// TrafficModel and its parts (TrafficLinks, TrafficFilter, TrafficSearch): unit and function read
// per framing, answers paired with their requests (latency, the decode view's exchange), both
// feeds (traffic log frames, engine transactions), filters, pause, clear, find, the row limit;
// QAbstractItemModelTester watches every change. A million rows are appended in batches and
// filtered, with the memory per row and the times printed (figures, not assertions).
#include "traffic/trafficmodel.h"
#include "traffic/trafficsearch.h"

#include "traffic/trafficlog.h"
#include "transport/monotonicclock.h"

#include <QtCore/QDateTime>

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>

#include <memory>

using namespace mbscope;

namespace {

const QString kRtuTcp = QStringLiteral("rtu-tcp://127.0.0.1:4001");
const QString kTcp = QStringLiteral("tcp://127.0.0.1:502");
const QString kAsciiTcp = QStringLiteral("ascii-tcp://127.0.0.1:5020");

// Published frames (tests/data/published-frames.json): RosRao and the Arduino slave.
const QByteArray kRosRaoRequest = QByteArray::fromHex("01030079001615DD");
const QByteArray kArduinoRequest = QByteArray::fromHex("0103000000044409");
const QByteArray kArduinoResponse = QByteArray::fromHex("010308004500" "4E00010001791D");
// 01 83 02: Illegal Data Address from unit 1 (CRC computed).
const QByteArray kException = QByteArray::fromHex("018302C0F1");
// The M221 write (tcp, unit 1, FC 10) as an MBAP frame.
const QByteArray kMbapWrite = QByteArray::fromHex("000100000009011000000001020001");

TrafficFrame frame(qint64 tNs, TrafficDirection direction, TrafficVerdict verdict, quint64 id, const QByteArray &bytes,
                   quint16 link = 0)
{
    TrafficFrame f;
    f.tNs = tNs;
    f.direction = direction;
    f.verdict = verdict;
    f.transactionId = id;
    f.bytes = bytes;
    f.link = link;
    return f;
}

QString cell(const TrafficModel &model, int row, int column)
{
    return model.data(model.index(row, column)).toString();
}

// Resident memory of this process, from /proc (Linux): what a million rows really cost.
qint64 residentBytes()
{
    QFile statm(QStringLiteral("/proc/self/statm"));
    if (!statm.open(QIODevice::ReadOnly))
        return -1;
    const QList<QByteArray> parts = statm.readAll().split(' ');
    return parts.size() > 1 ? parts.at(1).toLongLong() * 4096 : -1;
}

} // namespace

class TestTrafficModel : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<TrafficModel> m_model;
    std::unique_ptr<QAbstractItemModelTester> m_tester;

    // A small log: RosRao poll with one timeout, an exception, unsolicited and garbage bytes.
    void fillSample();

private Q_SLOTS:
    void init();
    void cleanup();
    void keys_data();
    void keys();
    void pairsAnswersWithRequests();
    void transactionsFeed();
    void recordedAndLiveShareOneClock();
    void trafficLogFeed();
    void filter_data();
    void filter();
    void appendsWhileFiltered();
    void pauseHoldsRowsBack();
    void clearEmpties();
    void find_data();
    void find();
    void rowLimitDropsTheOldest();
    void cellsAreFormattedLazily();
    void millionRows();
};

void TestTrafficModel::init()
{
    m_model = std::make_unique<TrafficModel>();
    m_tester = std::make_unique<QAbstractItemModelTester>(m_model.get(), QAbstractItemModelTester::FailureReportingMode::QtTest);
}

void TestTrafficModel::cleanup()
{
    m_tester.reset();
    m_model.reset();
}

void TestTrafficModel::fillSample()
{
    m_model->setLinkName(0, kRtuTcp);
    const qint64 ms = 1'000'000;
    m_model->appendFrames({
        frame(0 * ms, TrafficDirection::Out, TrafficVerdict::Sent, 1, kRosRaoRequest),
        frame(12 * ms, TrafficDirection::In, TrafficVerdict::Ok, 1, kArduinoResponse),
        frame(500 * ms, TrafficDirection::Out, TrafficVerdict::Sent, 2, kArduinoRequest),
        frame(1500 * ms, TrafficDirection::In, TrafficVerdict::Timeout, 2, {}),
    });
    m_model->appendFrames({
        frame(2000 * ms, TrafficDirection::Out, TrafficVerdict::Sent, 3, kArduinoRequest),
        frame(2003 * ms, TrafficDirection::In, TrafficVerdict::Exception, 3, kException),
        frame(2100 * ms, TrafficDirection::In, TrafficVerdict::Unsolicited, 0, QByteArray::fromHex("0703020001")),
        frame(2200 * ms, TrafficDirection::In, TrafficVerdict::Garbage, 0, QByteArray("\x07\x00hello", 7)),
    });
}

void TestTrafficModel::keys_data()
{
    QTest::addColumn<QString>("link");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("verdict");
    QTest::addColumn<QString>("unit");
    QTest::addColumn<QString>("function");

    QTest::newRow("rtu 01 03 00 79 00 16 15 DD") << kRtuTcp << kRosRaoRequest << int(TrafficVerdict::Sent)
                                                 << QStringLiteral("1") << QStringLiteral("0x03 Read Holding Registers");
    QTest::newRow("mbap 00 01 .. 01 10") << kTcp << kMbapWrite << int(TrafficVerdict::Sent) << QStringLiteral("1")
                                         << QStringLiteral("0x10 Write Multiple Registers");
    QTest::newRow("ascii :070300C800042A") << kAsciiTcp << QByteArray(":070300C800042A\r\n") << int(TrafficVerdict::Sent)
                                           << QStringLiteral("7") << QStringLiteral("0x03 Read Holding Registers");
    QTest::newRow("rtu exception 01 83 02") << kRtuTcp << kException << int(TrafficVerdict::Exception)
                                            << QStringLiteral("1") << QStringLiteral("0x83 Exception to Read Holding Registers");
    QTest::newRow("unnamed link, mbap guessed") << QString() << kMbapWrite << int(TrafficVerdict::Sent)
                                                << QStringLiteral("1") << QStringLiteral("0x10 Write Multiple Registers");
    QTest::newRow("garbage names nothing") << kRtuTcp << QByteArray::fromHex("0103") << int(TrafficVerdict::Garbage)
                                           << QString() << QString();
    QTest::newRow("empty timeout frame") << kRtuTcp << QByteArray() << int(TrafficVerdict::Timeout) << QString() << QString();
    QTest::newRow("delimited link: no unit") << QStringLiteral("tcp://127.0.0.1:4001?framing=delimited&start=24&end=23")
                                             << QByteArray("$01R#") << int(TrafficVerdict::Sent) << QString() << QString();
}

void TestTrafficModel::keys()
{
    QFETCH(QString, link);
    QFETCH(QByteArray, bytes);
    QFETCH(int, verdict);
    QFETCH(QString, unit);
    QFETCH(QString, function);

    if (!link.isEmpty())
        m_model->setLinkName(3, link);
    m_model->appendFrames({frame(5, TrafficDirection::Out, TrafficVerdict(verdict), 0, bytes, link.isEmpty() ? 9 : 3)});
    QCOMPARE(m_model->rowCount(), 1);
    QCOMPARE(cell(*m_model, 0, TrafficModel::UnitColumn), unit);
    QCOMPARE(cell(*m_model, 0, TrafficModel::FunctionColumn), function);
    QCOMPARE(cell(*m_model, 0, TrafficModel::LengthColumn), QString::number(bytes.size()));
    QCOMPARE(cell(*m_model, 0, TrafficModel::LinkColumn), link.isEmpty() ? QStringLiteral("link 9") : link);
    QCOMPARE(m_model->data(m_model->index(0, 0), TrafficModel::BytesRole).toByteArray(), bytes);
}

void TestTrafficModel::pairsAnswersWithRequests()
{
    fillSample();
    QCOMPARE(m_model->rowCount(), 8);
    // Answer 12 ms after its request.
    QCOMPARE(cell(*m_model, 1, TrafficModel::LatencyColumn), QStringLiteral("12.000 ms"));
    QCOMPARE(m_model->data(m_model->index(1, 0), TrafficModel::LatencyNsRole).toLongLong(), 12'000'000);
    QCOMPARE(cell(*m_model, 0, TrafficModel::LatencyColumn), QString()); // requests have none
    QCOMPARE(cell(*m_model, 3, TrafficModel::LatencyColumn), QString()); // a timeout has none
    QCOMPARE(cell(*m_model, 5, TrafficModel::LatencyColumn), QStringLiteral("3.000 ms"));
    QCOMPARE(cell(*m_model, 1, TrafficModel::TimeColumn), QStringLiteral("0.012000"));
    QCOMPARE(cell(*m_model, 3, TrafficModel::VerdictColumn), QStringLiteral("timeout"));

    // Selecting the answer gives its request, and the request its answer.
    FrameExchange e = m_model->exchangeAt(1);
    QCOMPARE(e.selected, TrafficDirection::In);
    QCOMPARE(e.request, kRosRaoRequest);
    QCOMPARE(e.response, kArduinoResponse);
    QCOMPARE(e.framing, Framing::Rtu);
    QCOMPARE(e.latencyNs, 12'000'000);
    QCOMPARE(e.link, kRtuTcp);
    e = m_model->exchangeAt(0);
    QCOMPARE(e.selected, TrafficDirection::Out);
    QCOMPARE(e.response, kArduinoResponse);
    QCOMPARE(e.verdict, TrafficVerdict::Ok);
    // A request that timed out: no answer, the timeout as its verdict.
    e = m_model->exchangeAt(2);
    QCOMPARE(e.request, kArduinoRequest);
    QVERIFY(e.response.isEmpty());
    QCOMPARE(e.verdict, TrafficVerdict::Timeout);
    // Unsolicited and garbage frames answer nothing.
    e = m_model->exchangeAt(6);
    QVERIFY(e.request.isEmpty());
    QCOMPARE(e.verdict, TrafficVerdict::Unsolicited);
    QCOMPARE(m_model->data(m_model->index(6, TrafficModel::VerdictColumn), Qt::ToolTipRole).toString(),
             QStringLiteral("Not an answer to any request sent"));
    QCOMPARE(m_model->data(m_model->index(1, TrafficModel::VerdictColumn), Qt::ToolTipRole).toString(),
             QStringLiteral("Answers frame 1"));
}

// Issue 25, one clock: an analysed capture's transactions carry wall-clock times (nanoseconds
// since the epoch) and the live frames that follow the monotonic clock; the list showed about
// -1.8e9 s for the live frames. The capture of a minute ago and a frame now are a minute apart.
void TestTrafficModel::recordedAndLiveShareOneClock()
{
    m_model->setCurrentLink(QStringLiteral("bench.pcapng"));
    Transaction recorded;
    recorded.id = 1;
    recorded.request = kArduinoRequest;
    recorded.response = kArduinoResponse;
    recorded.status = TransactionStatus::Ok;
    recorded.sentNs = (QDateTime::currentMSecsSinceEpoch() - 60'000) * 1'000'000;
    recorded.firstByteNs = recorded.doneNs = recorded.sentNs + 5'000'000;
    m_model->appendRecordedTransactions({recorded});
    m_model->appendFrames({frame(monotonicNowNs(), TrafficDirection::Out, TrafficVerdict::Sent, 2, kArduinoRequest)});
    QCOMPARE(m_model->rowCount(), 3);
    const auto seconds = [this](int row) { return m_model->index(row, TrafficModel::TimeColumn).data().toString().toDouble(); };
    QCOMPARE(seconds(0), 0.0);
    QCOMPARE(seconds(1), 0.005); // the recorded latency kept
    QVERIFY2(seconds(2) >= 59.0 && seconds(2) <= 70.0, qPrintable(QString::number(seconds(2))));
}

void TestTrafficModel::transactionsFeed()
{
    m_model->setCurrentLink(kRtuTcp);
    Transaction ok;
    ok.id = 7;
    ok.request = kArduinoRequest;
    ok.response = kArduinoResponse;
    ok.status = TransactionStatus::Ok;
    ok.sentNs = 1'000'000;
    ok.firstByteNs = 3'000'000;
    ok.doneNs = 4'250'000;
    Transaction timeout = ok;
    timeout.id = 8;
    timeout.response.clear();
    timeout.status = TransactionStatus::Timeout;
    timeout.sentNs = 10'000'000;
    timeout.firstByteNs = 0;
    timeout.doneNs = 0;
    Transaction late = ok;
    late.id = 8;
    late.status = TransactionStatus::Late;
    late.sentNs = 10'000'000;
    late.firstByteNs = 1'200'000'000;
    late.doneNs = 1'201'000'000;
    QSignalSpy inserted(m_model.get(), &QAbstractItemModel::rowsInserted);
    m_model->appendTransactions({ok, timeout});
    m_model->appendTransactions({late});
    QCOMPARE(inserted.size(), 2); // one insertion per batch
    QCOMPARE(m_model->rowCount(), 5);
    const QStringList directions{QStringLiteral("\u2192 out"), QStringLiteral("\u2190 in"), QStringLiteral("\u2192 out"),
                                 QStringLiteral("\u2190 in"), QStringLiteral("\u2190 in")};
    const QStringList verdicts{QStringLiteral("sent"), QStringLiteral("ok"), QStringLiteral("sent"), QStringLiteral("timeout"),
                               QStringLiteral("late")};
    for (int r = 0; r < 5; ++r) {
        QCOMPARE(cell(*m_model, r, TrafficModel::DirectionColumn), directions.at(r));
        QCOMPARE(cell(*m_model, r, TrafficModel::VerdictColumn), verdicts.at(r));
        QCOMPARE(cell(*m_model, r, TrafficModel::LinkColumn), kRtuTcp);
    }
    // As the engine's traffic log holds them: request written to the answer's first byte.
    QCOMPARE(cell(*m_model, 1, TrafficModel::LatencyColumn), QStringLiteral("2.000 ms"));
    // A timeout's row has no bytes: its unit and function are its request's.
    QCOMPARE(cell(*m_model, 3, TrafficModel::UnitColumn), QStringLiteral("1"));
    QCOMPARE(cell(*m_model, 3, TrafficModel::FunctionColumn), QStringLiteral("0x03 Read Holding Registers"));
    // The late answer belongs to the request listed under its timeout.
    const FrameExchange e = m_model->exchangeAt(4);
    QCOMPARE(e.request, kArduinoRequest);
    QCOMPARE(e.response, kArduinoResponse);
    QCOMPARE(e.verdict, TrafficVerdict::Late);
    QCOMPARE(e.latencyNs, 1'190'000'000);
}

// The frames of a TrafficLog (what the engine logs, unsolicited and garbage included) as they
// come out of TrafficLog::copy, with the log's link names.
void TestTrafficModel::trafficLogFeed()
{
    TrafficLog log;
    const quint16 rtu = log.addLink(kRtuTcp);
    const quint16 tcp = log.addLink(kTcp);
    log.append(100, TrafficDirection::Out, rtu, TrafficVerdict::Sent, 1, kArduinoRequest);
    log.append(2'100, TrafficDirection::In, rtu, TrafficVerdict::Ok, 1, kArduinoResponse);
    log.append(5'000, TrafficDirection::In, rtu, TrafficVerdict::Garbage, 0, QByteArray::fromHex("FFFF00"));
    log.append(6'000, TrafficDirection::Out, tcp, TrafficVerdict::Sent, 2, kMbapWrite);
    log.append(9'000, TrafficDirection::In, tcp, TrafficVerdict::Unsolicited, 0, kMbapWrite);
    for (qsizetype i = 0; i < log.links().size(); ++i)
        m_model->setLinkName(quint16(i), log.links().at(i));
    m_model->appendFrames(log.copy(log.firstSequence(), 3));
    m_model->appendFrames(log.copy(log.firstSequence() + 3, 10));
    QCOMPARE(m_model->rowCount(), 5);
    QCOMPARE(cell(*m_model, 1, TrafficModel::LatencyColumn), QStringLiteral("2.0 µs"));
    QCOMPARE(cell(*m_model, 2, TrafficModel::VerdictColumn), QStringLiteral("garbage"));
    QCOMPARE(cell(*m_model, 2, TrafficModel::UnitColumn), QString());
    QCOMPARE(cell(*m_model, 3, TrafficModel::LinkColumn), kTcp);
    QCOMPARE(cell(*m_model, 4, TrafficModel::VerdictColumn), QStringLiteral("unsolicited"));
    QCOMPARE(cell(*m_model, 4, TrafficModel::FunctionColumn), QStringLiteral("0x10 Write Multiple Registers"));
    QCOMPARE(m_model->exchangeAt(3).framing, Framing::Tcp);
    QCOMPARE(m_model->exchangeAt(0).framing, Framing::Rtu);
    QCOMPARE(m_model->exchangeAt(0).response, kArduinoResponse);
}

void TestTrafficModel::filter_data()
{
    QTest::addColumn<int>("unit");
    QTest::addColumn<int>("function");
    QTest::addColumn<int>("direction");
    QTest::addColumn<QList<int>>("verdicts"); // empty: all
    QTest::addColumn<QList<int>>("rows");     // store rows shown

    QTest::newRow("all") << -1 << -1 << -1 << QList<int>{} << QList<int>{0, 1, 2, 3, 4, 5, 6, 7};
    QTest::newRow("unit 7") << 7 << -1 << -1 << QList<int>{} << QList<int>{6};
    // The timeout (3) is its request's: unit 1, function 03.
    QTest::newRow("function 03 with its exception") << -1 << 3 << -1 << QList<int>{} << QList<int>{0, 1, 2, 3, 4, 5, 6};
    QTest::newRow("in") << -1 << -1 << int(TrafficDirection::In) << QList<int>{} << QList<int>{1, 3, 5, 6, 7};
    QTest::newRow("timeout or exception")
        << -1 << -1 << -1 << QList<int>{int(TrafficVerdict::Timeout), int(TrafficVerdict::Exception)} << QList<int>{3, 5};
    QTest::newRow("unit 1, out") << 1 << -1 << int(TrafficDirection::Out) << QList<int>{} << QList<int>{0, 2, 4};
    QTest::newRow("nothing") << 9 << -1 << -1 << QList<int>{} << QList<int>{};
}

void TestTrafficModel::filter()
{
    QFETCH(int, unit);
    QFETCH(int, function);
    QFETCH(int, direction);
    QFETCH(QList<int>, verdicts);
    QFETCH(QList<int>, rows);

    fillSample();
    TrafficFilter f;
    f.unit = unit;
    f.function = function;
    f.direction = direction;
    if (!verdicts.isEmpty()) {
        f.verdicts = 0;
        for (int v : verdicts)
            f.setVerdict(TrafficVerdict(v), true);
    }
    m_model->setFilter(f);
    QCOMPARE(m_model->rowCount(), rows.size());
    for (int r = 0; r < rows.size(); ++r) {
        QCOMPARE(m_model->storeRow(r), qsizetype(rows.at(r)));
        QCOMPARE(m_model->rowOfStoreRow(rows.at(r)), r);
        // Numbers are the frames' own, whatever is filtered out.
        QCOMPARE(cell(*m_model, r, TrafficModel::NumberColumn), QString::number(rows.at(r) + 1));
    }
    m_model->setFilter({});
    QCOMPARE(m_model->rowCount(), 8);
}

void TestTrafficModel::appendsWhileFiltered()
{
    TrafficFilter f;
    f.direction = int(TrafficDirection::In);
    m_model->setFilter(f);
    QSignalSpy inserted(m_model.get(), &QAbstractItemModel::rowsInserted);
    fillSample();
    QCOMPARE(m_model->rowCount(), 5);
    QCOMPARE(inserted.size(), 2);
    QCOMPARE(inserted.at(0).at(1).toInt(), 0);
    QCOMPARE(inserted.at(0).at(2).toInt(), 1);
    QCOMPARE(inserted.at(1).at(1).toInt(), 2);
    QCOMPARE(inserted.at(1).at(2).toInt(), 4);
    // A batch with nothing shown inserts nothing.
    m_model->appendFrames({frame(1, TrafficDirection::Out, TrafficVerdict::Sent, 9, kRosRaoRequest)});
    QCOMPARE(inserted.size(), 2);
    QCOMPARE(m_model->frameCount(), 9);
}

void TestTrafficModel::pauseHoldsRowsBack()
{
    QSignalSpy counts(m_model.get(), &TrafficModel::countsChanged);
    m_model->setPaused(true);
    fillSample();
    QCOMPARE(m_model->rowCount(), 0);
    QCOMPARE(m_model->heldCount(), 8);
    QVERIFY(counts.size() >= 2);
    QCOMPARE(m_model->findNext(QStringLiteral("timeout"), -1), -1); // held rows are not shown
    m_model->setPaused(false);
    QCOMPARE(m_model->rowCount(), 8);
    QCOMPARE(m_model->heldCount(), 0);
}

void TestTrafficModel::clearEmpties()
{
    fillSample();
    m_model->clear();
    QCOMPARE(m_model->rowCount(), 0);
    QCOMPARE(m_model->frameCount(), 0);
    // The clock starts again at the first frame after a clear.
    m_model->appendFrames({frame(9'000'000'000, TrafficDirection::Out, TrafficVerdict::Sent, 1, kRosRaoRequest)});
    QCOMPARE(cell(*m_model, 0, TrafficModel::TimeColumn), QStringLiteral("0.000000"));
    QCOMPARE(cell(*m_model, 0, TrafficModel::NumberColumn), QStringLiteral("1"));
    QCOMPARE(cell(*m_model, 0, TrafficModel::LinkColumn), kRtuTcp); // link names stay
}

void TestTrafficModel::find_data()
{
    QTest::addColumn<QString>("query");
    QTest::addColumn<int>("from");
    QTest::addColumn<bool>("forward");
    QTest::addColumn<int>("found");

    QTest::newRow("hex 15 DD") << QStringLiteral("15 DD") << -1 << true << 0;
    QTest::newRow("hex 0x44,0x09 from the top") << QStringLiteral("0x44,0x09") << -1 << true << 2;
    QTest::newRow("hex 44 09 after row 2") << QStringLiteral("44 09") << 2 << true << 4;
    QTest::newRow("hex 44 09 wraps") << QStringLiteral("44 09") << 4 << true << 2;
    QTest::newRow("hex backwards") << QStringLiteral("4409") << 4 << false << 2;
    QTest::newRow("verdict word") << QStringLiteral("timeout") << -1 << true << 3;
    QTest::newRow("verdict word, case") << QStringLiteral("EXCEPTION") << -1 << true << 5;
    QTest::newRow("function name") << QStringLiteral("holding") << 1 << true << 2;
    QTest::newRow("text in bytes") << QStringLiteral("hello") << -1 << true << 7;
    QTest::newRow("link") << QStringLiteral("4001") << 0 << true << 1;
    QTest::newRow("nothing") << QStringLiteral("zz top") << -1 << true << -1;
    QTest::newRow("blank") << QStringLiteral("  ") << -1 << true << -1;
}

void TestTrafficModel::find()
{
    QFETCH(QString, query);
    QFETCH(int, from);
    QFETCH(bool, forward);
    QFETCH(int, found);

    fillSample();
    QCOMPARE(m_model->findNext(query, from, forward), found);
}

void TestTrafficModel::rowLimitDropsTheOldest()
{
    m_model->setLinkName(0, kRtuTcp);
    m_model->setRowLimit(100);
    QList<TrafficFrame> batch;
    for (int i = 0; i < 150; ++i)
        batch.append(frame(i, i % 2 ? TrafficDirection::In : TrafficDirection::Out, i % 2 ? TrafficVerdict::Ok : TrafficVerdict::Sent,
                           quint64(i / 2 + 1), i % 2 ? kArduinoResponse : kArduinoRequest));
    m_model->appendFrames(batch);
    // Over the limit, the oldest tenth more than needed goes: 150 - 100 + 10.
    QCOMPARE(m_model->droppedCount(), quint64(60));
    QCOMPARE(m_model->rowCount(), 90);
    QCOMPARE(cell(*m_model, 0, TrafficModel::NumberColumn), QStringLiteral("61"));
    QCOMPARE(m_model->exchangeAt(1).request, kArduinoRequest);
    QCOMPARE(m_model->data(m_model->index(0, 0), TrafficModel::BytesRole).toByteArray(), kArduinoRequest);
    // Filtered, the shown rows follow the drop.
    TrafficFilter f;
    f.direction = int(TrafficDirection::In);
    m_model->setFilter(f);
    QCOMPARE(m_model->rowCount(), 45);
    m_model->appendFrames(batch);
    QCOMPARE(m_model->frameCount(), 90 + 150 - 150);
    QCOMPARE(m_model->rowCount(), 45);
    for (int r = 0; r < m_model->rowCount(); ++r)
        QCOMPARE(m_model->data(m_model->index(r, 0), TrafficModel::BytesRole).toByteArray(), kArduinoResponse);
}

// Text exists only when a cell is asked for: the store holds no QString, so its size is the rows
// and the bytes (48 bytes a row, the frames packed in 1 MiB chunks).
void TestTrafficModel::cellsAreFormattedLazily()
{
    fillSample();
    const std::size_t before = m_model->memoryBytes();
    for (int r = 0; r < m_model->rowCount(); ++r) {
        for (int c = 0; c < TrafficModel::ColumnCount; ++c)
            QVERIFY(m_model->data(m_model->index(r, c)).isValid() || c == TrafficModel::UnitColumn
                    || c == TrafficModel::FunctionColumn || c == TrafficModel::LatencyColumn || c == TrafficModel::BytesColumn);
    }
    QCOMPARE(m_model->memoryBytes(), before);
}

void TestTrafficModel::millionRows()
{
    // The tester would walk every row on each reset; it watches the small cases above.
    m_tester.reset();
    constexpr int kBatches = 1000;
    constexpr int kBatchSize = 1000; // the engine sends up to ~30 batches a second
    m_model->setLinkName(0, kRtuTcp);
    // As in the window: the newest 200,000 frames in memory, the older ones in the archive on
    // disk, all of them listed (filters and finds below read the archive back).
    QTemporaryDir archive;
    m_model->setArchiveFolder(archive.path());
    QSignalSpy inserted(m_model.get(), &QAbstractItemModel::rowsInserted);
    const qint64 rssBefore = residentBytes();
    QElapsedTimer timer;
    qint64 appendNs = 0;
    quint64 id = 0;
    for (int b = 0; b < kBatches; ++b) {
        QList<TrafficFrame> batch;
        batch.reserve(kBatchSize);
        for (int i = 0; i < kBatchSize; i += 2) {
            const qint64 t = (qint64(b) * kBatchSize + i) * 1'000'000;
            ++id;
            const bool timeout = id % 97 == 0;
            QByteArray request = kArduinoRequest;
            request[0] = char(1 + id % 4); // units 1..4
            batch.append(frame(t, TrafficDirection::Out, TrafficVerdict::Sent, id, request));
            batch.append(timeout ? frame(t + 900'000, TrafficDirection::In, TrafficVerdict::Timeout, id, {})
                                 : frame(t + 900'000, TrafficDirection::In, TrafficVerdict::Ok, id, kArduinoResponse));
        }
        timer.start();
        m_model->appendFrames(batch);
        appendNs += timer.nsecsElapsed();
    }
    const qint64 rows = m_model->rowCount();
    QCOMPARE(rows, qint64(kBatches) * kBatchSize);
    QCOMPARE(inserted.size(), kBatches);
    QVERIFY(m_model->archivedCount() >= quint64(kBatches) * kBatchSize - quint64(m_model->rowLimit()));
    const qint64 rssAfter = residentBytes();

    TrafficFilter f;
    f.verdicts = 0;
    f.setVerdict(TrafficVerdict::Timeout, true);
    timer.start();
    m_model->setFilter(f);
    const qint64 filterNs = timer.nsecsElapsed();
    QCOMPARE(m_model->rowCount(), int(id / 97));

    f = {};
    f.unit = 2;
    f.direction = int(TrafficDirection::Out);
    timer.start();
    m_model->setFilter(f);
    const qint64 filterUnitNs = timer.nsecsElapsed();
    QCOMPARE(m_model->rowCount(), int((id + 3) / 4));

    m_model->setFilter({});
    timer.start();
    const int found = m_model->findNext(QStringLiteral("timeout"), rows / 2);
    const qint64 findNs = timer.nsecsElapsed();
    QVERIFY(found > rows / 2);
    timer.start();
    const int notFound = m_model->findNext(QStringLiteral("DE AD BE EF"), 0);
    const qint64 findAllNs = timer.nsecsElapsed();
    QCOMPARE(notFound, -1);
    // Painting asks for the rows in view only: the last screenful's cells.
    timer.start();
    for (int r = int(rows) - 40; r < rows; ++r) {
        for (int c = 0; c < TrafficModel::ColumnCount; ++c)
            (void)m_model->data(m_model->index(r, c));
    }
    const qint64 screenNs = timer.nsecsElapsed();

    qInfo("traffic model, %lld rows in %d batches: append %.1f ms in all (%.2f ms a batch of %d)", rows, kBatches,
          double(appendNs) / 1e6, double(appendNs) / 1e6 / kBatches, kBatchSize);
    qInfo("memory: model %.1f MB = %.1f bytes a row (frames of 8 and 13 bytes); process RSS grew %.1f MB = %.1f bytes a row",
          double(m_model->memoryBytes()) / 1e6, double(m_model->memoryBytes()) / double(rows), double(rssAfter - rssBefore) / 1e6,
          double(rssAfter - rssBefore) / double(rows));
    qInfo("filter: verdict timeout %.1f ms (%d rows), unit 2 out %.1f ms; find next %.3f ms, find none %.1f ms; a screenful of cells %.3f ms",
          double(filterNs) / 1e6, int(id / 97), double(filterUnitNs) / 1e6, double(findNs) / 1e6, double(findAllNs) / 1e6,
          double(screenNs) / 1e6);
}

QTEST_MAIN(TestTrafficModel)
#include "tst_trafficmodel.moc"
