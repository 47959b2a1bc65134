#include "simulatornotice.h"

#include "common/noticebanner.h"
#include "link/taprunner.h"
#include "sim/embeddedsimulator.h"

namespace mbscope {

SimulatorNotice::SimulatorNotice(EmbeddedSimulator *simulator, LinkController *link, NoticeBanner *banner, QObject *parent)
    : QObject(parent)
    , m_simulator(simulator)
    , m_link(link)
    , m_banner(banner)
{
}

void SimulatorNotice::showStarted(const QString &profile, const QString &note)
{
    m_connected = tr("<b>Connected to mbscope's built-in simulator</b>, not to a device: a RosRao gamma detector "
                        "(profile <code>%1</code>) answering on <code>%2</code>. Press <b>Send</b> to read its 22 "
                        "registers. To talk to a real device, press <b>Disconnect</b>, choose its link type, host and "
                        "port (or serial port) and press <b>Connect</b>.")
                         .arg(profile, m_simulator->started().url.toString().toHtmlEscaped());
    if (!note.isEmpty())
        m_connected += QStringLiteral("<br>") + note.toHtmlEscaped();
    m_banner->showNotice(m_connected);
}

void SimulatorNotice::follow(LinkController::State state)
{
    // The banner says what the link does now (try-out 8, item 4: after Disconnect, Listen and
    // Connect, it still said "Disconnected ... press Connect" beside "listening only").
    const LinkUrl simulator = m_simulator->started().url;
    const QString where = simulator.toString().toHtmlEscaped();
    if (m_link->isTapping() && state != LinkController::State::Disconnected) {
        // A tap in front of the simulator (the guide's first tap): where the masters go.
        if (m_link->url().port != simulator.port || m_link->url().kind != simulator.kind) {
            m_banner->hide();
            return;
        }
        m_banner->showNotice(tr("<b>Tap</b> in front of the built-in simulator on <code>%1</code>: point a master "
                                "(mbpoll, a PLC, <code>mbscope read</code>) at <code>%2</code>; each request and its "
                                "answer are listed twice in Traffic, the master's and the device's leg.")
                                 .arg(where, m_link->tap()->endpoints().join(QStringLiteral(", ")).toHtmlEscaped()));
        return;
    }
    if (state == LinkController::State::Disconnected || state == LinkController::State::Failed) {
        m_banner->showNotice(tr("Disconnected. The built-in simulator still answers on <code>%1</code>: press "
                                "<b>Connect</b> to use it again, or choose a real device's link type, host "
                                "and port (or serial port) first.")
                                 .arg(where));
        return;
    }
    // Not the simulator any more: the banner has nothing to say about this link.
    if (m_link->url().port != simulator.port || m_link->url().kind != simulator.kind) {
        m_banner->hide();
        return;
    }
    if (m_link->isListening()) {
        m_banner->showNotice(tr("<b>Listening only</b> to the built-in simulator on <code>%1</code>: nothing is sent, "
                                "and the simulator answers only requests, so the traffic stays empty unless another "
                                "master polls it. Untick <b>Listen</b> and press <b>Connect</b> to send it requests.")
                                 .arg(where));
        return;
    }
    m_banner->showNotice(m_connected);
}

} // namespace mbscope
