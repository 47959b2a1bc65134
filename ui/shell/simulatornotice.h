#pragma once

#include "link/linkcontroller.h"

#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {

class EmbeddedSimulator;
class NoticeBanner;

// What the window's banner says about the built-in simulator: that the window is connected to
// it and not to a device (on the first run, or when the preferences start it), then what the link
// does now (disconnected, listening only, connected again), and nothing once the link goes
// elsewhere.
class SimulatorNotice : public QObject
{
    Q_OBJECT
public:
    SimulatorNotice(EmbeddedSimulator *simulator, LinkController *link, NoticeBanner *banner, QObject *parent);

    // The simulator started with profile on url (note: where it is not where it was asked to be).
    void showStarted(const QString &profile, const QString &note);
    // The link's new state, while the banner is shown.
    void follow(LinkController::State state);

private:
    EmbeddedSimulator *m_simulator;
    LinkController *m_link;
    NoticeBanner *m_banner;
    QString m_connected; // the notice shown when the simulator started
};

} // namespace mbscope
