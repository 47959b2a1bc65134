// No allocation on valid 07, 08, 0B, 0C, 11 and 2B frames once the field tree is warmed up
// (issue 2: no per-field heap allocation on the hot path), counted by allocationcounter.h.
#include "allocationcounter.h"
#include "diagtestsupport.h"

using namespace diagtest;

// Valid frames of 07, 08, 0B, 0C, 11 and 2B in both directions, with their request; the only
// flag they may carry is a literal note (static data).
class TestPduDiagAlloc : public QObject
{
    Q_OBJECT
private slots:
    void validFramesAllocateNothing_data()
    {
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<int>("direction");
        QTest::addColumn<QByteArray>("request");
        const struct {
            const char *pdu;
            Direction direction;
            const char *request;
        } rows[] = {
            {"07", Direction::Request, ""},
            {"07 6D", Direction::Response, "07"},
            {"08 00 00 A5 37", Direction::Request, ""},
            {"08 00 00 A5 37", Direction::Response, "08 00 00 A5 37"},
            {"08 00 01 FF 00", Direction::Response, "08 00 01 FF 00"},
            {"08 00 02 01 23", Direction::Response, "08 00 02 00 00"},
            {"08 00 03 0D 00", Direction::Response, "08 00 03 0D 00"},
            {"08 00 0B 00 00", Direction::Request, ""},
            {"08 00 0E 01 2C", Direction::Response, "08 00 0E 00 00"},
            {"08 00 14 00 00", Direction::Response, "08 00 14 00 00"},
            {"0B", Direction::Request, ""},
            {"0B 00 00 01 08", Direction::Response, "0B"},
            {"0C 0B 00 00 01 08 01 21 C2 41 04 00 52", Direction::Response, "0C"},
            {"11 05 2A FF 4C 4D 42", Direction::Response, "11"},
            {"2B 0E 01 00", Direction::Request, ""},
            {"2B 0E 01 01 00 00 03 00 07 43 6F 6D 70 61 6E 79 01 04 50 43 2D 31 02 05 56 32 2E 31 31",
             Direction::Response, "2B 0E 01 00"},
            {"2B 0E 04 81 00 00 01 05 04 4D 2D 31 30", Direction::Response, "2B 0E 04 05"},
            {"83 02", Direction::Response, "03 00 00 00 01"},
        };
        for (const auto &r : rows) {
            const QByteArray tag = QByteArray(r.pdu) + (r.direction == Direction::Response ? " response" : " request");
            QTest::newRow(tag.constData()) << hex(r.pdu) << int(r.direction) << hex(r.request);
        }
    }
    void validFramesAllocateNothing()
    {
        QFETCH(QByteArray, pdu);
        QFETCH(int, direction);
        QFETCH(QByteArray, request);
        if (!allocationcounter::available)
            QSKIP("allocations are not counted under a sanitizer or without glibc");
        FieldTree tree;
        dissect(tree, pdu, Direction(direction), request); // warm up: the field vector grows once
        QVERIFY(tree.worstSeverity() <= Severity::Info);
        allocationcounter::start();
        for (int i = 0; i < 10; ++i)
            dissect(tree, pdu, Direction(direction), request);
        QCOMPARE(allocationcounter::stop(), 0L);
    }

    // The counter itself works: a flagged frame builds its message on the heap.
    void flaggedFramesDoAllocate()
    {
        if (!allocationcounter::available)
            QSKIP("allocations are not counted under a sanitizer or without glibc");
        FieldTree tree;
        const QByteArray pdu = hex("08 00 01 12 34");
        dissect(tree, pdu, Direction::Request);
        allocationcounter::start();
        dissect(tree, pdu, Direction::Request);
        QVERIFY(allocationcounter::stop() > 0);
    }
};

QTEST_GUILESS_MAIN(TestPduDiagAlloc)
#include "tst_pdudiagalloc.moc"
