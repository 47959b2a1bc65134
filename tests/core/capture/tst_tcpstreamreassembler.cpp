// TcpStreamReassembler: segments as a capture shows them (in order, early, retransmitted,
// overlapping, lost, across the 2^32 wrap) give the byte stream the receiver read, with the
// holes the capture never filled reported as gaps.
#include "capture/tcpstreamreassembler.h"

#include <QtTest/QTest>

using namespace mbscope;

namespace {

struct Segment {
    quint32 sequence;
    quint8 flags;
    QByteArray payload;
};

} // namespace

Q_DECLARE_METATYPE(QList<Segment>)

class TestTcpStreamReassembler : public QObject
{
    Q_OBJECT

private slots:
    void reassemble_data();
    void reassemble();
};

void TestTcpStreamReassembler::reassemble_data()
{
    QTest::addColumn<QList<Segment>>("segments");
    QTest::addColumn<qsizetype>("maxBuffered");
    QTest::addColumn<QByteArray>("stream");    // delivered bytes, each gap shown as '~' per lost byte
    QTest::addColumn<qint64>("retransmitted");
    QTest::addColumn<qint64>("lost");

    const quint8 syn = 0x02;
    QTest::newRow("in order after a SYN")
        << QList<Segment>{{1000, syn, {}}, {1001, 0, "abc"}, {1004, 0, "def"}} << qsizetype(1024) << QByteArray("abcdef") << 0LL << 0LL;
    QTest::newRow("no SYN: the first segment starts the stream")
        << QList<Segment>{{5000, 0, "abc"}, {5003, 0, "de"}} << qsizetype(1024) << QByteArray("abcde") << 0LL << 0LL;
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
    TcpStreamReassembler reassembler(
        [&got](qint64 gap, QByteArrayView bytes) {
            got.append(QByteArray(gap, '~'));
            got.append(bytes.toByteArray());
        },
        maxBuffered);
    for (const Segment &s : segments)
        reassembler.add(s.sequence, s.flags, s.payload);
    reassembler.finish();
    QCOMPARE(got, stream);
    QCOMPARE(reassembler.retransmittedBytes(), retransmitted);
    QCOMPARE(reassembler.lostBytes(), lost);
    QCOMPARE(reassembler.delivered(), qint64(stream.size()));
    QCOMPARE(reassembler.bufferedBytes(), qsizetype(0));
}

QTEST_GUILESS_MAIN(TestTcpStreamReassembler)
#include "tst_tcpstreamreassembler.moc"
