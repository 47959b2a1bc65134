// ConnectionBar: the URL it produces for every link type, errors in place, recent targets; TLS's
// certificate, key and CA files (a missing one named in place, kept in recent targets).
#include "link/connectionbar.h"
#include "guitestsupport.h"
#include "link/tlsfilesfield.h"

#include <QtCore/QSettings>
#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtSerialPort/QSerialPortInfo>
#include <QtWidgets/QApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QMenu>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QToolButton>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;

class TestConnectionBar : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void networkUrl_data();
    void networkUrl();
    void serialUrl();
    void emptyHostIsRefusedInPlace();
    void hostWithPortIsRefused();
    void rtuNeedsEightDataBits();
    void setUrlRoundTrip_data();
    void setUrlRoundTrip();
    void keptOptionsGoWithTheLinkType();
    void paceFromAProfile();
    void connectAndDisconnectSignals();
    void recentTargets();
    void serialListIsReadAgainWhenOpened();
    void tlsUrlCarriesTheFiles();
    void tlsFileProblemsAreNamed_data();
    void tlsFileProblemsAreNamed();
    void tlsRecentTargetKeepsTheFiles();
    void screenshot();
};

void TestConnectionBar::initTestCase()
{
    guitest::isolateSettings();
}

void TestConnectionBar::init()
{
    QSettings().clear();
}

static void chooseKind(ConnectionBar &bar, LinkKind kind)
{
    auto *combo = bar.findChild<QComboBox *>(QStringLiteral("linkKindCombo"));
    QVERIFY(combo);
    combo->setCurrentIndex(combo->findData(int(kind)));
    QVERIFY(combo->currentIndex() >= 0);
}

void TestConnectionBar::networkUrl_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("host");
    QTest::addColumn<int>("port");
    QTest::addColumn<QString>("expected");
    QTest::newRow("tcp") << int(LinkKind::Tcp) << QStringLiteral("192.168.0.10") << 502 << QStringLiteral("tcp://192.168.0.10:502");
    QTest::newRow("rtu-tcp") << int(LinkKind::RtuTcp) << QStringLiteral("192.168.127.254") << 4001
                             << QStringLiteral("rtu-tcp://192.168.127.254:4001");
    QTest::newRow("udp") << int(LinkKind::Udp) << QStringLiteral("plc.local") << 502 << QStringLiteral("udp://plc.local:502");
    QTest::newRow("rtu-udp") << int(LinkKind::RtuUdp) << QStringLiteral("10.0.0.2") << 5000 << QStringLiteral("rtu-udp://10.0.0.2:5000");
    QTest::newRow("ascii-tcp") << int(LinkKind::AsciiTcp) << QStringLiteral("10.0.0.3") << 4002
                               << QStringLiteral("ascii-tcp://10.0.0.3:4002");
}

void TestConnectionBar::networkUrl()
{
    QFETCH(int, kind);
    QFETCH(QString, host);
    QFETCH(int, port);
    QFETCH(QString, expected);
    ConnectionBar bar;
    chooseKind(bar, LinkKind(kind));
    bar.findChild<QLineEdit *>(QStringLiteral("hostEdit"))->setText(host);
    bar.findChild<QSpinBox *>(QStringLiteral("portSpin"))->setValue(port);
    bar.findChild<QSpinBox *>(QStringLiteral("timeoutSpin"))->setValue(750);
    const std::optional<LinkUrl> url = bar.url();
    QVERIFY2(url, qPrintable(bar.errorText()));
    QCOMPARE(url->kind, LinkKind(kind));
    QCOMPARE(url->host, host);
    QCOMPARE(int(url->port), port);
    QCOMPARE(url->responseTimeoutMs, 750);
    QVERIFY2(url->toString().startsWith(expected), qPrintable(url->toString()));
    QVERIFY(bar.errorText().isEmpty());
}

