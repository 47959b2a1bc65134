// ConformanceJudge's words for what came back: a late answer (the request's own answer, read just
// after its timeout) is said to be late, never "bytes that answer nothing it asked" (before session
// 15 a libmodbus exception 03 sent after its 500 ms sleep was called that); bytes that match no
// request still are.

#include "conformance/conformancejudge.h"
#include "conformance/conformancelink.h"

#include <QtTest/QtTest>

using namespace mbscope;

class TestConformanceJudge : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void seenSaysWhatCame_data()
    {
        QTest::addColumn<bool>("late");
        QTest::addColumn<QString>("says");
        QTest::addColumn<QString>("never");
        QTest::newRow("late answer") << true << "00 25 00 00 00 03 01 83 03 only after the 500 ms timeout (a late answer"
                                     << "answer nothing";
        QTest::newRow("foreign bytes") << false << "00 25 00 00 00 03 01 83 03 (bytes that answer nothing it asked)" << "late";
    }
    void seenSaysWhatCame()
    {
        QFETCH(bool, late);
        QFETCH(QString, says);
        QFETCH(QString, never);
        ConformanceExchange e;
        e.request = QByteArray::fromHex("002500000006010300000000");
        e.answer = QByteArray::fromHex("002500000003018303");
        e.transaction.status = TransactionStatus::Timeout;
        e.timeoutMs = 500;
        e.late = late;
        const QString seen = ConformanceJudge::seen(e);
        QVERIFY2(seen.contains(says), qPrintable(seen));
        QVERIFY2(!seen.contains(never), qPrintable(seen));
    }
};

QTEST_MAIN(TestConformanceJudge)
#include "tst_conformancejudge.moc"
