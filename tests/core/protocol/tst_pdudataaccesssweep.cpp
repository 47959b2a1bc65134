#include "pduexpect.h"

#include <QtCore/QRandomGenerator>
#include <QtTest/QtTest>

using namespace mbscope;

// The data-access dissectors must never crash, read outside the PDU or run away on any input
// (MODBUS Application Protocol Specification V1.1b3 codes 01-06, 0F, 10, 14-18). Every prefix of
// every valid PDU, mutations of them, and random bytes after each function code are dissected
// in both directions, with and without a matching request; each tree must stay inside the
// frame, keep parents before children, and carry a message exactly on its flagged fields.
// Build with -fsanitize=address,undefined to turn any stray read into a failure.
class TestPduDataAccessSweep : public QObject
{
    Q_OBJECT
private:
    struct Pair {
        const char *request;
        const char *response;
    };

    // Valid request/response pairs of every code, from the specification's examples and the
    // frames published by mbscope's users.
    static QList<Pair> pairs()
    {
        return {
            {"01 00 13 00 13", "01 03 CD 6B 05"},
            {"02 00 C4 00 16", "02 03 AC DB 35"},
            // RosRao's request with a whole 44-byte answer (the printed one lost two registers).
            {"03 00 79 00 16", "03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 20 1F 40 00 00"
                               " 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00"},
            {"03 00 00 00 04", "03 08 00 45 00 4E 00 01 00 01"},
            {"04 01 2C 00 03", "04 06 03 E8 01 F4 00 0A"},
            {"05 00 AC FF 00", "05 00 AC FF 00"},
            {"06 00 01 00 03", "06 00 01 00 03"},
            {"0F 00 13 00 0A 02 CD 01", "0F 00 13 00 0A"},
            {"0F 00 00 00 01 01 01", "0F 00 00 00 01"},
            {"10 00 01 00 02 04 00 0A 01 02", "10 00 01 00 02"},
            {"10 00 00 00 01 02 00 CD", "10 00 00 00 01"},
            {"14 0E 06 00 04 00 01 00 02 06 00 03 00 09 00 02", "14 0C 05 06 0D FE 00 20 05 06 33 CD 00 40"},
            {"15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D", "15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D"},
            {"16 00 04 00 F2 00 25", "16 00 04 00 F2 00 25"},
            {"17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00 FF", "17 0C 00 FE 0A CD 00 01 00 03 00 0D 00 FF"},
            {"18 04 DE", "18 00 06 00 02 01 B8 12 84"},
        };
    }

    // Dissects and checks the promises that hold for any input; returns what broke, or empty.
    static QString run(FieldTree &tree, const QByteArray &pdu, Direction direction, const QByteArray &request)
    {
        pdutest::dissect(tree, pdu, direction, request);
        QString problem = pdutest::checkBounds(tree);
        if (!problem.isEmpty())
            return problem;
        if (tree.isEmpty() || std::strcmp(tree.at(0).key, "modbus.function_code") != 0)
            return QStringLiteral("no function code field\n") + pdutest::dump(tree);
        // Each byte can carry at most 8 bit fields plus a few headers; more means a runaway loop.
        if (tree.size() > 16 + 9 * pdu.size())
            return QStringLiteral("%1 fields for %2 bytes").arg(tree.size()).arg(pdu.size());
        for (int i = 0; i < tree.size(); ++i) {
            const Field &f = tree.at(i);
            // The one message an Ok field carries: a write's echo confirmed (pduchecks.cpp).
            const bool confirmation = f.severity == Severity::Ok && f.message == QLatin1String("matches the request");
            if ((f.severity == Severity::Ok) != (f.message.isEmpty() || confirmation))
                return QStringLiteral("field %1: severity and message disagree\n").arg(i) + pdutest::dump(tree);
        }
        return {};
    }

    static QString describe(const QByteArray &pdu, Direction direction, const QByteArray &request)
    {
        return QStringLiteral("%1 %2 / req %3")
            .arg(direction == Direction::Request ? QStringLiteral("req") : QStringLiteral("rsp"),
                 QString::fromLatin1(pdu.toHex(' ')), QString::fromLatin1(request.toHex(' ')));
    }

private slots:
    void validPairsAreClean()
    {
        FieldTree tree;
        for (const Pair &p : pairs()) {
            const QByteArray request = pdutest::bytes(p.request);
            const QByteArray response = pdutest::bytes(p.response);
            QVERIFY2(run(tree, request, Direction::Request, {}).isEmpty(), p.request);
            QCOMPARE(tree.worstSeverity(), Severity::Ok);
            QVERIFY2(run(tree, response, Direction::Response, request).isEmpty(), p.response);
            QVERIFY2(tree.worstSeverity() == Severity::Ok, qPrintable(pdutest::dump(tree)));
        }
    }

