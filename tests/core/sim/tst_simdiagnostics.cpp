// SimProcessor's serial line diagnostics: 07, 08 (every sub-function, real counters, listen-only
// mode and restart), 0B, 0C (event log), 11, a busy unit and broadcasts (V1.1b3 6.7-6.10, 6.13).

#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "sim/simprocessor.h"
#include "simfixture.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::simtest;

namespace {

QByteArray ex(int functionCode, int code)
{
    return pduOf(ResponseBuilder::exception(functionCode, code));
}

QByteArray counterRequest(int sub)
{
    return pduOf(RequestBuilder::diagnostics(sub));
}

// The value a counter sub-function (08/0B-08/12) or 08/02 answers.
int ask(SimProcessor &processor, int sub)
{
    const SimReply reply = processor.process(counterRequest(sub));
    if (reply.kind != SimReply::Kind::Normal || reply.pdu.size() != 5)
        return -1;
    return (quint8(reply.pdu[3]) << 8) | quint8(reply.pdu[4]);
}

} // namespace

class TestSimDiagnostics : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void answers_data();
    void answers();
    void counters();
    void commEventCounter();
    void commEventLog();
    void listenOnlyUntilRestart();
    void restartKeepsOrClearsLog_data();
    void restartKeepsOrClearsLog();
    void busy();
    void broadcast();
};

void TestSimDiagnostics::answers_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("expected");
    auto row = [](const QByteArray &request, const QByteArray &expected) {
        QTest::newRow(qPrintable(hexOf(request))) << request << expected;
    };
    // 07 Read Exception Status (6.7)
    row(pduOf(RequestBuilder::readExceptionStatus()), pduOf(ResponseBuilder::readExceptionStatus(0x6D)));
    row(hex("07 00"), ex(0x07, 3));
    // 08 Diagnostics (6.8.1)
    row(hex("08 00 00 12 34 AB CD"), hex("08 00 00 12 34 AB CD"));
    row(hex("08 00 00"), hex("08 00 00"));
    row(hex("08 00 00 12"), ex(0x08, 3));
    row(hex("08 00 01 00 00"), hex("08 00 01 00 00"));
    row(hex("08 00 01 FF 00"), hex("08 00 01 FF 00"));
    row(hex("08 00 01 12 34"), ex(0x08, 3));
    row(hex("08 00 02 00 00"), pduOf(ResponseBuilder::diagnosticsValue(0x02, 0x0F0F)));
    row(hex("08 00 02 00 01"), ex(0x08, 3));
    row(hex("08 00 02"), ex(0x08, 3));
    row(hex("08 00 03 3B 00"), hex("08 00 03 3B 00"));
    row(hex("08 00 03 3B 01"), ex(0x08, 3));
    row(hex("08 00 0A 00 00"), hex("08 00 0A 00 00"));
    row(hex("08 00 0A 00 00 00"), ex(0x08, 3));
    row(hex("08 00 0E 00 00"), pduOf(ResponseBuilder::diagnosticsValue(0x0E, 1))); // this very message
    row(hex("08 00 0B 00 00"), pduOf(ResponseBuilder::diagnosticsValue(0x0B, 0)));
    row(hex("08 00 12 00 00"), pduOf(ResponseBuilder::diagnosticsValue(0x12, 0)));
    row(hex("08 00 14 00 00"), hex("08 00 14 00 00"));
    row(hex("08 00 14 FF 00"), ex(0x08, 3));
    row(hex("08 00 05 00 00"), ex(0x08, 1)); // reserved sub-functions: 01 before the data check
    row(hex("08 00 09 12 34"), ex(0x08, 1));
    row(hex("08 00 13 00 00"), ex(0x08, 1));
    row(hex("08 00 15 00 00"), ex(0x08, 1));
    row(hex("08 FF FF 00 00"), ex(0x08, 1));
    row(hex("08 00"), ex(0x08, 3));
    row(hex("08"), ex(0x08, 3));
    // 0B, 0C with data
    row(hex("0B 00"), ex(0x0B, 3));
    row(hex("0C 00 00"), ex(0x0C, 3));
    // 11 Report Server ID (6.13)
    row(pduOf(RequestBuilder::reportServerId()), pduOf(ResponseBuilder::reportServerId("\x42", true, "sim")));
    row(hex("11 00"), ex(0x11, 3));
}

