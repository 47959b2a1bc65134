#pragma once

// Real peers of the watch service, started by the tests on loopback ports of their own with
// generated configurations and stopped when the objects go: Debian's prometheus (scraping
// `mbscope watch`), mosquitto (the broker) and mosquitto_sub (a subscriber); plus a small HTTP GET
// and the reading of a metrics exposition. Each start() says why it could not run (for QSKIP).

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QProcess>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QTemporaryDir>

#include <functional>
#include <memory>
#include <optional>

namespace mbscope::testcli {

struct HttpReply {
    int status = 0; // 0: no answer
    QByteArray contentType;
    QByteArray body;
    QString error;
};

// GET url (loopback), waiting up to timeoutMs; accept: the Accept header, when not empty.
[[nodiscard]] HttpReply httpGet(const QString &url, const QByteArray &accept = {}, int timeoutMs = 10000);

// The value of the first sample of metric whose labels include every one of labels
// ({"name", "counts"}), in a text exposition; nullopt when there is none.
[[nodiscard]] std::optional<double> metricValue(const QByteArray &exposition, const QString &metric,
                                                const QMap<QString, QString> &labels = {});
// The sum of every sample of metric.
[[nodiscard]] double metricSum(const QByteArray &exposition, const QString &metric);

// A long-running child process (mbscope watch, simulate, a peer) with its output collected.
class ChildProcess
{
public:
    ~ChildProcess() { stop(); }
    bool start(const QString &program, const QStringList &arguments, QString *error);
    // Waits until the collected standard output or error holds text.
    bool waitForOutput(const QByteArray &text, int timeoutMs);
    // SIGTERM (or SIGKILL), then wait; returns the exit code (-1 when it did not end).
    int stop(int signal = 15, int timeoutMs = 10000);
    void signal(int number);
    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] qint64 pid() const;
    [[nodiscard]] QByteArray output(); // stdout and stderr so far, merged
    [[nodiscard]] QProcess *process() { return m_process.get(); }

private:
    void drain();
    std::unique_ptr<QProcess> m_process;
    QByteArray m_output;
};

// `mbscope simulate --profile PROFILE --listen tcp://127.0.0.1:PORT` (port 0: any), its URL read.
class Simulator
{
public:
    bool start(const QString &profile, quint16 port, QString *error);
    void stop() { m_child.stop(2); }
    [[nodiscard]] QString url() const { return m_url; }
    [[nodiscard]] quint16 port() const;
    [[nodiscard]] qint64 pid() const { return m_child.pid(); }

private:
    ChildProcess m_child;
    QString m_url;
};

class Prometheus
{
public:
    ~Prometheus() { stop(); }
    // Scrapes each of targets ("127.0.0.1:PORT") every scrapeInterval ("1s") as job "mbscope".
    bool start(const QStringList &targets, const QString &scrapeInterval, QString *error);
    void stop() { m_child.stop(); }
    // GET /api/v1/query?query=... : the "data" object, empty on error (error says).
    [[nodiscard]] QJsonObject query(const QString &promql, QString *error = nullptr);
    // The first result's value of an instant query, nullopt when the result is empty.
    [[nodiscard]] std::optional<double> scalar(const QString &promql, QString *error = nullptr);
    // Waits until promql gives a value for which test holds.
    bool waitFor(const QString &promql, const std::function<bool(double)> &test, int timeoutMs, double *last = nullptr);
    [[nodiscard]] QString url() const { return m_url; }
    [[nodiscard]] QByteArray output() { return m_child.output(); }

private:
    QTemporaryDir m_dir;
    ChildProcess m_child;
    QString m_url;
};

class Mosquitto
{
public:
    ~Mosquitto() { stop(); }
    // On port, or on a free one when 0.
    bool start(QString *error, quint16 port = 0);
    void stop() { m_child.stop(); }
    [[nodiscard]] quint16 port() const { return m_port; }
    [[nodiscard]] QString url(const QString &prefix) const;
    [[nodiscard]] QByteArray output() { return m_child.output(); }

private:
    QTemporaryDir m_dir;
    ChildProcess m_child;
    quint16 m_port = 0;
};

// mosquitto_sub -v on a topic filter, each message one line "TOPIC RETAINED PAYLOAD" (retained 0/1).
class Subscriber
{
public:
    struct Message {
        QString topic;
        bool retained = false;
        QByteArray payload;
    };
    bool start(quint16 port, const QString &filter, QString *error);
    void stop() { m_child.stop(); }
    // Waits for a message on topic (exactly) whose payload contains text; messages are kept.
    std::optional<Message> waitFor(const QString &topic, const QByteArray &contains, int timeoutMs);
    [[nodiscard]] QList<Message> messages();

private:
    void read();
    ChildProcess m_child;
    QList<Message> m_messages;
    QByteArray m_partial;
};

// mosquitto_pub once.
bool publish(quint16 port, const QString &topic, const QByteArray &payload, QString *error);
// A program on PATH, or in /usr/sbin (Debian's mosquitto), empty when missing.
[[nodiscard]] QString programPath(const QString &name);
// Whether a program is there; else why, for QSKIP.
bool haveProgram(const QString &name, const QString &package, QString *why);

} // namespace mbscope::testcli
