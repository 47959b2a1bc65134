#include "service/metricsendpoint.h"

#include "metrics/metricstext.h"

#include <QtHttpServer/QHttpServer>
#include <QtHttpServer/QHttpServerRequest>
#include <QtHttpServer/QHttpServerResponse>
#include <QtNetwork/QTcpServer>

namespace mbscope::app {

MetricsEndpoint::MetricsEndpoint(const MetricsRegistry &registry, QObject *parent)
    : QObject(parent)
    , m_registry(registry)
    , m_server(std::make_unique<QHttpServer>())
{
    m_server->route(QStringLiteral("/metrics"), [this](const QHttpServerRequest &request) {
        if (m_beforeScrape)
            m_beforeScrape();
        ++m_scrapes;
        const MetricsText::Format format = MetricsText::negotiate(request.value("Accept"));
        return QHttpServerResponse(MetricsText::contentType(format), MetricsText::write(m_registry, format));
    });
    m_server->route(QStringLiteral("/"), [] {
        return QHttpServerResponse(QByteArrayLiteral("text/plain; charset=utf-8"),
                                   QByteArrayLiteral("mbscope watch: metrics at /metrics\n"));
    });
}

MetricsEndpoint::~MetricsEndpoint() = default;

bool MetricsEndpoint::listen(const ListenAddress &where, QString *error)
{
    auto tcp = std::make_unique<QTcpServer>();
    if (!tcp->listen(where.address, where.port)) {
        *error = QStringLiteral("cannot listen on %1:%2: %3").arg(where.hostText()).arg(where.port).arg(tcp->errorString());
        return false;
    }
    m_tcp = tcp.release();
    m_server->bind(m_tcp); // the server takes the socket over
    ListenAddress bound = where;
    bound.port = m_tcp->serverPort();
    QString host = bound.hostText();
    if (where.address == QHostAddress::Any)
        host = QStringLiteral("0.0.0.0");
    m_url = QUrl(QStringLiteral("http://%1:%2/metrics").arg(host).arg(bound.port));
    return true;
}

} // namespace mbscope::app
