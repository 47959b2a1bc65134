// A serial port the user may not open: the window says so in the connection bar, in the link's
// words, with the group that owns the device ("dialout") and how to join it. The test runs as any
// user (root opens everything), so the link is a stand-in that fails as SerialLink fails on
// EACCES, with SerialLink's own message for a device file owned by group dialout.
#include "link/connectionbar.h"
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "shell/mainwindow.h"

#include "engine/transactionengine.h"
#include "transport/link.h"
#include "transport/seriallink.h"

#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtWidgets/QPushButton>
#include <QtTest/QtTest>

#include <cerrno>
#include <grp.h>
#include <unistd.h>

using namespace mbscope;

namespace {

// Fails to open as SerialLink does when open(2) answers EACCES.
class DeniedSerialLink : public Link
{
public:
    DeniedSerialLink(const LinkUrl &url, QObject *parent)
        : Link(url, parent)
    {
    }
    void open() override
    {
        setState(State::Closed);
        reportError(LinkError::Kind::Permission, SerialLink::openFailureMessage(url().serial.device, EACCES));
    }
    void close() override { setState(State::Closed); }
    bool write(const QByteArray &) override { return false; }
};

} // namespace

class TestSerialPermission : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void permissionDeniedNamesTheGroup();
};

void TestSerialPermission::permissionDeniedNamesTheGroup()
{
    const group *dialout = getgrnam("dialout");
    if (!dialout)
        QSKIP("no 'dialout' group on this system (Debian creates it with the base system)");
    QTemporaryDir dir;
    const QString device = dir.filePath(QStringLiteral("ttyUSB0"));
    {
        QFile file(device);
        QVERIFY(file.open(QIODevice::WriteOnly));
    }
    if (::chown(QFile::encodeName(device).constData(), uid_t(-1), dialout->gr_gid) != 0)
        QSKIP("cannot give the stand-in device file to group dialout (chown needs membership or root)");

    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    LinkUrl url;
    url.kind = LinkKind::Rtu;
    url.serial.device = device;
    window.connectionBar()->setUrl(url);
    // Connect opens the link at once: the stand-in link is named before it.
    window.controller()->setLinkFactory(
        [](const LinkUrl &target, QObject *parent) -> Link * { return new DeniedSerialLink(target, parent); });
    window.connectionBar()->connectButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Failed, 5000);
    const QString shown = window.connectionBar()->errorText();
    QVERIFY2(shown.contains(QLatin1String("permission denied opening ") + device), qPrintable(shown));
    QVERIFY2(shown.contains(QLatin1String("group 'dialout'")), qPrintable(shown));
    QVERIFY2(shown.contains(QLatin1String("sudo usermod -aG dialout $USER")), qPrintable(shown));
    QVERIFY(guitest::saveShot(window.connectionBar(), QStringLiteral("connectionbar-serial-permission.png")));
}

QTEST_MAIN(TestSerialPermission)
#include "tst_serialpermission.moc"