void TestConnectionBar::serialUrl()
{
    ConnectionBar bar;
    chooseKind(bar, LinkKind::Rtu);
    bar.findChild<QComboBox *>(QStringLiteral("serialPortCombo"))->setCurrentText(QStringLiteral("/dev/ttyUSB0"));
    bar.findChild<QComboBox *>(QStringLiteral("baudCombo"))->setCurrentText(QStringLiteral("19200"));
    auto *parity = bar.findChild<QComboBox *>(QStringLiteral("parityCombo"));
    parity->setCurrentIndex(parity->findData(QStringLiteral("N")));
    auto *stop = bar.findChild<QComboBox *>(QStringLiteral("stopBitsCombo"));
    stop->setCurrentIndex(stop->findData(2));
    const std::optional<LinkUrl> url = bar.url();
    QVERIFY2(url, qPrintable(bar.errorText()));
    QCOMPARE(url->kind, LinkKind::Rtu);
    QCOMPARE(url->serial.device, QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(url->serial.baud, 19200);
    QCOMPARE(url->serial.parity, 'N');
    QCOMPARE(url->serial.dataBits, 8);
    QCOMPARE(url->serial.stopBits, 2);
    QCOMPARE(bar.framing(), Framing::Rtu);
}

void TestConnectionBar::emptyHostIsRefusedInPlace()
{
    ConnectionBar bar;
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    bar.findChild<QLineEdit *>(QStringLiteral("hostEdit"))->clear();
    QTest::mouseClick(bar.connectButton(), Qt::LeftButton);
    QCOMPARE(connectSpy.count(), 0);
    QVERIFY2(bar.errorText().contains(QLatin1String("host name or IP address")), qPrintable(bar.errorText()));
    // Typing in the field clears the message.
    QTest::keyClicks(bar.findChild<QLineEdit *>(QStringLiteral("hostEdit")), QStringLiteral("10.0.0.1"));
    QVERIFY(bar.errorText().isEmpty());
}

void TestConnectionBar::hostWithPortIsRefused()
{
    ConnectionBar bar;
    bar.findChild<QLineEdit *>(QStringLiteral("hostEdit"))->setText(QStringLiteral("10.0.0.1 502"));
    QVERIFY(!bar.url());
    QVERIFY2(bar.errorText().contains(QLatin1String("the port goes in Port")), qPrintable(bar.errorText()));
}

void TestConnectionBar::rtuNeedsEightDataBits()
{
    ConnectionBar bar;
    chooseKind(bar, LinkKind::Rtu);
    bar.findChild<QComboBox *>(QStringLiteral("serialPortCombo"))->setCurrentText(QStringLiteral("/dev/ttyS0"));
    auto *data = bar.findChild<QComboBox *>(QStringLiteral("dataBitsCombo"));
    data->setCurrentIndex(data->findData(7));
    QVERIFY(!bar.url());
    QVERIFY2(bar.errorText().contains(QLatin1String("8 data bits")), qPrintable(bar.errorText()));
}

void TestConnectionBar::setUrlRoundTrip_data()
{
    QTest::addColumn<QString>("url");
    QTest::newRow("tcp") << QStringLiteral("tcp://192.168.1.5:502?timeout=1500ms");
    QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:4001?timeout=1000ms");
    QTest::newRow("rtu") << QStringLiteral("rtu:///dev/ttyUSB1?baud=38400&parity=O&data=8&stop=1&timeout=200ms");
    QTest::newRow("ascii") << QStringLiteral("ascii:///dev/ttyS1?baud=9600&parity=E&data=7&stop=1&timeout=1000ms");
    // Options no field shows are kept (they were dropped: a session's rts=up came back without it).
    QTest::newRow("rtu, RTS direction") << QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&parity=E&rts=up&rts_before=500us&rts_after=1ms&timeout=1000ms");
    QTest::newRow("rtu, kernel RS-485") << QStringLiteral("rtu:///dev/ttyAMA0?baud=9600&rs485=kernel&turnaround=2ms&timeout=1000ms");
    QTest::newRow("tcp, reverse connection") << QStringLiteral("tcp://0.0.0.0:1502?mode=listen&busy=queue&timeout=1000ms");
    QTest::newRow("rtu-tcp, reverse connection") << QStringLiteral("rtu-tcp://127.0.0.1:4001?mode=listen&busy=refuse&timeout=800ms");
}

void TestConnectionBar::setUrlRoundTrip()
{
    QFETCH(QString, url);
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    QVERIFY2(parsed.url, qPrintable(parsed.error));
    ConnectionBar bar;
    bar.setUrl(*parsed.url);
    const std::optional<LinkUrl> back = bar.url();
    QVERIFY2(back, qPrintable(bar.errorText()));
    QCOMPARE(back->toString(), parsed.url->toString());
    // What no field shows is said beside the fields, and only that.
    auto *kept = bar.findChild<QLabel *>(QStringLiteral("keptOptionsLabel"));
    QVERIFY(kept);
    const bool hidden = url.contains(QLatin1String("rts")) || url.contains(QLatin1String("mode=")) || url.contains(QLatin1String("turnaround"));
    QCOMPARE(kept->isVisibleTo(&bar), hidden);
    QCOMPARE(bar.keptOptions().isEmpty(), !hidden);
    for (const QString &option : bar.keptOptions().split(QLatin1Char('&'), Qt::SkipEmptyParts))
        QVERIFY2(parsed.url->toString().contains(option) && kept->text().contains(option), qPrintable(option));
}

void TestConnectionBar::keptOptionsGoWithTheLinkType()
{
    const LinkUrl::Result parsed = LinkUrl::parse(QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&rts=up&rts_after=1ms"));
    QVERIFY(parsed.url);
    ConnectionBar bar;
    bar.setUrl(*parsed.url);
    QCOMPARE(bar.keptOptions(), QStringLiteral("rts=up&rts_after=1ms"));
    // Another port typed in: the options stay.
    bar.findChild<QComboBox *>(QStringLiteral("serialPortCombo"))->setCurrentText(QStringLiteral("/dev/ttyUSB1"));
    std::optional<LinkUrl> url = bar.url();
    QVERIFY2(url, qPrintable(bar.errorText()));
    QVERIFY2(url->toString().contains(QLatin1String("rts=up&rts_after=1ms")) && url->serial.device == QLatin1String("/dev/ttyUSB1"),
             qPrintable(url->toString()));
    // Another link type: they go, and the label says nothing.
    chooseKind(bar, LinkKind::Tcp);
    bar.findChild<QLineEdit *>(QStringLiteral("hostEdit"))->setText(QStringLiteral("127.0.0.1"));
    url = bar.url();
    QVERIFY2(url, qPrintable(bar.errorText()));
    QVERIFY2(!url->toString().contains(QLatin1String("rts")), qPrintable(url->toString()));
    QVERIFY(bar.keptOptions().isEmpty());
    QVERIFY(!bar.findChild<QLabel *>(QStringLiteral("keptOptionsLabel"))->isVisibleTo(&bar));
    // Back to RTU serial: the target set last still holds them.
    chooseKind(bar, LinkKind::Rtu);
    QCOMPARE(bar.keptOptions(), QStringLiteral("rts=up&rts_after=1ms"));
}

// Issue 28: Device pace… sets the device's pace on the target (gap=, warmup=, close=each), here taken
// from a profile's limits with poll --profile's margins; it goes into the URL Connect uses.
void TestConnectionBar::paceFromAProfile()
{
    QTemporaryDir dir;
    const QString profile = dir.filePath(QStringLiteral("slow.json"));
    QFile file(profile);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"name": "slow", "limits": {"minGapMs": 50, "warmUpMs": 500, "closesAfterAnswer": true, "maxQuantity": {"0x03": 16}},
                  "units": [{"id": 1}]})");
    file.close();
    ConnectionBar bar;
    chooseKind(bar, LinkKind::Tcp);
    bar.findChild<QLineEdit *>(QStringLiteral("hostEdit"))->setText(QStringLiteral("127.0.0.1"));
    QString status;
    QTimer::singleShot(0, &bar, [&] {
        auto *dialog = qobject_cast<PaceDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        QVERIFY(dialog->takeProfile(profile));
        status = dialog->findChild<QLabel *>(QStringLiteral("paceStatus"))->text();
        dialog->accept();
    });
    // Recent > Device pace… (a button of its own made the window too wide for 1024 pixels).
    QMenu *recent = bar.findChild<QToolButton *>(QStringLiteral("recentButton"))->menu();
    QVERIFY(recent->actions().contains(bar.paceAction()));
    bar.paceAction()->trigger();
    QVERIFY2(status.startsWith(QLatin1String("From slow.json: minGapMs 50 (51 ms, 1 ms to spare), warmUpMs 500 (550 ms, a tenth to "
                                             "spare), closesAfterAnswer. Its maxQuantity (0x03 16) is not applied")),
             qPrintable(status));
    QCOMPARE(bar.keptOptions(), QStringLiteral("gap=51ms&warmup=550ms&close=each"));
    QCOMPARE(bar.findChild<QLabel *>(QStringLiteral("keptOptionsLabel"))->text(), QStringLiteral("+ gap=51ms&warmup=550ms&close=each"));
    const std::optional<LinkUrl> url = bar.url();
    QVERIFY2(url, qPrintable(bar.errorText()));
    QCOMPARE(url->gap, std::chrono::milliseconds(51));
    QCOMPARE(url->warmUp, std::chrono::milliseconds(550));
    QVERIFY(url->closeAfterAnswer);
    // Set back to none by hand: the URL carries no pace.
    bar.setPace({});
    QVERIFY(bar.keptOptions().isEmpty());
    QVERIFY(!bar.url()->hasPace());
    // A serial link has no connection to hang up: the box is off there.
    chooseKind(bar, LinkKind::Rtu);
    bar.setPace({std::chrono::milliseconds(20), std::chrono::milliseconds(0), true});
    QCOMPARE(bar.keptOptions(), QStringLiteral("gap=20ms"));
}

