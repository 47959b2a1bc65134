#include "networklink.h"

namespace mbscope {

NetworkLink::NetworkLink(const LinkUrl &url, QObject *parent)
    : Link(url, parent)
    , m_connectTimer(this) // a child, so that moveToThread() takes it along
{
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        if (state() == State::Opening)
            onConnectTimeout();
    });
}

void NetworkLink::open()
{
    if (state() != State::Closed)
        return;
    setState(State::Opening);
    QMetaObject::invokeMethod(this, [this] {
        if (state() == State::Opening)
            startOpen();
    }, Qt::QueuedConnection);
}

void NetworkLink::close()
{
    if (state() == State::Closed)
        return;
    teardown();
    setClosed(QStringLiteral("closed on request"));
}

} // namespace mbscope
