#pragma once

// Shared by the link tests: records what a link signalled, in order.

#include "transport/link.h"

#include <QtCore/QList>
#include <QtCore/QStringList>
#include <QtTest/QtTest>

namespace linktesting {

inline const char *kindName(mbscope::LinkError::Kind kind)
{
    using Kind = mbscope::LinkError::Kind;
    switch (kind) {
    case Kind::None: return "none";
    case Kind::Config: return "config";
    case Kind::NotFound: return "notfound";
    case Kind::Permission: return "permission";
    case Kind::Refused: return "refused";
    case Kind::Timeout: return "timeout";
    case Kind::Closed: return "closed";
    case Kind::Io: return "io";
    case Kind::Handshake: return "handshake";
    }
    return "?";
}

class Recorder : public QObject
{
public:
    explicit Recorder(mbscope::Link *link)
    {
        using mbscope::Link;
        connect(link, &Link::opened, this, [this] {
            ++opened;
            events.append(QStringLiteral("opened"));
        });
        connect(link, &Link::closed, this, [this](const QString &reason) {
            ++closed;
            closedReasons.append(reason);
            events.append(QStringLiteral("closed"));
        });
        connect(link, &Link::bytesWritten, this, [this](qint64 ns) {
            writtenNs.append(ns);
            events.append(QStringLiteral("written"));
        });
        connect(link, &Link::bytesReceived, this, [this](const QByteArray &bytes, qint64 first, qint64 last) {
            received += bytes;
            chunks.append(bytes);
            firstNs.append(first);
            lastNs.append(last);
            events.append(QStringLiteral("received"));
        });
        connect(link, &Link::errorOccurred, this, [this](const mbscope::LinkError &error) {
            errors.append(error);
            events.append(QStringLiteral("error ") + QLatin1String(kindName(error.kind)));
        });
    }

    [[nodiscard]] QString lastMessage() const { return errors.isEmpty() ? QString() : errors.last().message; }

    int opened = 0;
    int closed = 0;
    QStringList closedReasons;
    QList<qint64> writtenNs;
    QByteArray received;
    QList<QByteArray> chunks;
    QList<qint64> firstNs;
    QList<qint64> lastNs;
    QList<mbscope::LinkError> errors;
    QStringList events;
};

} // namespace linktesting