void TestSimDiagnostics::answers()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, expected);
    auto unit = makeUnit();
    unit->setDiagnosticRegister(0x0F0F);
    SimProcessor processor(unit.get());
    const SimReply reply = processor.process(request);
    QCOMPARE(hexOf(reply.pdu), hexOf(expected));
    QString why;
    QVERIFY2(dissectsCleanly(request, reply.pdu, &why), qPrintable(why));
    if (request == hex("08 00 03 3B 00"))
        QCOMPARE(unit->asciiDelimiter(), ';');
}

void TestSimDiagnostics::counters()
{
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    // What the endpoint reports: 5 frames seen on the bus, 2 CRC errors, 1 overrun.
    for (int i = 0; i < 5; ++i)
        SimProcessor::noteBusMessage(*unit);
    SimProcessor::noteCommError(*unit);
    SimProcessor::noteCommError(*unit);
    SimProcessor::noteOverrun(*unit);
    // Requests: 2 exceptions (one of them 06 busy), a broadcast.
    processor.process(hex("03 00 00 00 7E"));
    unit->setBusy(true);
    processor.process(hex("03 00 00 00 01"));
    unit->setBusy(false);
    processor.process(hex("06 00 01 00 05"), true);
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 1), std::optional<quint16>(5));

    QCOMPARE(ask(processor, 0x0B), 5); // bus messages
    QCOMPARE(ask(processor, 0x0C), 2); // bus communication errors
    QCOMPARE(ask(processor, 0x0D), 2); // exceptions returned
    QCOMPARE(ask(processor, 0x0E), 7); // server messages: 3 + the 4 questions so far
    QCOMPARE(ask(processor, 0x0F), 1); // no response: the broadcast
    QCOMPARE(ask(processor, 0x10), 0); // NAK
    QCOMPARE(ask(processor, 0x11), 1); // busy
    QCOMPARE(ask(processor, 0x12), 1); // overrun
    QCOMPARE(processor.process(hex("08 00 14 00 00")).kind, SimReply::Kind::Normal);
    QCOMPARE(ask(processor, 0x12), 0);
    QCOMPARE(ask(processor, 0x0C), 2);
    // 0A clears every counter and the diagnostic register.
    unit->setDiagnosticRegister(0x8001);
    QCOMPARE(processor.process(hex("08 00 0A 00 00")).kind, SimReply::Kind::Normal);
    QCOMPARE(ask(processor, 0x02), 0);
    QCOMPARE(ask(processor, 0x0C), 0);
    QCOMPARE(ask(processor, 0x0D), 0);
    QCOMPARE(ask(processor, 0x0E), 4); // the four questions since
}

void TestSimDiagnostics::commEventCounter()
{
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    QCOMPARE(hexOf(processor.process(hex("0B")).pdu), hexOf(pduOf(ResponseBuilder::getCommEventCounter(false, 0))));
    processor.process(hex("03 00 00 00 01"));     // counted
    processor.process(hex("03 00 00 00 7E"));     // exception: not counted
    processor.process(hex("06 00 01 00 01"), true); // broadcast: not answered, not counted
    processor.process(hex("08 00 00 AA 55"));     // counted
    processor.process(hex("0C"));                 // fetch: not counted
    QCOMPARE(hexOf(processor.process(hex("0B")).pdu), hexOf(pduOf(ResponseBuilder::getCommEventCounter(false, 2))));
}

void TestSimDiagnostics::commEventLog()
{
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    for (int i = 0; i < 3; ++i)
        SimProcessor::noteBusMessage(*unit);
    processor.process(hex("03 00 00 00 01"));    // receive 80, send 40
    processor.process(hex("03 00 00 00 7E"));    // receive 80, send 41 (read exception)
    const SimReply reply = processor.process(hex("0C")); // receive 80, logged before the answer
    // V1.1b3 6.10: status, event count, message count, events newest first.
    const QByteArray events = hex("80 41 80 40 80");
    QCOMPARE(hexOf(reply.pdu), hexOf(pduOf(ResponseBuilder::getCommEventLog(false, 1, 3, events))));
    // The log keeps 64 events.
    for (int i = 0; i < 40; ++i)
        processor.process(hex("03 00 00 00 01"));
    QCOMPARE(unit->eventLog().size(), 64);
    const SimReply full = processor.process(hex("0C"));
    QCOMPARE(full.pdu.size(), 2 + 6 + 64);
    QCOMPARE(quint8(full.pdu[1]), quint8(70));
    // Comm errors and overruns are logged as receive events with their bits.
    SimProcessor::noteCommError(*unit);
    QCOMPARE(unit->eventLog().first(), quint8(0x82));
    SimProcessor::noteOverrun(*unit);
    QCOMPARE(unit->eventLog().first(), quint8(0x90));
}

