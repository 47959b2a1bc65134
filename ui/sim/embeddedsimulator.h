#pragma once

#include "profile/deviceprofile.h"
#include "sim/simulatorhost.h"
#include "transport/linkurl.h"

#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QString>

namespace mbscope {


// The built-in simulator the window starts on a first run: one shipped device profile served on
// one endpoint by a SimulatorHost (its own thread, so that answering never competes with
// painting, and a poll measured from the window measures the engine, not the GUI thread's
// backlog). The simulator panel shows it as one of its running entries (host()).
//
// When the preferred port is taken (another mbscope, a real device server on this machine) it
// listens on a free loopback port instead and says so in note(): the user sees where it went.
class EmbeddedSimulator : public QObject
{
    Q_OBJECT
public:
    struct Started {
        bool ok = false;
        LinkUrl url;   // the endpoint as bound, ready to connect to
        QString note;  // set when it is not where it was asked to be
        QString error; // why nothing listens (!ok)
    };

    explicit EmbeddedSimulator(QObject *parent = nullptr);
    ~EmbeddedSimulator() override;

    // Loads the profile ("rosrao-gamma" or a file) and listens on url (e.g.
    // "rtu-tcp://127.0.0.1:4001"; port 0: the OS chooses). Stops what ran before.
    Started start(const QString &profile, const QString &url);
    void stop();
    // False also once the simulator panel stopped it.
    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] const Started &started() const { return m_started; }
    [[nodiscard]] QString profileName() const { return m_profile; }
    // The profile served (names and scaling for the register table).
    [[nodiscard]] const DeviceProfile &profile() const { return m_loaded; }
    // The running simulator (nullptr when none was started or it was stopped).
    [[nodiscard]] SimulatorHost *host() const;

Q_SIGNALS:
    // A host was started (the panel lists it).
    void hostStarted(mbscope::SimulatorHost *host);

private:
    QPointer<SimulatorHost> m_host;
    Started m_started;
    QString m_profile;
    DeviceProfile m_loaded;
};

} // namespace mbscope