void TestConnectionBar::connectAndDisconnectSignals()
{
    ConnectionBar bar;
    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    QSignalSpy disconnectSpy(&bar, &ConnectionBar::disconnectRequested);
    bar.connectButton()->click();
    QCOMPARE(connectSpy.count(), 1);
    bar.setConnected(true);
    QCOMPARE(bar.connectButton()->text(), QStringLiteral("Dis&connect"));
    QVERIFY(!bar.findChild<QComboBox *>(QStringLiteral("linkKindCombo"))->isEnabled());
    bar.connectButton()->click();
    QCOMPARE(disconnectSpy.count(), 1);
    QCOMPARE(connectSpy.count(), 1);
}

void TestConnectionBar::recentTargets()
{
    ConnectionBar bar;
    for (int i = 0; i < ConnectionBar::kMaxRecent + 3; ++i) {
        LinkUrl url;
        url.host = QStringLiteral("10.0.0.%1").arg(i);
        bar.addRecent(url);
    }
    LinkUrl again;
    again.host = QStringLiteral("10.0.0.5");
    bar.addRecent(again);
    const QStringList recent = bar.recentTargets();
    QCOMPARE(recent.size(), ConnectionBar::kMaxRecent);
    QCOMPARE(recent.first(), again.toString());
    QCOMPARE(recent.count(again.toString()), 1);
    // A second bar (the next start of the program) sees the same list.
    ConnectionBar next;
    QCOMPARE(next.recentTargets(), recent);
    // The menu shows a URL's options as written: '&' is no shortcut mark there (it read
    // "timeout=1000msgap=51ms" with the g underlined).
    LinkUrl paced;
    paced.host = QStringLiteral("10.0.0.99");
    paced.gap = std::chrono::milliseconds(51);
    paced.warmUp = std::chrono::milliseconds(550);
    next.addRecent(paced);
    QMenu *menu = next.findChild<QToolButton *>(QStringLiteral("recentButton"))->menu();
    QVERIFY(!menu->actions().isEmpty());
    QCOMPARE(menu->actions().first()->text(), QStringLiteral("tcp://10.0.0.99:502?gap=51ms&&warmup=550ms"));
    QCOMPARE(menu->actions().first()->iconText(), QStringLiteral("tcp://10.0.0.99:502?gap=51ms&warmup=550ms"));
}