    void everyPrefix()
    {
        FieldTree tree;
        int runs = 0;
        for (const Pair &p : pairs()) {
            const QByteArray request = pdutest::bytes(p.request);
            const QByteArray response = pdutest::bytes(p.response);
            for (const QByteArray &whole : {request, response}) {
                for (int n = 0; n <= whole.size(); ++n) {
                    const QByteArray pdu = whole.left(n);
                    for (Direction d : {Direction::Request, Direction::Response}) {
                        for (int r = 0; r <= request.size(); ++r) {
                            const QByteArray req = request.left(r);
                            const QString problem = run(tree, pdu, d, req);
                            QVERIFY2(problem.isEmpty(), qPrintable(describe(pdu, d, req) + QLatin1Char('\n') + problem));
                            ++runs;
                        }
                    }
                }
            }
        }
        QVERIFY(runs > 5000);
    }

    void mutations()
    {
        QRandomGenerator random(0x6d6273); // fixed seed: the same inputs on every run
        FieldTree tree;
        for (const Pair &p : pairs()) {
            const QByteArray request = pdutest::bytes(p.request);
            const QByteArray response = pdutest::bytes(p.response);
            for (int i = 0; i < 400; ++i) {
                QByteArray pdu = (i % 2 ? response : request);
                const int flips = 1 + int(random.bounded(3));
                for (int k = 0; k < flips; ++k) {
                    const int at = 1 + int(random.bounded(qMax<qsizetype>(1, pdu.size() - 1)));
                    if (at < pdu.size())
                        pdu[at] = char(random.bounded(256));
                }
                if (random.bounded(4) == 0)
                    pdu.truncate(int(random.bounded(int(pdu.size()) + 1)));
                else if (random.bounded(4) == 0)
                    pdu.append(QByteArray(int(random.bounded(8)), char(random.bounded(256))));
                const Direction d = random.bounded(2) ? Direction::Response : Direction::Request;
                const QByteArray req = random.bounded(3) ? request : QByteArray();
                const QString problem = run(tree, pdu, d, req);
                QVERIFY2(problem.isEmpty(), qPrintable(describe(pdu, d, req) + QLatin1Char('\n') + problem));
            }
        }
    }

    void randomBytesAfterEachCode()
    {
        QRandomGenerator random(0x2a2a);
        FieldTree tree;
        const quint8 codes[] = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x0F, 0x10, 0x14, 0x15, 0x16, 0x17, 0x18};
        for (quint8 code : codes) {
            for (int i = 0; i < 1500; ++i) {
                QByteArray pdu(1, char(code));
                // Short PDUs mostly, where the length rules bite; now and then a long one.
                const int length = random.bounded(10) == 0 ? int(random.bounded(300)) : int(random.bounded(24));
                for (int k = 0; k < length; ++k)
                    pdu.append(char(random.bounded(256)));
                // Small byte counts and lengths reach the deeper paths more often than random ones.
                if (pdu.size() > 1 && random.bounded(2))
                    pdu[1] = char(random.bounded(qMax(1, length)));
                QByteArray req(1, char(code));
                const int requestLength = int(random.bounded(20));
                for (int k = 0; k < requestLength; ++k)
                    req.append(char(random.bounded(8)));
                for (Direction d : {Direction::Request, Direction::Response}) {
                    for (const QByteArray &r : {QByteArray(), req}) {
                        const QString problem = run(tree, pdu, d, r);
                        QVERIFY2(problem.isEmpty(), qPrintable(describe(pdu, d, r) + QLatin1Char('\n') + problem));
                    }
                }
            }
        }
    }

    void pduInsideALargerFrame()
    {
        // The PDU need not start at frame offset 0 (RTU, MBAP): offsets are frame offsets, and
        // nothing past ctx.length is read even when the frame goes on (CRC bytes here).
        const QByteArray frame = pdutest::bytes("01 03 08 00 45 00 4E 00 01 00 01 79 1D");
        for (int length = 0; length <= 10; ++length) {
            FieldTree tree;
            tree.reset(frame);
            pdu::dissect(PduContext{tree, -1, 1, length, Direction::Response, {}});
            for (int i = 0; i < tree.size(); ++i) {
                const Field &f = tree.at(i);
                QVERIFY2(f.offset >= 1 && f.offset + f.length <= 1 + length, qPrintable(pdutest::dump(tree)));
            }
            if (length == 10) {
                QCOMPARE(tree.indexesOf("modbus.register_value").size(), 4);
                QCOMPARE(tree.at(tree.indexOf("modbus.register_value")).offset, 3);
                QCOMPARE(tree.worstSeverity(), Severity::Ok);
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestPduDataAccessSweep)
#include "tst_pdudataaccesssweep.moc"
