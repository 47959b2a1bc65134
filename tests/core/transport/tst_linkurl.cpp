#include "transport/linkurl.h"

#include <QtTest/QtTest>

using namespace mbscope;

// Target URLs (issue 3, "Links"): every scheme, its options, canonical text, and the errors that
// name the part at fault. Default ports: 502 (Messaging on TCP/IP V1.0b, 4.1), 802 (MODBUS/TCP
// Security, 5.1).
class TestLinkUrl : public QObject
{
    Q_OBJECT
private:
    static LinkUrl parsed(const QString &text)
    {
        const auto result = LinkUrl::parse(text);
        if (!result.url)
            qWarning().noquote() << result.error;
        return result.url.value_or(LinkUrl{});
    }

private slots:
    // Each URL parses and prints back in canonical form.
    void canonical_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("canonical");
        auto row = [](const char *text, const char *canonical) {
            QTest::newRow(text) << QString::fromUtf8(text) << QString::fromUtf8(canonical);
        };
        row("tcp://192.168.1.10:502", "tcp://192.168.1.10:502");
        row("tcp://192.168.1.10", "tcp://192.168.1.10:502");
        row("TCP://plc.local:1502", "tcp://plc.local:1502");
        row("tcp://[::1]:502", "tcp://[::1]:502");
        row("tcp://[::1]", "tcp://[::1]:502");
        row("tcp://[fe80::1:2]:5020/", "tcp://[fe80::1:2]:5020");
        row("  tcp://host:502  ", "tcp://host:502");
        row("rtu-tcp://192.168.127.254:4001", "rtu-tcp://192.168.127.254:4001");
        row("ascii-tcp://gw:4002", "ascii-tcp://gw:4002");
        row("udp://10.0.0.2", "udp://10.0.0.2:502");
        row("udp://10.0.0.2:1502", "udp://10.0.0.2:1502");
        row("rtu-udp://10.0.0.2:4001", "rtu-udp://10.0.0.2:4001");
        row("tls://plc", "tls://plc:802");
        row("tls://plc:802?cert=/etc/mb/client.pem&key=/etc/mb/client.key&ca=/etc/mb/ca.pem",
            "tls://plc:802?cert=/etc/mb/client.pem&key=/etc/mb/client.key&ca=/etc/mb/ca.pem");
        row("tls://plc?ca=/etc/mb/ca.pem&key=k.pem&cert=c.pem", "tls://plc:802?cert=c.pem&key=k.pem&ca=/etc/mb/ca.pem");
        row("tls://plc?cert=/my%20certs/c.pem&key=k%26.pem", "tls://plc:802?cert=/my%20certs/c.pem&key=k%26.pem");
        row("rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1");
        row("rtu:///dev/ttyUSB0", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1");
        row("rtu:///dev/ttyUSB0?baud=19200&parity=none&stop=2", "rtu:///dev/ttyUSB0?baud=19200&parity=N&data=8&stop=2");
        row("rtu:///dev/ttyS1?parity=odd", "rtu:///dev/ttyS1?baud=9600&parity=O&data=8&stop=1");
        row("rtu://COM3?baud=115200", "rtu://COM3?baud=115200&parity=E&data=8&stop=1");
        row("rtu:///dev/serial/by-id/usb-FTDI_FT232R-if00-port0",
            "rtu:///dev/serial/by-id/usb-FTDI_FT232R-if00-port0?baud=9600&parity=E&data=8&stop=1");
        row("rtu:///dev/ttyUSB0?turnaround=10ms", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&turnaround=10ms");
        row("rtu:///dev/ttyUSB0?turnaround=10", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&turnaround=10ms");
        row("rtu:///dev/ttyUSB0?turnaround_us=1500", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&turnaround=1500us");
        row("rtu:///dev/ttyUSB0?turnaround=2s", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&turnaround=2000ms");
        row("rtu:///dev/ttyUSB0?turnaround=0", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1");
        // The one duration grammar (time/duration.h): decimals and minutes, as on the command line.
        row("rtu:///dev/ttyUSB0?turnaround=1.5ms", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&turnaround=1500us");
        row("tcp://h?timeout=1.5s", "tcp://h:502?timeout=1500ms");
        row("tcp://h?connect_timeout=1min", "tcp://h:502?connect_timeout=60000ms");
        // Serial Line V1.02, 2.5.2: ASCII characters carry 7 data bits unless told otherwise.
        row("ascii:///dev/ttyUSB1", "ascii:///dev/ttyUSB1?baud=9600&parity=E&data=7&stop=1");
        row("ascii:///dev/ttyUSB1?data=8&parity=N&stop=2", "ascii:///dev/ttyUSB1?baud=9600&parity=N&data=8&stop=2");
        row("tcp://h:502?timeout=1000ms", "tcp://h:502?timeout=1000ms");
        row("tcp://h:502?timeout=2s&connect_timeout=500", "tcp://h:502?connect_timeout=500ms&timeout=2000ms");
        row("tcp://h:502?connect_timeout=3000ms", "tcp://h:502");
        row("rtu:///dev/ttyUSB0?timeout=300ms", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&timeout=300ms");
        // Delimited framing; bytes in hex: 24 '$', 23 '#', 05 ENQ, 04 EOT.
        row("rtu:///dev/ttyUSB0?baud=9600&parity=N&framing=delimited&start=24&end=23",
            "rtu:///dev/ttyUSB0?baud=9600&parity=N&data=8&stop=1&framing=delimited&start=24&end=23");
        row("tcp://h:502?framing=delimited&end=0x0d", "tcp://h:502?framing=delimited&end=0D");
        row("tcp://h:502?framing=delimited", "tcp://h:502?framing=delimited&end=0A");
        row("rtu-tcp://h:4001?framing=delimited&start=05&end=04&checksum=sum",
            "rtu-tcp://h:4001?framing=delimited&start=05&end=04&checksum=sum");
        row("rtu-tcp://h:4001?framing=delimited&start=05&end=04&checksum=BCC&display=hex",
            "rtu-tcp://h:4001?framing=delimited&start=05&end=04&checksum=sum&display=hex");
        row("ascii-tcp://h:9?framing=delimited&end=3&checksum=xor&display=text",
            "ascii-tcp://h:9?framing=delimited&end=03&checksum=xor");
        // Delimited frames need not be 8-bit RTU characters.
        row("rtu:///dev/ttyS0?data=7&framing=delimited&start=24&end=23",
            "rtu:///dev/ttyS0?baud=9600&parity=E&data=7&stop=1&framing=delimited&start=24&end=23");
        row("tcp://h?&timeout=5ms&", "tcp://h:502?timeout=5ms");
        // Reverse connections (issue 27): listen, and use the connection the device opens.
        row("tcp://0.0.0.0:5020?mode=listen", "tcp://0.0.0.0:5020?mode=listen");
        row("rtu-tcp://127.0.0.1:4001?MODE=Listen&busy=queue", "rtu-tcp://127.0.0.1:4001?mode=listen&busy=queue");
        row("tcp://[::]:5020?mode=listen&busy=replace", "tcp://[::]:5020?mode=listen");
        row("tcp://h:502?mode=connect", "tcp://h:502");
        row("ascii-tcp://127.0.0.1:9?busy=refuse&mode=listen&connect_timeout=60s",
            "ascii-tcp://127.0.0.1:9?connect_timeout=60000ms&mode=listen&busy=refuse");
        row("tls://0.0.0.0?mode=listen&cert=s.pem&key=s.key&ca=ca.pem", "tls://0.0.0.0:802?cert=s.pem&key=s.key&ca=ca.pem&mode=listen");
        row("rtu-tcp://10.0.0.5:4001?mode=listen&framing=delimited&end=0D",
            "rtu-tcp://10.0.0.5:4001?mode=listen&framing=delimited&end=0D");
        // RS-485 direction control (issue 27): RTS level while sending, delays, the driver's mode.
        row("rtu:///dev/ttyUSB0?rts=up", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&rts=up");
        row("rtu:///dev/ttyUSB0?RTS=Down", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&rts=down");
        row("rtu:///dev/ttyUSB0?rts=up&rts_before=500us&rts_after=2",
            "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&rts=up&rts_before=500us&rts_after=2ms");
        row("rtu:///dev/ttyUSB0?rts_after=1.5ms&rts=down&turnaround=5ms",
            "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&turnaround=5ms&rts=down&rts_after=1500us");
        row("rtu:///dev/ttyUSB0?rts=up&rts_before=0&rts_after=0", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&rts=up");
        row("rtu:///dev/ttyUSB0?rs485=kernel", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1&rts=up&rs485=kernel");
        row("rtu:///dev/ttyS1?rs485=KERNEL&rts=down&rts_before=1ms&rts_after=1s",
            "rtu:///dev/ttyS1?baud=9600&parity=E&data=8&stop=1&rts=down&rts_before=1ms&rts_after=1000ms&rs485=kernel");
        row("ascii:///dev/ttyUSB1?rts=up&rts_after=3ms",
            "ascii:///dev/ttyUSB1?baud=9600&parity=E&data=7&stop=1&rts=up&rts_after=3ms");
        row("tcp://h:502?warmup=1.5s&close=each&gap=20", "tcp://h:502?gap=20ms&warmup=1500ms&close=each");
        row("rtu:///dev/ttyUSB0?gap=0&warmup=0", "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1");
        row("rtu-tcp://gw:4001?gap=50ms&timeout=300", "rtu-tcp://gw:4001?timeout=300ms&gap=50ms");
    }
    void canonical()
    {
        QFETCH(QString, text);
        QFETCH(QString, canonical);
        const auto result = LinkUrl::parse(text);
        QVERIFY2(result.url.has_value(), qPrintable(result.error));
        QVERIFY(result.error.isEmpty());
        QCOMPARE(result.url->toString(), canonical);
        // Round trip: the canonical text parses to the same URL and prints the same.
        const auto again = LinkUrl::parse(result.url->toString());
        QVERIFY2(again.url.has_value(), qPrintable(again.error));
        QVERIFY(*again.url == *result.url);
        QCOMPARE(again.url->toString(), canonical);
    }

    // Parsed values, field by field.
    void fields()
    {
        LinkUrl url = parsed(QStringLiteral("rtu-tcp://192.168.127.254:4001"));
        QCOMPARE(url.kind, LinkKind::RtuTcp);
        QCOMPARE(url.host, QStringLiteral("192.168.127.254"));
        QCOMPARE(url.port, quint16(4001));
        QCOMPARE(url.framing(), Framing::Rtu);
        QVERIFY(!url.isSerial());
        QVERIFY(!url.isDatagram());
        QCOMPARE(url.connectTimeoutMs, 3000);
        QCOMPARE(url.responseTimeoutMs, -1);
        QCOMPARE(url.address(), QStringLiteral("192.168.127.254:4001"));

        url = parsed(QStringLiteral("tcp://[::1]:1502"));
        QCOMPARE(url.host, QStringLiteral("::1"));
        QCOMPARE(url.address(), QStringLiteral("[::1]:1502"));
        QCOMPARE(url.framing(), Framing::Tcp);

        url = parsed(QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&parity=O&data=8&stop=2&turnaround=10ms&timeout=250"));
        QCOMPARE(url.kind, LinkKind::Rtu);
        QVERIFY(url.isSerial());
        QCOMPARE(url.serial.device, QStringLiteral("/dev/ttyUSB0"));
        QCOMPARE(url.serial.baud, 19200);
        QCOMPARE(url.serial.parity, 'O');
        QCOMPARE(url.serial.dataBits, 8);
        QCOMPARE(url.serial.stopBits, 2);
        QCOMPARE(url.serial.turnaroundUs, 10000);
        QCOMPARE(url.responseTimeoutMs, 250);
        QCOMPARE(url.address(), QStringLiteral("/dev/ttyUSB0"));

        url = parsed(QStringLiteral("rtu:///dev/ttyUSB0?turnaround=750us"));
        QCOMPARE(url.serial.turnaroundUs, 750);
        url = parsed(QStringLiteral("rtu:///dev/ttyUSB0?turnaround=2000000ns"));
        QCOMPARE(url.serial.turnaroundUs, 2000);

        QVERIFY(!url.serial.rs485.enabled());
        url = parsed(QStringLiteral("rtu:///dev/ttyUSB0?rts=down&rts_before=250us&rts_after=2ms"));
        QCOMPARE(url.serial.rs485.rts, Rs485Settings::Rts::Down);
        QVERIFY(url.serial.rs485.enabled());
        QVERIFY(!url.serial.rs485.sendLevel());
        QVERIFY(!url.serial.rs485.kernel);
        QCOMPARE(url.serial.rs485.beforeUs, 250);
        QCOMPARE(url.serial.rs485.afterUs, 2000);
        url = parsed(QStringLiteral("rtu:///dev/ttyUSB0?rs485=kernel&rts_after=5"));
        QCOMPARE(url.serial.rs485.rts, Rs485Settings::Rts::Up);
        QVERIFY(url.serial.rs485.kernel);
        QCOMPARE(url.serial.rs485.afterUs, 5000);

        url = parsed(QStringLiteral("ascii:///dev/ttyUSB1"));
        QCOMPARE(url.framing(), Framing::Ascii);
        QCOMPARE(url.serial.dataBits, 7);

        url = parsed(QStringLiteral("udp://h"));
        QVERIFY(url.isDatagram());
        QCOMPARE(url.framing(), Framing::Udp);
        QCOMPARE(parsed(QStringLiteral("rtu-udp://h:9")).framing(), Framing::Rtu);
        QCOMPARE(parsed(QStringLiteral("ascii-tcp://h:9")).framing(), Framing::Ascii);

        url = parsed(QStringLiteral("tls://plc?cert=/a/c.pem&key=/a/k.pem&ca=/a/ca.pem&connect_timeout=5s"));
        QCOMPARE(url.kind, LinkKind::Tls);
        QCOMPARE(url.port, quint16(802));
        QCOMPARE(url.framing(), Framing::Tcp);
        QCOMPARE(url.tls.certificate, QStringLiteral("/a/c.pem"));
        QCOMPARE(url.tls.privateKey, QStringLiteral("/a/k.pem"));
        QCOMPARE(url.tls.caCertificates, QStringLiteral("/a/ca.pem"));
        QCOMPARE(url.connectTimeoutMs, 5000);

        url = parsed(QStringLiteral("tls://plc?cert=/my%20certs/c.pem&key=k%26.pem"));
        QCOMPARE(url.tls.certificate, QStringLiteral("/my certs/c.pem"));
        QCOMPARE(url.tls.privateKey, QStringLiteral("k&.pem"));

        url = parsed(QStringLiteral("rtu:///dev/ttyUSB0?framing=delimited&start=24&end=23"));
        QVERIFY(url.delimited.enabled);
        QCOMPARE(url.delimited.startBytes, QByteArray("$"));
        QCOMPARE(url.delimited.endBytes, QByteArray("#"));
        QCOMPARE(url.delimited.checksum, DelimitedChecksum::None);
        QVERIFY(url.delimited.textDisplay);

        url = parsed(QStringLiteral("tcp://h?framing=delimited&start=05&end=04&checksum=sum&display=hex"));
        QCOMPARE(url.delimited.startBytes, QByteArray("\x05"));
        QCOMPARE(url.delimited.endBytes, QByteArray("\x04"));
        QCOMPARE(url.delimited.checksum, DelimitedChecksum::Sum);
        QVERIFY(!url.delimited.textDisplay);

        url = parsed(QStringLiteral("tcp://h?framing=delimited"));
        QCOMPARE(url.delimited.startBytes, QByteArray());
        QCOMPARE(url.delimited.endBytes, QByteArray("\n"));

        // LG Master-K answers: ACK or NAK ... ETX; the same byte twice counts once.
        url = parsed(QStringLiteral("rtu-tcp://h:4001?framing=delimited&start=06,15,06&end=03&checksum=sum"));
        QCOMPARE(url.delimited.startBytes, QByteArray("\x06\x15"));
        QCOMPARE(url.delimited.endBytes, QByteArray("\x03"));
        QVERIFY2(url.toString().contains(QStringLiteral("start=06,15&end=03")), qPrintable(url.toString()));
        QVERIFY(!parsed(QStringLiteral("tcp://h")).delimited.enabled);
    }

    // Errors: the whole text, then the part at fault and what was expected.
    void errors_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("error");
        auto row = [](const char *name, const char *text, const char *error) {
            QTest::newRow(name) << QString::fromUtf8(text) << QString::fromUtf8(text).trimmed() + QStringLiteral(": ")
                    + QString::fromUtf8(error);
        };
        row("baud not a number", "rtu:///dev/ttyUSB0?baud=96OO", "baud '96OO' is not a number");
        row("baud out of range", "rtu:///dev/ttyUSB0?baud=0", "baud 0 is out of range: expected 50-4000000");
        row("unknown scheme", "modbus://h:502",
            "unknown scheme 'modbus': expected one of tcp, rtu-tcp, ascii-tcp, udp, rtu-udp, rtu, ascii, tls");
        row("no scheme", "192.168.1.10:502",
            "no scheme: expected scheme://..., with a scheme among tcp, rtu-tcp, ascii-tcp, udp, rtu-udp, rtu, ascii, tls "
            "(e.g. tcp://192.168.1.10:502)");
        row("empty", "", "no scheme: expected scheme://..., with a scheme among tcp, rtu-tcp, ascii-tcp, udp, rtu-udp, rtu, "
                         "ascii, tls (e.g. tcp://192.168.1.10:502)");
        row("unknown option", "tcp://h:502?speed=fast",
            "unknown option 'speed': tcp links take connect_timeout, timeout, framing, start, end, checksum, display, mode, busy, "
            "gap, warmup, close");
        row("unknown serial option", "rtu:///dev/ttyUSB0?bauds=9600",
            "unknown option 'bauds': rtu links take baud, parity, data, stop, turnaround, turnaround_us, rts, rts_before, "
            "rts_after, rs485, timeout, framing, start, end, checksum, display, gap, warmup");
        row("serial option on tcp", "tcp://h:502?baud=9600",
            "'baud' is an option of serial links (rtu, ascii), not of tcp links");
        row("tls option on tcp", "tcp://h:502?cert=c.pem", "'cert' is an option of tls links, not of tcp links");
        row("connect_timeout on serial", "rtu:///dev/ttyUSB0?connect_timeout=1s",
            "'connect_timeout' is an option of network links (tcp, rtu-tcp, ascii-tcp, udp, rtu-udp, tls), not of rtu links");
        row("option twice", "rtu:///dev/ttyUSB0?baud=9600&baud=19200", "option 'baud' is given twice");
        row("option without value", "rtu:///dev/ttyUSB0?baud", "option 'baud' has no value: expected baud=<value>");
        row("rtu-tcp without port", "rtu-tcp://192.168.127.254",
            "no port: rtu-tcp needs one, e.g. rtu-tcp://192.168.127.254:4001 (serial device servers listen on ports of their own)");
        row("rtu-udp without port", "rtu-udp://gw",
            "no port: rtu-udp needs one, e.g. rtu-udp://gw:4001 (serial device servers listen on ports of their own)");
        row("ascii-tcp without port", "ascii-tcp://gw",
            "no port: ascii-tcp needs one, e.g. ascii-tcp://gw:4001 (serial device servers listen on ports of their own)");
        row("port not a number", "tcp://h:5o2", "port '5o2' is not a number");
        row("port out of range", "tcp://h:70000", "port 70000 is out of range: expected 1-65535");
        row("port zero", "tcp://h:0", "port 0 is out of range: expected 1-65535");
        row("empty port", "tcp://h:", "no port after ':': expected a number 1-65535");
        row("no host", "tcp://", "no host: expected tcp://host:port");
        row("no host, port only", "tcp://:502", "no host: expected tcp://host:port");
        row("bad host", "tcp://plc one:502", "host 'plc one' is not a host name or an IPv4 address (letters, digits, '-', '.')");
        row("IPv6 without brackets", "tcp://::1:502",
            "host '::1:502' looks like an IPv6 address: write it in brackets, e.g. tcp://[::1]:502");
        row("unclosed bracket", "tcp://[::1:502",
            "'[' without ']' in the host: expected an IPv6 address in brackets, e.g. tcp://[::1]:502");
        row("not IPv6 in brackets", "tcp://[plc]:502", "'plc' in brackets is not an IPv6 address");
        row("junk after brackets", "tcp://[::1]502", "unexpected '502' after the IPv6 address: expected ':port'");
        row("path on tcp", "tcp://h:502/unit/1", "unexpected path '/unit/1': tcp links have no path");
        row("no serial device", "rtu://", "no serial device: expected e.g. rtu:///dev/ttyUSB0");
        row("no serial device with options", "ascii://?baud=9600", "no serial device: expected e.g. ascii:///dev/ttyUSB0");
        row("parity", "rtu:///dev/ttyUSB0?parity=X", "parity 'X' is not N, E or O (none, even, odd)");
        row("data bits", "rtu:///dev/ttyUSB0?data=9", "data 9 is out of range: expected 5-8");
        row("rtu with 7 data bits", "rtu:///dev/ttyUSB0?data=7",
            "data=7 cannot carry RTU frames: RTU needs data=8 (Serial Line V1.02, 2.5.1)");
        row("ascii with 6 data bits", "ascii:///dev/ttyUSB0?data=6", "data=6 cannot carry ASCII frames: expected data=7 or 8");
        row("stop bits", "rtu:///dev/ttyUSB0?stop=1.5", "stop '1.5' is not 1 or 2");
        row("turnaround unit", "rtu:///dev/ttyUSB0?turnaround=10parsecs",
            "turnaround '10parsecs' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h "
            "(e.g. 100ms, 1.5s, 2min; a bare number is milliseconds)");
        row("turnaround in minutes", "rtu:///dev/ttyUSB0?turnaround=10min", "turnaround '10min' is out of range: expected at most 10 s");
        row("turnaround negative", "rtu:///dev/ttyUSB0?turnaround=-1ms",
            "turnaround '-1ms' is a negative duration: a duration is 0 or more");
        row("turnaround in ns", "rtu:///dev/ttyUSB0?turnaround=1500ns", "turnaround '1500ns' is not a whole number of microseconds");
        row("turnaround too long", "rtu:///dev/ttyUSB0?turnaround=11s", "turnaround '11s' is out of range: expected at most 10 s");
        row("both turnarounds", "rtu:///dev/ttyUSB0?turnaround=1ms&turnaround_us=1000",
            "turnaround and turnaround_us are both given: use one");
        row("timeout zero", "tcp://h?timeout=0", "timeout '0' is out of range: expected 1 ms to 24 h");
        row("timeout not whole ms", "tcp://h?timeout=1500us", "timeout '1500us' is not a whole number of milliseconds");
        row("timeout fractional milliseconds", "tcp://h?timeout=1.5ms", "timeout '1.5ms' is not a whole number of milliseconds");
        row("timeout overflowing", "tcp://h?timeout=999999999999999999s",
            "timeout '999999999999999999s' is out of range: expected 1 ms to 24 h");
        row("connect_timeout too long", "tcp://h?connect_timeout=2000000s",
            "connect_timeout '2000000s' is out of range: expected 1 ms to 24 h");
        row("framing unknown", "tcp://h?framing=rtu", "framing 'rtu' is not known: expected delimited (the scheme chooses the "
                                                      "Modbus framing)");
        row("start without framing", "rtu:///dev/ttyUSB0?start=24&end=23", "'start' needs framing=delimited");
        row("checksum without framing", "tcp://h?checksum=sum", "'checksum' needs framing=delimited");
        row("start not hex", "tcp://h?framing=delimited&start=$",
            "start '$' is not a byte in hex: expected two hex digits, e.g. 24 for '$', 05 for ENQ, "
            "or several separated by commas (06,15 for ACK or NAK)");
        row("end too long", "tcp://h?framing=delimited&end=123",
            "end '123' is not a byte in hex: expected two hex digits, e.g. 24 for '$', 05 for ENQ, "
            "or several separated by commas (06,15 for ACK or NAK)");
        row("start list, one byte bad", "tcp://h?framing=delimited&start=06,zz",
            "start 'zz' is not a byte in hex: expected two hex digits, e.g. 24 for '$', 05 for ENQ, "
            "or several separated by commas (06,15 for ACK or NAK)");
        row("checksum unknown", "tcp://h?framing=delimited&checksum=crc", "checksum 'crc' is not none, sum or xor");
        row("display unknown", "tcp://h?framing=delimited&display=ascii", "display 'ascii' is not text or hex");
        row("cert without key", "tls://plc?cert=c.pem", "cert without key: mutual TLS needs both cert=FILE and key=FILE");
        row("key without cert", "tls://plc?key=k.pem", "key without cert: mutual TLS needs both cert=FILE and key=FILE");
        row("empty ca", "tls://plc?ca=", "ca is empty: expected the path of a PEM file");
        row("mode unknown", "tcp://h?mode=server",
            "mode 'server' is not connect or listen (listen: wait for the device to connect to this address)");
        row("mode on udp", "udp://0.0.0.0:502?mode=listen",
            "'mode' is an option of stream links (tcp, rtu-tcp, ascii-tcp, tls), not of udp links");
        row("mode on serial", "rtu:///dev/ttyUSB0?mode=listen",
            "'mode' is an option of stream links (tcp, rtu-tcp, ascii-tcp, tls), not of rtu links");
        row("busy without listen", "tcp://h?busy=queue", "'busy' needs mode=listen");
        row("busy with connect", "tcp://h?mode=connect&busy=refuse", "'busy' needs mode=listen");
        row("busy unknown", "tcp://0.0.0.0:5020?mode=listen&busy=wait", "busy 'wait' is not replace, queue or refuse");
        row("listen on a host name", "tcp://plc.local:5020?mode=listen",
            "mode=listen needs an address of this machine to listen on, not the host name 'plc.local' (0.0.0.0 for every "
            "IPv4 interface, [::] for every IPv6 interface, 127.0.0.1 for this machine only)");
        row("listen on port 0", "tcp://127.0.0.1:0?mode=listen", "port 0 is out of range: expected 1-65535");
        row("tls listen without cert", "tls://0.0.0.0?mode=listen",
            "tls with mode=listen needs cert=FILE and key=FILE: mbscope is the TLS server of the device's connection");
        row("rts level", "rtu:///dev/ttyUSB0?rts=high", "rts 'high' is not up or down (the RTS level while sending)");
        row("rts on tcp", "rtu-tcp://gw:4001?rts=up", "'rts' is an option of serial links (rtu, ascii), not of rtu-tcp links");
        row("rs485 mode", "rtu:///dev/ttyUSB0?rs485=auto",
            "rs485 'auto' is not known: expected kernel (the driver's RS-485 mode; rts=up or rts=down without it has mbscope "
            "switch RTS)");
        row("rts_before alone", "rtu:///dev/ttyUSB0?rts_before=1ms", "'rts_before' needs rts=up, rts=down or rs485=kernel");
        row("rts_after alone", "ascii:///dev/ttyUSB0?rts_after=1ms", "'rts_after' needs rts=up, rts=down or rs485=kernel");
        row("rts_before unit", "rtu:///dev/ttyUSB0?rts=up&rts_before=1jiffy",
            "rts_before '1jiffy' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h "
            "(e.g. 100ms, 1.5s, 2min; a bare number is milliseconds)");
        row("rts_after too long", "rtu:///dev/ttyUSB0?rts=up&rts_after=11s", "rts_after '11s' is out of range: expected at most 10 s");
        row("rts_after in ns", "rtu:///dev/ttyUSB0?rts=up&rts_after=100ns",
            "rts_after '100ns' is not a whole number of microseconds");
        row("rts_before negative", "rtu:///dev/ttyUSB0?rts=up&rts_before=-1",
            "rts_before '-1' is a negative duration: a duration is 0 or more");
        row("kernel delay in us", "rtu:///dev/ttyUSB0?rs485=kernel&rts_after=1500us",
            "rts_after 1500us is not a whole number of milliseconds: rs485=kernel hands the driver milliseconds");
        row("rts twice", "rtu:///dev/ttyUSB0?rts=up&rts=down", "option 'rts' is given twice");
        // The device's pace: gap=, warmup= (every link), close=each (streams).
        row("gap not a duration", "tcp://h:502?gap=fast",
            "gap 'fast' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, 1.5s, "
            "2min; a bare number is milliseconds)");
        row("warmup negative", "tcp://h:502?warmup=-5ms", "warmup '-5ms' is a negative duration: a duration is 0 or more");
        row("gap in us", "tcp://h:502?gap=1500us", "gap '1500us' is not a whole number of milliseconds");
        row("close unknown", "tcp://h:502?close=always",
            "close 'always' is not known: expected each (the device hangs up after each answer: a new connection for each request)");
        row("close on udp", "udp://h:502?close=each", "'close' is an option of stream links (tcp, rtu-tcp, ascii-tcp, tls), not of udp links");
    }
    void errors()
    {
        QFETCH(QString, text);
        QFETCH(QString, error);
        const auto result = LinkUrl::parse(text);
        QVERIFY2(!result.url.has_value(), qPrintable(result.url ? result.url->toString() : QString()));
        QCOMPARE(result.error, error);
    }

    // mode= belongs to targets: an address something listens on (the simulator's) refuses it.
    void modeIsForTargets()
    {
        const auto paced = LinkUrl::parse(QStringLiteral("tcp://127.0.0.1:0?gap=5ms"), LinkUse::Listen);
        QVERIFY(!paced.url);
        QCOMPARE(paced.error, QStringLiteral("tcp://127.0.0.1:0?gap=5ms: 'gap' is the pace of a device asked (an option of --target "
                                             "URLs), not of an address to listen on"));
        const LinkUrl pace = parsed(QStringLiteral("tcp://h?gap=20ms&warmup=300ms&close=each"));
        QCOMPARE(pace.gap, std::chrono::milliseconds(20));
        QCOMPARE(pace.warmUp, std::chrono::milliseconds(300));
        QVERIFY(pace.closeAfterAnswer && pace.hasPace());
        const auto listen = LinkUrl::parse(QStringLiteral("tcp://127.0.0.1:0?mode=listen"), LinkUse::Listen);
        QVERIFY(!listen.url);
        QCOMPARE(listen.error, QStringLiteral("tcp://127.0.0.1:0?mode=listen: 'mode' is an option of --target URLs, not of an "
                                              "address to listen on (this one listens already)"));
        const LinkUrl url = parsed(QStringLiteral("rtu-tcp://0.0.0.0:4001?mode=listen&busy=refuse"));
        QVERIFY(url.listen);
        QCOMPARE(url.busy, BusyPolicy::Refuse);
        QCOMPARE(url.address(), QStringLiteral("0.0.0.0:4001"));
        QCOMPARE(url.framing(), Framing::Rtu);
        const LinkUrl plain = parsed(QStringLiteral("tcp://h:502"));
        QVERIFY(!plain.listen);
        QCOMPARE(plain.busy, BusyPolicy::Replace);
    }

    void schemeNames()
    {
        QCOMPARE(LinkUrl::knownSchemes(), QStringLiteral("tcp, rtu-tcp, ascii-tcp, udp, rtu-udp, rtu, ascii, tls"));
        for (LinkKind kind : {LinkKind::Tcp, LinkKind::RtuTcp, LinkKind::AsciiTcp, LinkKind::Udp, LinkKind::RtuUdp,
                              LinkKind::Rtu, LinkKind::Ascii, LinkKind::Tls}) {
            const QString text = LinkUrl::schemeName(kind) + (kind == LinkKind::Rtu || kind == LinkKind::Ascii
                                                                  ? QStringLiteral(":///dev/ttyS0")
                                                                  : QStringLiteral("://h:1"));
            QCOMPARE(parsed(text).kind, kind);
        }
    }

    // Values built in code print as URLs that parse back to them.
    void roundTripBuilt()
    {
        LinkUrl url;
        url.kind = LinkKind::Rtu;
        url.serial.device = QStringLiteral("/dev/tty USB?&#0");
        url.serial.baud = 38400;
        url.serial.parity = 'N';
        url.serial.stopBits = 2;
        url.serial.turnaroundUs = 1234;
        url.serial.rs485 = Rs485Settings{Rs485Settings::Rts::Down, false, 1500, 20};
        url.responseTimeoutMs = 77;
        url.delimited = DelimitedFraming{true, QByteArray(":"), QByteArray("\r\n"), DelimitedChecksum::Xor, false};
        const auto again = LinkUrl::parse(url.toString());
        QVERIFY2(again.url.has_value(), qPrintable(again.error));
        QVERIFY(*again.url == url);

        LinkUrl tls;
        tls.kind = LinkKind::Tls;
        tls.host = QStringLiteral("2001:db8::7");
        tls.port = 8802;
        tls.tls = TlsSettings{QStringLiteral("/p/c=1.pem"), QStringLiteral("/p/k 1.pem"), QStringLiteral("/p/ca%.pem")};
        tls.connectTimeoutMs = 12;
        QCOMPARE(tls.toString(), QStringLiteral("tls://[2001:db8::7]:8802?cert=/p/c%3D1.pem&key=/p/k%201.pem&ca=/p/ca%25.pem"
                                                "&connect_timeout=12ms"));
        const auto tlsAgain = LinkUrl::parse(tls.toString());
        QVERIFY2(tlsAgain.url.has_value(), qPrintable(tlsAgain.error));
        QVERIFY(*tlsAgain.url == tls);
    }
};

QTEST_GUILESS_MAIN(TestLinkUrl)
#include "tst_linkurl.moc"
