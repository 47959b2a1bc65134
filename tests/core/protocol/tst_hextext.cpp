#include "protocol/hextext.h"

#include <QtCore/QRandomGenerator>
#include <QtTest/QtTest>

using namespace mbscope;

// Accepted and rejected hex text as users type it. The accepted forms come from the issue (the
// RosRao request "01 03 00 79 00 16 15 DD" as printed in its publication, C arrays, dashes,
// colons); the rejections pin the exact line and column of the first bad character.
class TestHexText : public QObject
{
    Q_OBJECT
private slots:
    void accepts_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QByteArray>("bytes");
        const QByteArray rosrao = QByteArray::fromHex("01030079001615DD");
        QTest::newRow("01 03 00 79 00 16 15 DD (rosrao, spaced)") << QStringLiteral("01 03 00 79 00 16 15 DD") << rosrao;
        QTest::newRow("01030079001615DD (compact)") << QStringLiteral("01030079001615DD") << rosrao;
        QTest::newRow("01030079 001615DD (compact groups)") << QStringLiteral("01030079 001615DD") << rosrao;
        QTest::newRow("lower case 01030079001615dd") << QStringLiteral("01030079001615dd") << rosrao;
        QTest::newRow("mixed case aB cD eF") << QStringLiteral("aB cD eF") << QByteArray::fromHex("ABCDEF");
        QTest::newRow("0x01,0x03") << QStringLiteral("0x01,0x03") << QByteArray::fromHex("0103");
        QTest::newRow("0x01, 0x03 (comma space)") << QStringLiteral("0x01, 0x03") << QByteArray::fromHex("0103");
        QTest::newRow("0X1A (capital X)") << QStringLiteral("0X1A") << QByteArray::fromHex("1A");
        QTest::newRow("0x1a lower digits") << QStringLiteral("0x1a") << QByteArray::fromHex("1A");
        QTest::newRow("0x1 (one digit after 0x)") << QStringLiteral("0x1") << QByteArray::fromHex("01");
        QTest::newRow("0xA, 0xb (one digit each)") << QStringLiteral("0xA, 0xb") << QByteArray::fromHex("0A0B");
        QTest::newRow("0x00") << QStringLiteral("0x00") << QByteArray::fromHex("00");
        QTest::newRow("0xFF") << QStringLiteral("0xFF") << QByteArray::fromHex("FF");
        QTest::newRow("00 is a byte, not a prefix") << QStringLiteral("00") << QByteArray::fromHex("00");
        QTest::newRow("0a starts with 0 but is not 0x") << QStringLiteral("0a") << QByteArray::fromHex("0A");
        QTest::newRow("01-03 (dashed)") << QStringLiteral("01-03") << QByteArray::fromHex("0103");
        QTest::newRow("01:03 (colon)") << QStringLiteral("01:03") << QByteArray::fromHex("0103");
        QTest::newRow("01;03 (semicolon)") << QStringLiteral("01;03") << QByteArray::fromHex("0103");
        QTest::newRow("01\\t03 (tab)") << QStringLiteral("01\t03") << QByteArray::fromHex("0103");
        QTest::newRow("01\\n03 (LF)") << QStringLiteral("01\n03") << QByteArray::fromHex("0103");
        QTest::newRow("01\\r\\n03 (CR LF)") << QStringLiteral("01\r\n03") << QByteArray::fromHex("0103");
        QTest::newRow("01\\r03 (lone CR)") << QStringLiteral("01\r03") << QByteArray::fromHex("0103");
        QTest::newRow("leading and trailing whitespace") << QStringLiteral("  \t01 03 \r\n") << QByteArray::fromHex("0103");
        QTest::newRow("runs of separators 01,,03") << QStringLiteral("01,,03") << QByteArray::fromHex("0103");
        QTest::newRow("01 - 03 (spaced dash)") << QStringLiteral("01 - 03") << QByteArray::fromHex("0103");
        QTest::newRow("trailing comma 0x01,") << QStringLiteral("0x01,") << QByteArray::fromHex("01");
        QTest::newRow("leading separator ,01") << QStringLiteral(",01") << QByteArray::fromHex("01");
        QTest::newRow("mixed forms 0x01 0203 04-05:06;07") << QStringLiteral("0x01 0203 04-05:06;07")
                                                           << QByteArray::fromHex("01020304050607");
        QTest::newRow("c array over lines") << QStringLiteral("0x01, 0x03,\n0x00, 0x79,\r\n0x00")
                                            << QByteArray::fromHex("0103007900");
        QTest::newRow("07 03 00 C8 00 04 C5 91 (tutorial)") << QStringLiteral("07 03 00 C8 00 04 C5 91")
                                                            << QByteArray::fromHex("070300C80004C591");
        QTest::newRow("00 01 00 00 00 09 00 10 ... (m221 tcp)")
            << QStringLiteral("00 01 00 00 00 09 00 10 00 00 00 01 02 00 CD")
            << QByteArray::fromHex("000100000009001000000001020" "0CD");
        QTest::newRow("rosrao response over three lines")
            << QStringLiteral("01 03 2C 04 1A 00 00\n00 00 00 00 00 FA\n00 01 03 E8 27 10")
            << QByteArray::fromHex("01032C041A0000" "000000000" "0FA" "000103E82710");
    }
    void accepts()
    {
        QFETCH(QString, text);
        QFETCH(QByteArray, bytes);
        const HexTextResult result = HexText::parse(text);
        QVERIFY2(result.ok, qPrintable(result.error.message));
        QCOMPARE(result.bytes, bytes);
        QCOMPARE(result.error.line, 0);
        QCOMPARE(result.error.column, 0);
        QVERIFY(result.error.message.isEmpty());
    }

    void rejects_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("fragment");
        QTest::newRow("01 03 0G: stray G")
            << QStringLiteral("01 03 0G") << 1 << 8 << QStringLiteral("'G' is not a hex digit or a separator");
        QTest::newRow("1G: stray before odd count")
            << QStringLiteral("1G") << 1 << 2 << QStringLiteral("'G' is not a hex digit");
        QTest::newRow("01 03 G: a group that is only a stray")
            << QStringLiteral("01 03 G") << 1 << 7 << QStringLiteral("'G' is not a hex digit");
        QTest::newRow("01.03: a dot is no separator")
            << QStringLiteral("01.03") << 1 << 3 << QStringLiteral("'.' is not a hex digit or a separator");
        QTest::newRow("01 03 # comment")
            << QStringLiteral("01 03 # comment") << 1 << 7 << QStringLiteral("'#' is not a hex digit");
        QTest::newRow("$01R# (scada ascii, not hex)")
            << QStringLiteral("$01R#") << 1 << 1 << QStringLiteral("'$' is not a hex digit");
        QTest::newRow("01h: no suffix notation")
            << QStringLiteral("01h") << 1 << 3 << QStringLiteral("'h' is not a hex digit");
        QTest::newRow("% in text")
            << QStringLiteral("01 %3") << 1 << 4 << QStringLiteral("'%' is not a hex digit");
        QTest::newRow("10x1: 0x inside a group")
            << QStringLiteral("10x1") << 1 << 3 << QStringLiteral("'x' is not a hex digit or a separator (0x may only start a byte");
        QTest::newRow("0x1A0x1B: prefixes without separator")
            << QStringLiteral("0x1A0x1B") << 1 << 6 << QStringLiteral("'x' is not a hex digit");
        QTest::newRow("123: odd count")
            << QStringLiteral("123") << 1 << 1 << QStringLiteral("'123' has an odd number of hex digits (3); each byte needs two");
        QTest::newRow("01 123: odd group points at its start")
            << QStringLiteral("01 123") << 1 << 4 << QStringLiteral("'123' has an odd number of hex digits (3); each byte needs two");
        QTest::newRow("01 03 79 0: last digit alone")
            << QStringLiteral("01 03 79 0") << 1 << 10 << QStringLiteral("'0' has an odd number of hex digits (1)");
        QTest::newRow("1: a single digit")
            << QStringLiteral("1") << 1 << 1 << QStringLiteral("'1' has an odd number of hex digits (1)");
        QTest::newRow("01-3: odd after dash")
            << QStringLiteral("01-3") << 1 << 4 << QStringLiteral("'3' has an odd number");
        QTest::newRow("odd group on line 2 after LF")
            << QStringLiteral("01 03\n00 7") << 2 << 4 << QStringLiteral("'7' has an odd number of hex digits (1)");
        QTest::newRow("odd group on line 2 after CR LF")
            << QStringLiteral("01 03\r\n00 7") << 2 << 4 << QStringLiteral("'7' has an odd number");
        QTest::newRow("stray on line 2 after lone CR")
            << QStringLiteral("01\r0G") << 2 << 2 << QStringLiteral("'G' is not a hex digit");
        QTest::newRow("stray on line 3 after blank line")
            << QStringLiteral("01\n\n  0Z") << 3 << 4 << QStringLiteral("'Z' is not a hex digit");
        QTest::newRow("tabs count one column each")
            << QStringLiteral("\t\t0G") << 1 << 4 << QStringLiteral("'G' is not");
        QTest::newRow("0x alone")
            << QStringLiteral("0x") << 1 << 1 << QStringLiteral("0x is not followed by a hex digit");
        QTest::newRow("0X alone keeps the user's case")
            << QStringLiteral("0X") << 1 << 1 << QStringLiteral("0X is not followed by a hex digit");
        QTest::newRow("01 0x: lone 0x at the end")
            << QStringLiteral("01 0x") << 1 << 4 << QStringLiteral("0x is not followed by a hex digit");
        QTest::newRow("0x,0x01: lone 0x before comma")
            << QStringLiteral("0x,0x01") << 1 << 1 << QStringLiteral("0x is not followed");
        QTest::newRow("0x01 0x: lone 0x second")
            << QStringLiteral("0x01 0x") << 1 << 6 << QStringLiteral("0x is not followed");
        QTest::newRow("0xG1: stray after prefix")
            << QStringLiteral("0xG1") << 1 << 3 << QStringLiteral("'G' is not a hex digit");
        QTest::newRow("0x1G: stray after one digit")
            << QStringLiteral("0x1G") << 1 << 4 << QStringLiteral("'G' is not a hex digit");
        QTest::newRow("0x123: three digits after 0x")
            << QStringLiteral("0x123") << 1 << 1 << QStringLiteral("'0x123' has 3 hex digits after 0x; a 0x prefix introduces one byte");
        QTest::newRow("0x0103: a word after 0x")
            << QStringLiteral("01, 0x0103") << 1 << 5 << QStringLiteral("'0x0103' has 4 hex digits after 0x");
        QTest::newRow("empty text")
            << QString() << 1 << 1 << QStringLiteral("the text is empty");
        QTest::newRow("only separators")
            << QStringLiteral("  ,\n\t- ") << 1 << 1 << QStringLiteral("only separators and no hex byte");
        QTest::newRow("no-break space U+00A0")
            << QStringLiteral("01\u00A003") << 1 << 3 << QStringLiteral("U+00A0 (a space character other than space, tab or newline)");
        QTest::newRow("control character U+0007")
            << QStringLiteral("01\a03") << 1 << 3 << QStringLiteral("U+0007 (a control or unprintable character)");
        QTest::newRow("NUL character")
            << QString(QStringLiteral("01 ") + QChar(0) + QStringLiteral("03")) << 1 << 4 << QStringLiteral("U+0000");
        QTest::newRow("non-ASCII letter")
            << QStringLiteral("01 \u00E9") << 1 << 4 << QStringLiteral("'\u00E9' (U+00E9) is not a hex digit");
        QTest::newRow("full-width digit is not a hex digit")
            << QStringLiteral("01 \uFF10\uFF11") << 1 << 4 << QStringLiteral("(U+FF10)");
        QTest::newRow("emoji outside the BMP")
            << QStringLiteral("01 \U0001F600") << 1 << 4 << QStringLiteral("(U+1F600) is not a hex digit");
        QTest::newRow("long odd group is quoted shortened")
            << QString(QString(QStringLiteral("0")).repeated(101)) << 1 << 1
            << QStringLiteral("'000000000000000000000000...' has an odd number of hex digits (101)");
    }
    void rejects()
    {
        QFETCH(QString, text);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(QString, fragment);
        const HexTextResult result = HexText::parse(text);
        QVERIFY(!result.ok);
        QVERIFY(result.bytes.isEmpty());
        QCOMPARE(result.error.line, line);
        QCOMPARE(result.error.column, column);
        const QString prefix = QStringLiteral("line %1, column %2: ").arg(line).arg(column);
        QVERIFY2(result.error.message.startsWith(prefix), qPrintable(result.error.message));
        QVERIFY2(result.error.message.contains(fragment), qPrintable(result.error.message));
    }

    void oddCountMessageIsExact()
    {
        // The whole message, as the issue words it, so a change of wording is a visible decision.
        QCOMPARE(HexText::parse(QStringLiteral("01 123")).error.message,
                 QStringLiteral("line 1, column 4: '123' has an odd number of hex digits (3); each byte needs two"));
        QCOMPARE(HexText::parse(QStringLiteral("01 03 0G")).error.message,
                 QStringLiteral("line 1, column 8: 'G' is not a hex digit or a separator "
                                "(separators are space, tab, newline, ',', '-', ':' and ';')"));
    }

    // Random text over digits, separators and bad characters: parse never fails to answer, and an
    // error's line and column point at a character that explains it. Lines are located here
    // independently of the parser (split on CR LF, CR, LF).
    void randomTextPointsAtTheCulprit()
    {
        const QString alphabet = QStringLiteral("0123456789abcdefABCDEF    ,-:;\t\r\n0x0XgG.#\u00A0");
        QRandomGenerator random(42);
        for (int trial = 0; trial < 20000; ++trial) {
            QString text;
            const int length = random.bounded(12);
            for (int i = 0; i < length; ++i)
                text += alphabet[random.bounded(int(alphabet.size()))];
            const HexTextResult result = HexText::parse(text);
            if (result.ok) {
                QVERIFY(!result.bytes.isEmpty());
                continue;
            }
            QVERIFY(result.bytes.isEmpty());
            QVERIFY2(result.error.message.startsWith(
                         QStringLiteral("line %1, column %2: ").arg(result.error.line).arg(result.error.column)),
                     qPrintable(result.error.message));
            const QStringList lines = QString(text).replace(QLatin1String("\r\n"), QLatin1String("\n"))
                                          .replace(QLatin1Char('\r'), QLatin1Char('\n'))
                                          .split(QLatin1Char('\n'));
            QVERIFY(result.error.line >= 1 && result.error.line <= lines.size());
            const QString &line = lines[result.error.line - 1];
            if (result.error.message.contains(QLatin1String("the text"))) {
                QCOMPARE(result.error.column, 1); // empty or separators only: points at the start
                continue;
            }
            QVERIFY2(result.error.column >= 1 && result.error.column <= line.size(), qPrintable(text));
            const QChar culprit = line[result.error.column - 1];
            const bool startsGroup = result.error.column == 1
                || QStringLiteral(" \t,-:;").contains(line[result.error.column - 2]);
            if (result.error.message.contains(QLatin1String("is not a hex digit or a separator"))) {
                QVERIFY2(!QStringLiteral("0123456789abcdefABCDEF \t,-:;").contains(culprit), qPrintable(text));
            } else if (result.error.message.contains(QLatin1String("odd number"))) {
                QVERIFY2(QStringLiteral("0123456789abcdefABCDEF").contains(culprit) && startsGroup, qPrintable(text));
            } else {
                QVERIFY2(culprit == u'0' && startsGroup, qPrintable(text + QLatin1String(": ") + result.error.message));
            }
        }
    }

    void format_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("style");
        QTest::addColumn<bool>("uppercase");
        QTest::addColumn<int>("bytesPerLine");
        QTest::addColumn<QString>("text");
        const QByteArray rosrao = QByteArray::fromHex("01030079001615DD");
        const int spaced = int(HexText::Style::Spaced);
        const int compact = int(HexText::Style::Compact);
        const int carray = int(HexText::Style::CArray);
        const int dashed = int(HexText::Style::Dashed);
        const int colon = int(HexText::Style::Colon);
        QTest::newRow("spaced upper") << rosrao << spaced << true << 0 << QStringLiteral("01 03 00 79 00 16 15 DD");
        QTest::newRow("spaced lower") << rosrao << spaced << false << 0 << QStringLiteral("01 03 00 79 00 16 15 dd");
        QTest::newRow("compact upper") << rosrao << compact << true << 0 << QStringLiteral("01030079001615DD");
        QTest::newRow("compact lower") << rosrao << compact << false << 0 << QStringLiteral("01030079001615dd");
        QTest::newRow("c array upper") << rosrao << carray << true << 0
                                       << QStringLiteral("0x01, 0x03, 0x00, 0x79, 0x00, 0x16, 0x15, 0xDD");
        QTest::newRow("c array lower") << rosrao << carray << false << 0
                                       << QStringLiteral("0x01, 0x03, 0x00, 0x79, 0x00, 0x16, 0x15, 0xdd");
        QTest::newRow("dashed") << rosrao << dashed << true << 0 << QStringLiteral("01-03-00-79-00-16-15-DD");
        QTest::newRow("colon") << rosrao << colon << true << 0 << QStringLiteral("01:03:00:79:00:16:15:DD");
        QTest::newRow("spaced 4 per line") << rosrao << spaced << true << 4 << QStringLiteral("01 03 00 79\n00 16 15 DD");
        QTest::newRow("spaced 3 per line, last short") << rosrao << spaced << true << 3
                                                       << QStringLiteral("01 03 00\n79 00 16\n15 DD");
        QTest::newRow("compact 2 per line") << rosrao << compact << true << 2 << QStringLiteral("0103\n0079\n0016\n15DD");
        QTest::newRow("c array 4 per line keeps the comma") << rosrao << carray << true << 4
                                                            << QStringLiteral("0x01, 0x03, 0x00, 0x79,\n0x00, 0x16, 0x15, 0xDD");
        QTest::newRow("dashed 1 per line") << QByteArray::fromHex("0A0B") << dashed << true << 1 << QStringLiteral("0A\n0B");
        QTest::newRow("per line larger than data") << rosrao << colon << true << 100 << QStringLiteral("01:03:00:79:00:16:15:DD");
        QTest::newRow("per line exactly the data") << rosrao << spaced << true << 8 << QStringLiteral("01 03 00 79 00 16 15 DD");
        QTest::newRow("negative per line means one line") << rosrao << spaced << true << -3 << QStringLiteral("01 03 00 79 00 16 15 DD");
        QTest::newRow("empty bytes") << QByteArray() << spaced << true << 0 << QString();
        QTest::newRow("empty bytes c array") << QByteArray() << carray << true << 4 << QString();
        QTest::newRow("one byte") << QByteArray::fromHex("FF") << carray << true << 1 << QStringLiteral("0xFF");
    }
    void format()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(int, style);
        QFETCH(bool, uppercase);
        QFETCH(int, bytesPerLine);
        QFETCH(QString, text);
        HexText::FormatOptions options;
        options.style = HexText::Style(style);
        options.uppercase = uppercase;
        options.bytesPerLine = bytesPerLine;
        QCOMPARE(HexText::format(bytes, options), text);
    }

    void formatDefaultIsSpacedUpper()
    {
        QCOMPARE(HexText::format(QByteArray::fromHex("01030079")), QStringLiteral("01 03 00 79"));
    }

    void everyByteValue()
    {
        // Independent check against QByteArray::toHex over all 256 values, both cases.
        QByteArray all;
        for (int b = 0; b < 256; ++b)
            all.append(char(b));
        HexText::FormatOptions upper{HexText::Style::Compact, true, 0};
        HexText::FormatOptions lower{HexText::Style::Compact, false, 0};
        QCOMPARE(HexText::format(all, upper), QString::fromLatin1(all.toHex().toUpper()));
        QCOMPARE(HexText::format(all, lower), QString::fromLatin1(all.toHex()));
        QCOMPARE(HexText::parse(QString::fromLatin1(all.toHex())).bytes, all);
        QCOMPARE(HexText::parse(QString::fromLatin1(all.toHex().toUpper())).bytes, all);
        QCOMPARE(HexText::parse(QString::fromLatin1(all.toHex(' '))).bytes, all);
    }

    void roundTrip_data()
    {
        QTest::addColumn<int>("style");
        QTest::addColumn<bool>("uppercase");
        QTest::addColumn<int>("bytesPerLine");
        const struct { HexText::Style style; const char *name; } styles[] = {
            {HexText::Style::Spaced, "spaced"}, {HexText::Style::Compact, "compact"},
            {HexText::Style::CArray, "carray"}, {HexText::Style::Dashed, "dashed"},
            {HexText::Style::Colon, "colon"},
        };
        for (const auto &s : styles) {
            for (bool upper : {true, false}) {
                for (int perLine : {0, 1, 7, 16}) {
                    QTest::addRow("%s %s %d per line", s.name, upper ? "upper" : "lower", perLine)
                        << int(s.style) << upper << perLine;
                }
            }
        }
    }
    void roundTrip()
    {
        QFETCH(int, style);
        QFETCH(bool, uppercase);
        QFETCH(int, bytesPerLine);
        HexText::FormatOptions options{HexText::Style(style), uppercase, bytesPerLine};
        // Fixed seed per row: failures reproduce, and every row sees different data.
        QRandomGenerator random(quint32(style * 1000 + (uppercase ? 500 : 0) + bytesPerLine));
        for (int trial = 0; trial < 200; ++trial) {
            QByteArray bytes(1 + random.bounded(300), Qt::Uninitialized);
            for (char &b : bytes)
                b = char(random.bounded(256));
            const QString text = HexText::format(bytes, options);
            const HexTextResult back = HexText::parse(text);
            QVERIFY2(back.ok, qPrintable(back.error.message + QLatin1String(" in ") + text));
            QCOMPARE(back.bytes, bytes);
        }
    }
};

QTEST_GUILESS_MAIN(TestHexText)
#include "tst_hextext.moc"