namespace {

// Three files standing for the PEM files: the bar checks that they exist and can be read; what
// is in them is the link's business (TlsLink says when one holds no certificate).
struct TlsFiles {
    QTemporaryDir dir;
    QString cert = dir.filePath(QStringLiteral("client.pem"));
    QString key = dir.filePath(QStringLiteral("client.key"));
    QString ca = dir.filePath(QStringLiteral("ca.pem"));
    TlsFiles()
    {
        for (const QString &path : {cert, key, ca}) {
            QFile file(path);
            if (file.open(QIODevice::WriteOnly))
                file.write("-----BEGIN CERTIFICATE-----\n");
        }
    }
};

void setTlsFiles(ConnectionBar &bar, const QString &cert, const QString &key, const QString &ca)
{
    bar.tlsFiles()->certificateEdit()->setText(cert);
    bar.tlsFiles()->keyEdit()->setText(key);
    bar.tlsFiles()->caEdit()->setText(ca);
}

} // namespace

void TestConnectionBar::serialListIsReadAgainWhenOpened()
{
    ConnectionBar bar;
    chooseKind(bar, LinkKind::Rtu);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    auto *combo = bar.findChild<QComboBox *>(QStringLiteral("serialPortCombo"));
    QVERIFY(combo);
    // A port that was listed once and is gone (an adapter pulled out) leaves the list when it opens;
    // what the user typed stays.
    combo->addItem(QStringLiteral("/dev/ttyGONE0"));
    combo->setCurrentText(QStringLiteral("/dev/ttyUSB7"));
    combo->showPopup();
    QCOMPARE(combo->findText(QStringLiteral("/dev/ttyGONE0")), -1);
    QCOMPARE(combo->count(), int(QSerialPortInfo::availablePorts().size()));
    QCOMPARE(combo->currentText(), QStringLiteral("/dev/ttyUSB7"));
    combo->hidePopup();
}

