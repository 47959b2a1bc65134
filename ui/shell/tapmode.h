#pragma once

#include <QtCore/QObject>

class QStatusBar;

namespace mbscope {

class ConnectionBar;
class LinkController;
class RequestComposer;
class TrafficMonitor;

// The window's inline tap, wired: the connection bar's Tap starts it on the link controller
// (LinkController::tapTo), both legs reach the traffic list (and from there the Answer tab's
// decode view), the tap's counters the bar's Tap row, and the composer says why it does not send
// while the tap runs. What goes wrong is said where it happened: a URL that cannot listen and a
// target that fails in the bar, the tap's start in the status bar.
class TapMode : public QObject
{
    Q_OBJECT
public:
    TapMode(QObject *parent, ConnectionBar *bar, LinkController *link, TrafficMonitor *traffic,
            RequestComposer *composer, QStatusBar *status);
};

} // namespace mbscope
