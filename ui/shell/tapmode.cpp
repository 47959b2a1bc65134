#include "tapmode.h"

#include "compose/requestcomposer.h"
#include "link/connectionbar.h"
#include "link/linkcontroller.h"
#include "link/tapfields.h"
#include "link/taprunner.h"
#include "traffic/trafficmonitor.h"

#include <QtWidgets/QStatusBar>

namespace mbscope {

TapMode::TapMode(QObject *parent, ConnectionBar *bar, LinkController *link, TrafficMonitor *traffic,
                 RequestComposer *composer, QStatusBar *status)
    : QObject(parent)
{
    connect(bar, &ConnectionBar::tapRequested, link, &LinkController::tapTo);
    connect(link, &LinkController::tapFramesLogged, traffic, &TrafficMonitor::appendNamedFrames);
    connect(link, &LinkController::tapCountersChanged, bar->tapFields(), &TapFields::showCounters);
    connect(link, &LinkController::tapFailed, bar, [bar, status](const QString &message) {
        bar->showError(tr("The tap could not start: %1. Choose another port in Masters connect to (port 0: any free "
                          "port), or stop the program that listens there.")
                           .arg(message));
        status->showMessage(tr("The tap did not start"), 10000);
    });
    // After the window's own handler of the state: the tap's words replace the link's.
    connect(link, &LinkController::stateChanged, this, [bar, link, composer, status](LinkController::State state, const QString &message) {
        composer->setTapping(link->isTapping());
        if (!link->isTapping())
            return;
        if (state == LinkController::State::Failed) {
            bar->showError(tr("The tap's target failed: %1. The masters get exception 0B (or silence) until it "
                              "answers again; their next request opens the link again. Press Disconnect to stop the tap.")
                               .arg(message));
        } else if (state == LinkController::State::Connected && link->tap()) {
            status->showMessage(tr("Tap started, the same as: mbscope tap %1")
                                    .arg(link->tap()->setup().arguments().join(QLatin1Char(' '))),
                                15000);
        }
    });
}

} // namespace mbscope