void TestSimDiagnostics::listenOnlyUntilRestart()
{
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    SimReply reply = processor.process(hex("08 00 04 00 00"));
    QCOMPARE(reply.kind, SimReply::Kind::Silent); // 6.8.1: no response to 04
    QVERIFY(!reply.hasAnswer());
    QVERIFY(unit->isListenOnly());
    QCOMPARE(unit->eventLog().at(1), quint8(0x04)); // entered listen-only (after it, the send event)
    // Nothing is processed, not even writes or diagnostics.
    reply = processor.process(hex("06 00 01 00 09"));
    QCOMPARE(reply.kind, SimReply::Kind::ListenOnly);
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 1), std::optional<quint16>(10));
    QCOMPARE(processor.process(hex("08 00 0A 00 00")).kind, SimReply::Kind::ListenOnly);
    QCOMPARE(processor.process(hex("08 00 01 12 34")).kind, SimReply::Kind::Silent); // bad data: still silent
    QVERIFY(unit->isListenOnly());
    QCOMPARE(unit->eventLog().first(), quint8(0x60)); // send event, listen-only bit
    // 08/01 brings it back, without an answer since it was in listen-only mode.
    reply = processor.process(hex("08 00 01 00 00"));
    QCOMPARE(reply.kind, SimReply::Kind::Silent);
    QVERIFY(!unit->isListenOnly());
    QCOMPARE(unit->eventLog().first(), quint8(0x00)); // communication restart
    QCOMPARE(unit->counters().serverMessages, quint16(0)); // counters cleared by the restart
    QCOMPARE(processor.process(hex("03 00 01 00 01")).kind, SimReply::Kind::Normal);
}

void TestSimDiagnostics::restartKeepsOrClearsLog_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<int>("logSize");
    QTest::newRow("08 00 01 00 00") << hex("08 00 01 00 00") << 7; // 2 x 2 before, 2 for it, restart
    QTest::newRow("08 00 01 FF 00") << hex("08 00 01 FF 00") << 1; // the restart event alone
}

void TestSimDiagnostics::restartKeepsOrClearsLog()
{
    QFETCH(QByteArray, request);
    QFETCH(int, logSize);
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    processor.process(hex("03 00 00 00 01"));
    processor.process(hex("03 00 00 00 01"));
    const SimReply reply = processor.process(request);
    QCOMPARE(hexOf(reply.pdu), hexOf(request)); // not in listen-only mode: the echo
    QCOMPARE(unit->eventLog().size(), logSize);
    QCOMPARE(unit->eventLog().first(), quint8(0x00));
    QCOMPARE(unit->counters().commEventCounter, quint16(0)); // cleared after the answer
}

void TestSimDiagnostics::busy()
{
    auto unit = makeUnit();
    unit->setBusy(true);
    SimProcessor processor(unit.get());
    QCOMPARE(hexOf(processor.process(hex("03 00 00 00 01")).pdu), hexOf(ex(0x03, 6)));
    QCOMPARE(hexOf(processor.process(hex("0B")).pdu), hexOf(pduOf(ResponseBuilder::getCommEventCounter(true, 0))));
    QCOMPARE(ask(processor, 0x11), 1);
    QCOMPARE(unit->eventLog().at(4), quint8(0x44)); // the 03's send event: busy exception
}

void TestSimDiagnostics::broadcast()
{
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    SimReply reply = processor.process(hex("10 00 00 00 02 04 00 07 00 08"), true);
    QCOMPARE(reply.kind, SimReply::Kind::Silent);
    QVERIFY(!reply.hasAnswer());
    QCOMPARE(unit->values(SimTable::HoldingRegisters, 0, 2), (QList<quint16>{7, 8}));
    QCOMPARE(unit->eventLog().at(1), quint8(0xC0)); // receive event with the broadcast bit
    // A broadcast that fails is not answered either (and not counted as an exception returned).
    reply = processor.process(hex("06 00 28 00 01"), true);
    QCOMPARE(reply.kind, SimReply::Kind::Silent);
    QVERIFY(reply.note.contains(QStringLiteral("exception 0x02")));
    QCOMPARE(unit->counters().exceptionErrors, quint16(0));
    QCOMPARE(unit->counters().serverNoResponse, quint16(2));
}

QTEST_GUILESS_MAIN(TestSimDiagnostics)
#include "tst_simdiagnostics.moc"
