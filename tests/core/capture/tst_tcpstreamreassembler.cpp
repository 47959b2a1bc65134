// TcpStreamReassembler: segments as a capture shows them (in order, early, retransmitted,
// overlapping, lost, across the 2^32 wrap) give the byte stream the receiver read, with the
// holes the capture never filled reported as gaps: at once when the peer acknowledges the bytes
// the capture lost, else when too much waits or at the end.
#include "capture/tcpstreamreassembler.h"

#include <QtTest/QTest>

using namespace mbscope;

namespace {

struct Segment {
    quint32 sequence;
    quint8 flags;
    QByteArray payload;
    qint64 ack = -1; // >= 0: instead of a segment, the peer acknowledges this sequence number
};

constexpr quint8 kSyn = 0x02;
constexpr quint8 kFin = 0x01;

// Delivered bytes, each lost byte shown as '~' and the start of a stream joined mid-way as '^'.
void append(QByteArray &got, qint64 gap, QByteArrayView bytes)
{
    if (gap == TcpStreamReassembler::kJoinedMidStream)
        got.append('^');
    else
        got.append(QByteArray(gap, '~'));
    got.append(bytes.toByteArray());
}

void play(TcpStreamReassembler &reassembler, const QList<Segment> &segments)
{
    for (const Segment &s : segments) {
        if (s.ack >= 0)
            reassembler.acknowledged(quint32(s.ack));
        else
            reassembler.add(s.sequence, s.flags, s.payload);
    }
}

} // namespace

Q_DECLARE_METATYPE(QList<Segment>)

class TestTcpStreamReassembler : public QObject
{
    Q_OBJECT

private slots:
    void reassemble_data();
    void reassemble();
    void acknowledged_data();
    void acknowledged();
};

void TestTcpStreamReassembler::reassemble_data()
{
    QTest::addColumn<QList<Segment>>("segments");
    QTest::addColumn<qsizetype>("maxBuffered");
    QTest::addColumn<QByteArray>("stream");    // delivered bytes, each gap shown as '~' per lost byte
    QTest::addColumn<qint64>("retransmitted");
    QTest::addColumn<qint64>("lost");

    const quint8 syn = kSyn;
    QTest::newRow("in order after a SYN")
        << QList<Segment>{{1000, syn, {}}, {1001, 0, "abc"}, {1004, 0, "def"}} << qsizetype(1024) << QByteArray("abcdef") << 0LL << 0LL;
    QTest::newRow("no SYN: the first segment starts the stream, joined mid-way")
        << QList<Segment>{{5000, 0, "abc"}, {5003, 0, "de"}} << qsizetype(1024) << QByteArray("^abcde") << 0LL << 0LL;
    QTest::newRow("early segment waits for the hole")
        << QList<Segment>{{1, syn, {}}, {2, 0, "ab"}, {6, 0, "ef"}, {4, 0, "cd"}} << qsizetype(1024) << QByteArray("abcdef") << 0LL << 0LL;
    QTest::newRow("whole retransmission dropped")
        << QList<Segment>{{1, syn, {}}, {2, 0, "ab"}, {2, 0, "ab"}, {4, 0, "cd"}} << qsizetype(1024) << QByteArray("abcd") << 2LL << 0LL;
    QTest::newRow("overlap trimmed")
        << QList<Segment>{{1, syn, {}}, {2, 0, "abc"}, {3, 0, "bcdef"}} << qsizetype(1024) << QByteArray("abcdef") << 2LL << 0LL;
    QTest::newRow("early overlapping segments")
        << QList<Segment>{{1, syn, {}}, {2, 0, "a"}, {5, 0, "defg"}, {4, 0, "cde"}, {3, 0, "b"}} << qsizetype(1024)
        << QByteArray("abcdefg") << 2LL << 0LL;
    QTest::newRow("lost segment given up at finish")
        << QList<Segment>{{1, syn, {}}, {2, 0, "ab"}, {6, 0, "ef"}} << qsizetype(1024) << QByteArray("ab~~ef") << 0LL << 2LL;
    QTest::newRow("lost segment given up when too much waits")
        << QList<Segment>{{1, syn, {}}, {2, 0, "ab"}, {6, 0, "efgh"}, {10, 0, "ijkl"}} << qsizetype(6) << QByteArray("ab~~efghijkl") << 0LL << 2LL;
    QTest::newRow("sequence numbers wrap")
        << QList<Segment>{{0xfffffffd, syn, {}}, {0xfffffffe, 0, "ab"}, {0, 0, "cd"}, {2, 0, "ef"}} << qsizetype(1024) << QByteArray("abcdef")
        << 0LL << 0LL;
}