void TestConnectionBar::tlsUrlCarriesTheFiles()
{
    TlsFiles files;
    QVERIFY(files.dir.isValid());
    ConnectionBar bar;
    QVERIFY(!bar.tlsFiles()->isVisibleTo(&bar));
    chooseKind(bar, LinkKind::Tls);
    QVERIFY(bar.tlsFiles()->isVisibleTo(&bar));
    QCOMPARE(bar.findChild<QSpinBox *>(QStringLiteral("portSpin"))->value(), 802); // MODBUS/TCP Security, 5.1
    bar.findChild<QLineEdit *>(QStringLiteral("hostEdit"))->setText(QStringLiteral("plc.example.org"));
    setTlsFiles(bar, files.cert, files.key, files.ca);
    const std::optional<LinkUrl> url = bar.url();
    QVERIFY2(url, qPrintable(bar.errorText()));
    QCOMPARE(url->kind, LinkKind::Tls);
    QCOMPARE(url->port, quint16(802));
    QCOMPARE(url->tls.certificate, files.cert);
    QCOMPARE(url->tls.privateKey, files.key);
    QCOMPARE(url->tls.caCertificates, files.ca);
    QVERIFY(url->toString().startsWith(QLatin1String("tls://plc.example.org:802?")));
    QCOMPARE(bar.framing(), Framing::Tcp);
    // Without client files (a server that needs none) and with the system's CAs.
    setTlsFiles(bar, {}, {}, {});
    QVERIFY2(bar.url(), qPrintable(bar.errorText()));
    // Back to plain Modbus TCP: the port follows, the files go out of sight.
    chooseKind(bar, LinkKind::Tcp);
    QCOMPARE(bar.findChild<QSpinBox *>(QStringLiteral("portSpin"))->value(), 502);
    QVERIFY(!bar.tlsFiles()->isVisibleTo(&bar));
}

void TestConnectionBar::tlsFileProblemsAreNamed_data()
{
    QTest::addColumn<QString>("cert");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("ca");
    QTest::addColumn<QString>("named");     // the error names this file
    QTest::addColumn<QString>("focusedEdit");
    QTest::newRow("missing certificate") << QStringLiteral("gone.pem") << QStringLiteral("key") << QStringLiteral("ca")
                                         << QStringLiteral("certificate file '%1gone.pem' does not exist")
                                         << QStringLiteral("tlsCertificateEdit");
    QTest::newRow("missing key") << QStringLiteral("cert") << QStringLiteral("nokey.pem") << QString()
                                 << QStringLiteral("private key file '%1nokey.pem' does not exist")
                                 << QStringLiteral("tlsKeyEdit");
    QTest::newRow("missing CA") << QString() << QString() << QStringLiteral("noca.pem")
                                << QStringLiteral("CA certificate file '%1noca.pem' does not exist")
                                << QStringLiteral("tlsCaEdit");
    QTest::newRow("folder as CA") << QString() << QString() << QStringLiteral(".")
                                  << QStringLiteral("is a folder") << QStringLiteral("tlsCaEdit");
    QTest::newRow("certificate without key") << QStringLiteral("cert") << QString() << QString()
                                             << QStringLiteral("without its private key") << QStringLiteral("tlsKeyEdit");
    QTest::newRow("key without certificate") << QString() << QStringLiteral("key") << QString()
                                             << QStringLiteral("without its certificate") << QStringLiteral("tlsCertificateEdit");
}

