// Listen only in the window (issue 13, item 5): the connection bar's Listen only box turns Connect
// into "listen to this bus", offered for the links a monitor can listen on; the LinkController
// then runs a bus monitor whose exchanges reach the window as transactions, and never writes to
// the line (the test holds the pty's other end and reads nothing back); the composer's Send and
// Poll are off and say why.
#include "compose/rawrequesteditor.h"
#include "compose/requestcomposer.h"
#include "link/connectionbar.h"
#include "link/linkcontroller.h"
#include "protocol/checksum.h"

#include <QtGui/QAction>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

using namespace mbscope;

namespace {

QByteArray rtu(const char *hex)
{
    QByteArray frame = QByteArray::fromHex(hex);
    const quint16 crc = checksum::crc16Modbus(frame);
    frame.append(char(crc & 0xff));
    frame.append(char(crc >> 8));
    return frame;
}

// A pseudo-terminal: the test writes the bus's bytes into its controller; the monitor opens the device.
struct Pty {
    int controller = -1;
    QString device;
    ~Pty()
    {
        if (controller >= 0)
            ::close(controller);
    }
    bool open()
    {
        controller = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (controller < 0 || ::grantpt(controller) != 0 || ::unlockpt(controller) != 0)
            return false;
        device = QString::fromLocal8Bit(::ptsname(controller));
        return true;
    }
    void write(const QByteArray &bytes) const { QVERIFY(::write(controller, bytes.constData(), size_t(bytes.size())) == bytes.size()); }
    // What the device's side wrote (the monitor must write nothing).
    [[nodiscard]] QByteArray readBack() const
    {
        char buffer[256];
        const ssize_t n = ::read(controller, buffer, sizeof buffer);
        return n > 0 ? QByteArray(buffer, n) : QByteArray();
    }
};

} // namespace

class TestListenOnly : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void barOffersListenOnlyForBusLinks();
    void controllerListensAndNeverWrites();
    void composerSaysWhySendIsOff();
};

void TestListenOnly::barOffersListenOnlyForBusLinks()
{
    ConnectionBar bar;
    auto *check = bar.findChild<QCheckBox *>(QStringLiteral("listenOnlyCheck"));
    QVERIFY(check);
    bar.setUrl(*LinkUrl::parse(u"tcp://127.0.0.1:502").url);
    QVERIFY(!check->isEnabled());
    check->setChecked(true);
    QVERIFY(!bar.isListenOnly()); // Modbus TCP has no bus to listen to
    bar.setUrl(*LinkUrl::parse(u"rtu-tcp://127.0.0.1:4001").url);
    QVERIFY(check->isEnabled());
    QVERIFY(bar.isListenOnly());

    QSignalSpy listen(&bar, &ConnectionBar::listenRequested);
    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    bar.connectButton()->click();
    QCOMPARE(listen.size(), 1);
    QCOMPARE(connectSpy.size(), 0);
    QCOMPARE(listen.at(0).at(0).value<LinkUrl>().kind, LinkKind::RtuTcp);
    bar.setConnected(true);
    QVERIFY(!check->isEnabled()); // a live link's settings are locked
}

void TestListenOnly::controllerListensAndNeverWrites()
{
    Pty pty;
    QVERIFY(pty.open());
    LinkController controller;
    QSignalSpy states(&controller, &LinkController::stateChanged);
    QSignalSpy transactions(&controller, &LinkController::transactionsFinished);
    controller.listenTo(*LinkUrl::parse(QStringLiteral("rtu://%1?baud=9600&parity=N").arg(pty.device)).url);
    QVERIFY(controller.isListening());
    QTRY_COMPARE_WITH_TIMEOUT(controller.state(), LinkController::State::Connected, 10000);
    QVERIFY2(controller.message().contains(QStringLiteral("listening only")), qPrintable(controller.message()));
    QCOMPARE(controller.send(rtu("010300000002")), quint64(0)); // refused: nothing can be sent
    QVERIFY(!controller.startPoll(rtu("010300000002"), 100, 1));

    // Another master's read and the slave's answer, then a read whose answer the line damaged.
    pty.write(rtu("010300000002"));
    QTest::qWait(20);
    pty.write(rtu("01030400450046"));
    QTest::qWait(20);
    pty.write(rtu("010300000002"));
    QTest::qWait(20);
    QByteArray damaged = rtu("01030400450046");
    damaged[5] = char(damaged[5] ^ 0x01);
    pty.write(damaged);
    QList<Transaction> seen;
    QTRY_VERIFY_WITH_TIMEOUT(([&] {
                                 while (!transactions.isEmpty())
                                     seen += transactions.takeFirst().at(0).value<QList<Transaction>>();
                                 return seen.size() >= 2;
                             }()),
                             10000);
    QCOMPARE(seen.size(), 2);
    QCOMPARE(seen.at(0).status, TransactionStatus::Ok);
    QCOMPARE(seen.at(0).request, rtu("010300000002"));
    QCOMPARE(seen.at(0).response, rtu("01030400450046"));
    QVERIFY(seen.at(0).latencyNs() >= 0);
    QCOMPARE(seen.at(1).status, TransactionStatus::CrcError);
    QCOMPARE(pty.readBack(), QByteArray()); // the monitor wrote nothing to the line
    QCOMPARE(errno, EAGAIN);

    controller.disconnectLink();
    QVERIFY(!controller.isListening());
    QCOMPARE(controller.state(), LinkController::State::Disconnected);
}

void TestListenOnly::composerSaysWhySendIsOff()
{
    RequestComposer composer;
    composer.rawEditor()->setText(QStringLiteral("01 03 00 00 00 02 C4 0B"));
    composer.setLinkReady(true);
    QVERIFY(composer.sendAction()->isEnabled());
    composer.setListenOnly(true);
    QVERIFY(!composer.sendAction()->isEnabled());
    QVERIFY(!composer.pollAction()->isEnabled());
    bool hinted = false;
    for (const QLabel *label : composer.findChildren<QLabel *>())
        hinted = hinted || label->text().contains(QStringLiteral("Listen only"));
    QVERIFY(hinted);
    for (const QPushButton *button : composer.findChildren<QPushButton *>()) {
        if (!button->isEnabled() && !button->toolTip().isEmpty() && button->toolTip().contains(QStringLiteral("listen-only")))
            return;
    }
    QFAIL("no disabled button says the link is listen-only");
}

QTEST_MAIN(TestListenOnly)
#include "tst_listenonly.moc"
