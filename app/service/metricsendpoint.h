#pragma once

#include "common/listenaddress.h"

#include <QtCore/QObject>
#include <QtCore/QUrl>

#include <functional>
#include <memory>

class QHttpServer;
class QTcpServer;

namespace mbscope {
class MetricsRegistry;
}

namespace mbscope::app {

// The HTTP endpoint Prometheus scrapes (Qt HttpServer): GET /metrics answers the registry in
// OpenMetrics when the scraper asks for it (Prometheus does), in the text format 0.0.4 otherwise;
// / answers a line that points to /metrics. beforeScrape runs first, to bring values that are read
// rather than pushed (process memory and CPU) up to date.
class MetricsEndpoint : public QObject
{
    Q_OBJECT
public:
    MetricsEndpoint(const MetricsRegistry &registry, QObject *parent = nullptr);
    ~MetricsEndpoint() override;

    void setBeforeScrape(std::function<void()> hook) { m_beforeScrape = std::move(hook); }
    // False with a message saying why (port in use, address not on this machine).
    [[nodiscard]] bool listen(const ListenAddress &where, QString *error);
    // http://127.0.0.1:PORT/metrics, with the port the OS gave for port 0.
    [[nodiscard]] QUrl url() const { return m_url; }
    [[nodiscard]] quint64 scrapes() const { return m_scrapes; }

private:
    const MetricsRegistry &m_registry;
    std::unique_ptr<QHttpServer> m_server;
    QTcpServer *m_tcp = nullptr;
    std::function<void()> m_beforeScrape;
    QUrl m_url;
    quint64 m_scrapes = 0;
};

} // namespace mbscope::app