void TestConnectionBar::tlsFileProblemsAreNamed()
{
    QFETCH(QString, cert);
    QFETCH(QString, key);
    QFETCH(QString, ca);
    QFETCH(QString, named);
    QFETCH(QString, focusedEdit);
    TlsFiles files;
    const QString dir = files.dir.path() + QLatin1Char('/');
    // "cert", "key", "ca" stand for the existing files; other names are made missing in the folder.
    const auto path = [&](const QString &name, const QString &existing) {
        if (name.isEmpty() || name == QLatin1String("cert") || name == QLatin1String("key") || name == QLatin1String("ca"))
            return name.isEmpty() ? QString() : existing;
        return name == QLatin1String(".") ? files.dir.path() : dir + name;
    };
    ConnectionBar bar;
    bar.show();
    QVERIFY(QTest::qWaitForWindowActive(&bar));
    chooseKind(bar, LinkKind::Tls);
    setTlsFiles(bar, path(cert, files.cert), path(key, files.key), path(ca, files.ca));
    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    bar.connectButton()->click();
    QCOMPARE(connectSpy.count(), 0);
    const QString expected = named.contains(QLatin1String("%1")) ? named.arg(dir) : named;
    QVERIFY2(bar.errorText().contains(expected), qPrintable(bar.errorText()));
    QCOMPARE(QApplication::focusWidget() ? QApplication::focusWidget()->objectName() : QString(), focusedEdit);
    // Typing in a file field takes the message away.
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_End);
    QTest::keyClicks(QApplication::focusWidget(), QStringLiteral("x"));
    QVERIFY(bar.errorText().isEmpty());
}

void TestConnectionBar::tlsRecentTargetKeepsTheFiles()
{
    TlsFiles files;
    ConnectionBar bar;
    chooseKind(bar, LinkKind::Tls);
    bar.findChild<QLineEdit *>(QStringLiteral("hostEdit"))->setText(QStringLiteral("10.1.2.3"));
    setTlsFiles(bar, files.cert, files.key, files.ca);
    const std::optional<LinkUrl> url = bar.url();
    QVERIFY2(url, qPrintable(bar.errorText()));
    bar.addRecent(*url);
    QCOMPARE(bar.recentTargets().first(), url->toString());

    // The next start: choosing the recent target brings the files back.
    ConnectionBar next;
    auto *recent = next.findChild<QToolButton *>(QStringLiteral("recentButton"));
    QVERIFY(recent && recent->menu());
    const QList<QAction *> actions = recent->menu()->actions();
    QVERIFY(!actions.isEmpty());
    actions.first()->trigger();
    QCOMPARE(next.tlsFiles()->certificateEdit()->text(), files.cert);
    QCOMPARE(next.tlsFiles()->keyEdit()->text(), files.key);
    QCOMPARE(next.tlsFiles()->caEdit()->text(), files.ca);
    QVERIFY(next.tlsFiles()->isVisibleTo(&next));
    const std::optional<LinkUrl> again = next.url();
    QVERIFY2(again, qPrintable(next.errorText()));
    QCOMPARE(again->toString(), url->toString());
    // A file removed since: named in place when connecting.
    QFile::remove(files.key);
    QVERIFY(!next.url());
    QVERIFY2(next.errorText().contains(files.key), qPrintable(next.errorText()));
}

void TestConnectionBar::screenshot()
{
    ConnectionBar bar;
    bar.resize(1400, bar.sizeHint().height());
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QVERIFY(guitest::saveShot(&bar, QStringLiteral("connectionbar-network.png")));
    chooseKind(bar, LinkKind::Rtu);
    bar.findChild<QComboBox *>(QStringLiteral("serialPortCombo"))->setCurrentText(QString());
    QVERIFY(!bar.url());
    QVERIFY(guitest::saveShot(&bar, QStringLiteral("connectionbar-serial-error.png")));
    chooseKind(bar, LinkKind::Tls);
    bar.tlsFiles()->certificateEdit()->setText(QStringLiteral("/etc/modbus/client.pem"));
    bar.tlsFiles()->keyEdit()->setText(QStringLiteral("/etc/modbus/client.key"));
    QVERIFY(!bar.url());
    bar.resize(1400, bar.sizeHint().height());
    QVERIFY(guitest::saveShot(&bar, QStringLiteral("connectionbar-tls-error.png")));
}

QTEST_MAIN(TestConnectionBar)
#include "tst_connectionbar.moc"
