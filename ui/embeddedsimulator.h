#pragma once

#include "sim/deviceprofile.h"
#include "transport/linkurl.h"

#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QThread>

#include <memory>

namespace mbscope {

class FaultInjector;
class GeneratorDriver;
class Simulator;

// The built-in simulator the window starts on a first run: one shipped device profile served on
// one endpoint, on a thread of its own so that answering never competes with painting (and a
// poll measured from the window measures the engine, not the GUI thread's backlog).
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
    [[nodiscard]] bool isRunning() const { return m_simulator != nullptr; }
    [[nodiscard]] const Started &started() const { return m_started; }
    [[nodiscard]] QString profileName() const { return m_profile; }
    // The profile served (names and scaling for the register table).
    [[nodiscard]] const DeviceProfile &profile() const { return m_loaded; }

private:
    QThread m_thread;
    QObject *m_anchor = nullptr; // lives in m_thread: where the simulator's objects are deleted
    Simulator *m_simulator = nullptr;
    GeneratorDriver *m_driver = nullptr;
    std::unique_ptr<FaultInjector> m_injector;
    Started m_started;
    QString m_profile;
    DeviceProfile m_loaded;
};

} // namespace mbscope
