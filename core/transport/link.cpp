#include "link.h"

namespace mbscope {

Link::Link(const LinkUrl &url, QObject *parent)
    : QObject(parent)
    , m_url(url)
{
    qRegisterMetaType<mbscope::LinkError>();
}

Link::~Link() = default;

bool Link::refuseWriteWhenListening(qsizetype byteCount)
{
    if (!m_listenOnly)
        return false;
    reportError(LinkError::Kind::Config,
                QStringLiteral("%1 bytes not sent: the link is listen-only (a monitor never writes to the line)").arg(byteCount));
    return true;
}

void Link::reportError(LinkError::Kind kind, const QString &what)
{
    m_lastError.kind = kind;
    m_lastError.message = m_url.toString() + QStringLiteral(": ") + what;
    Q_EMIT errorOccurred(m_lastError);
}

void Link::setClosed(const QString &reason)
{
    const State was = m_state;
    m_state = State::Closed;
    if (was != State::Closed)
        Q_EMIT closed(reason);
}

void Link::reportLoss(LinkError::Kind kind, const QString &what)
{
    m_state = State::Closed;
    reportError(kind, what);
    Q_EMIT closed(m_lastError.message);
}

QString Link::osAnswer(const QString &errorString)
{
    if (errorString.isEmpty())
        return QStringLiteral("no reason given");
    QString text = errorString;
    if (text.size() > 1 && text.at(0).isUpper() && text.at(1).isLower())
        text[0] = text.at(0).toLower();
    if (text.endsWith(QLatin1Char('.')))
        text.chop(1);
    return text;
}

} // namespace mbscope

#include "moc_link.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