void TestTcpStreamReassembler::reassemble()
{
    QFETCH(QList<Segment>, segments);
    QFETCH(qsizetype, maxBuffered);
    QFETCH(QByteArray, stream);
    QFETCH(qint64, retransmitted);
    QFETCH(qint64, lost);
    QByteArray got;
    TcpStreamReassembler reassembler([&got](qint64 gap, QByteArrayView bytes) { append(got, gap, bytes); }, maxBuffered);
    play(reassembler, segments);
    reassembler.finish();
    QCOMPARE(got, stream);
    QCOMPARE(reassembler.retransmittedBytes(), retransmitted);
    QCOMPARE(reassembler.lostBytes(), lost);
    QCOMPARE(reassembler.delivered(), qint64(stream.size() - stream.count('^')));
    QCOMPARE(reassembler.bufferedBytes(), qsizetype(0));
}

// What is delivered before finish(): a hole the peer acknowledged does not wait for the end.
void TestTcpStreamReassembler::acknowledged_data()
{
    QTest::addColumn<QList<Segment>>("segments");
    QTest::addColumn<QByteArray>("beforeFinish");
    QTest::addColumn<qint64>("gaps");

    QTest::newRow("lost segment before an early one, then acknowledged")
        << QList<Segment>{{1, kSyn, {}}, {2, 0, "ab"}, {6, 0, "ef"}, {0, 0, {}, 8}} << QByteArray("ab~~ef") << 1LL;
    QTest::newRow("lost last segment, acknowledged before anything follows")
        << QList<Segment>{{1, kSyn, {}}, {2, 0, "ab"}, {0, 0, {}, 6}, {6, 0, "ef"}} << QByteArray("ab~~ef") << 1LL;
    QTest::newRow("acknowledged up to the middle of an early segment")
        << QList<Segment>{{1, kSyn, {}}, {2, 0, "ab"}, {6, 0, "efgh"}, {0, 0, {}, 7}} << QByteArray("ab~~efgh") << 1LL;
    QTest::newRow("two holes, one acknowledgement")
        << QList<Segment>{{1, kSyn, {}}, {2, 0, "a"}, {4, 0, "c"}, {6, 0, "e"}, {0, 0, {}, 7}} << QByteArray("a~c~e") << 2LL;
    QTest::newRow("acknowledging what was delivered changes nothing")
        << QList<Segment>{{1, kSyn, {}}, {2, 0, "ab"}, {0, 0, {}, 4}, {0, 0, {}, 2}, {4, 0, "cd"}} << QByteArray("abcd") << 0LL;
    QTest::newRow("the FIN's acknowledgement is no lost byte")
        << QList<Segment>{{1, kSyn, {}}, {2, kFin, "ab"}, {0, 0, {}, 5}} << QByteArray("ab") << 0LL;
    QTest::newRow("acknowledgements before the stream began are ignored")
        << QList<Segment>{{0, 0, {}, 900}, {1000, 0, "ab"}, {1002, 0, "cd"}} << QByteArray("^abcd") << 0LL;
    QTest::newRow("a hole still waits without an acknowledgement")
        << QList<Segment>{{1, kSyn, {}}, {2, 0, "ab"}, {6, 0, "ef"}, {0, 0, {}, 4}} << QByteArray("ab") << 0LL;
    QTest::newRow("acknowledged across the 2^32 wrap")
        << QList<Segment>{{0xfffffffd, kSyn, {}}, {0xfffffffe, 0, "a"}, {1, 0, "d"}, {0, 0, {}, 2}} << QByteArray("a~~d") << 1LL;
}

void TestTcpStreamReassembler::acknowledged()
{
    QFETCH(QList<Segment>, segments);
    QFETCH(QByteArray, beforeFinish);
    QFETCH(qint64, gaps);
    QByteArray got;
    TcpStreamReassembler reassembler([&got](qint64 gap, QByteArrayView bytes) { append(got, gap, bytes); });
    play(reassembler, segments);
    QCOMPARE(got, beforeFinish);
    QCOMPARE(reassembler.gaps(), gaps);
}

QTEST_GUILESS_MAIN(TestTcpStreamReassembler)
#include "tst_tcpstreamreassembler.moc"
