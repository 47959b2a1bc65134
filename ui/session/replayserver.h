#pragma once

#include "replay/replayresponder.h"
#include "transport/linkurl.h"

#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QThread>

#include <memory>

namespace mbscope {

class ReplayScript;
class Simulator;

// The device side of replay in the window (what `mbscope replay --serve URL` does): a Simulator
// whose units answer with a recording's answers through the core's ReplayResponder, on one
// endpoint, on a thread of its own so that serving never waits on painting. Everything of the
// simulator is made, used and deleted in that thread; the GUI asks it through blocking calls.
class ReplayServer : public QObject
{
    Q_OBJECT
public:
    explicit ReplayServer(QObject *parent = nullptr);
    ~ReplayServer() override;

    // Listens on url (tcp://, rtu-tcp://, udp://, rtu://...; port 0: the OS chooses), stopping
    // what served before. False with *error saying why nothing listens.
    bool start(const ReplayScript &script, const QString &url, ReplayResponder::Unrecorded unrecorded, double speed,
               QString *error);
    void stop();
    [[nodiscard]] bool isServing() const { return m_simulator != nullptr; }
    // The endpoint as bound: a client connects here.
    [[nodiscard]] const LinkUrl &boundUrl() const { return m_bound; }
    // Answers served so far (asked of the serving thread).
    [[nodiscard]] ReplayResponder::Counters counters() const;
    [[nodiscard]] qsizetype distinctRequests() const { return m_distinct; }

Q_SIGNALS:
    void servingChanged(bool serving);

private:
    QThread m_thread;
    QObject *m_anchor = nullptr; // lives in m_thread
    Simulator *m_simulator = nullptr;
    std::unique_ptr<ReplayResponder> m_responder;
    LinkUrl m_bound;
    qsizetype m_distinct = 0;
};

} // namespace mbscope
