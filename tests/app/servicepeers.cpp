#include "servicepeers.h"

#include "clitest.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QThread>
#include <QtCore/QTimer>
#include <QtCore/QUrlQuery>
#include <QtNetwork/QNetworkAccessManager>
#include <QtNetwork/QNetworkReply>
#include <QtNetwork/QTcpSocket>

#include <csignal>

namespace mbscope::testcli {

HttpReply httpGet(const QString &url, const QByteArray &accept, int timeoutMs)
{
    HttpReply result;
    QNetworkAccessManager manager;
    QNetworkRequest request{QUrl(url)};
    if (!accept.isEmpty())
        request.setRawHeader("Accept", accept);
    request.setTransferTimeout(timeoutMs);
    QNetworkReply *reply = manager.get(request);
    QEventLoop loop;
    QObject::connect(reply, &QNetworkReply::finished, &loop, &QEventLoop::quit);
    QTimer::singleShot(timeoutMs + 500, &loop, &QEventLoop::quit);
    loop.exec();
    if (!reply->isFinished()) {
        result.error = QStringLiteral("no answer from %1 within %2 ms").arg(url).arg(timeoutMs);
        reply->abort();
    } else {
        result.status = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
        result.contentType = reply->header(QNetworkRequest::ContentTypeHeader).toByteArray();
        result.body = reply->readAll();
        if (reply->error() != QNetworkReply::NoError)
            result.error = reply->errorString();
    }
    delete reply;
    return result;
}

namespace {

// name{a="x",b="y"} value  ->  labels and value; false for comments and other metrics.
bool parseSample(const QByteArray &line, const QString &metric, QMap<QString, QString> *labels, double *value)
{
    if (line.startsWith('#') || !line.startsWith(metric.toUtf8()))
        return false;
    const QByteArray rest = line.mid(metric.size());
    if (!rest.startsWith('{') && !rest.startsWith(' '))
        return false;
    labels->clear();
    qsizetype at = 0;
    if (rest.startsWith('{')) {
        at = 1;
        while (at < rest.size() && rest.at(at) != '}') {
            const qsizetype eq = rest.indexOf('=', at);
            if (eq < 0)
                return false;
            const QString name = QString::fromUtf8(rest.mid(at, eq - at));
            qsizetype i = eq + 2; // past ="
            QByteArray v;
            while (i < rest.size() && rest.at(i) != '"') {
                if (rest.at(i) == '\\' && i + 1 < rest.size()) {
                    ++i;
                    v += rest.at(i) == 'n' ? '\n' : rest.at(i);
                } else {
                    v += rest.at(i);
                }
                ++i;
            }
            labels->insert(name, QString::fromUtf8(v));
            at = i + 1;
            if (at < rest.size() && rest.at(at) == ',')
                ++at;
        }
        ++at;
    }
    bool ok = false;
    const QByteArray number = rest.mid(at).trimmed().split(' ').value(0);
    *value = number == "+Inf" ? qInf() : number.toDouble(&ok);
    return ok || number == "+Inf";
}

} // namespace

std::optional<double> metricValue(const QByteArray &exposition, const QString &metric, const QMap<QString, QString> &labels)
{
    for (const QByteArray &line : exposition.split('\n')) {
        QMap<QString, QString> have;
        double value = 0;
        if (!parseSample(line, metric, &have, &value))
            continue;
        bool all = true;
        for (auto it = labels.cbegin(); it != labels.cend(); ++it)
            all = all && have.value(it.key()) == it.value();
        if (all)
            return value;
    }
    return std::nullopt;
}

double metricSum(const QByteArray &exposition, const QString &metric)
{
    double sum = 0;
    for (const QByteArray &line : exposition.split('\n')) {
        QMap<QString, QString> have;
        double value = 0;
        if (parseSample(line, metric, &have, &value))
            sum += value;
    }
    return sum;
}

bool ChildProcess::start(const QString &program, const QStringList &arguments, QString *error)
{
    stop();
    m_output.clear();
    m_process = std::make_unique<QProcess>();
    m_process->setProcessChannelMode(QProcess::MergedChannels);
    m_process->start(program, arguments);
    if (!m_process->waitForStarted(30000)) {
        *error = QStringLiteral("cannot start %1: %2").arg(program, m_process->errorString());
        return false;
    }
    return true;
}

void ChildProcess::drain()
{
    if (m_process)
        m_output += m_process->readAll();
}

bool ChildProcess::waitForOutput(const QByteArray &text, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    while (true) {
        drain();
        if (m_output.contains(text))
            return true;
        if (deadline.hasExpired() || !m_process || m_process->state() == QProcess::NotRunning)
            return false;
        m_process->waitForReadyRead(int(qMin<qint64>(200, qMax<qint64>(1, deadline.remainingTime()))));
    }
}

void ChildProcess::signal(int number)
{
    if (isRunning())
        ::kill(pid_t(m_process->processId()), number);
}

int ChildProcess::stop(int number, int timeoutMs)
{
    if (!m_process)
        return -1;
    if (m_process->state() != QProcess::NotRunning) {
        ::kill(pid_t(m_process->processId()), number);
        if (!m_process->waitForFinished(timeoutMs)) {
            m_process->kill();
            m_process->waitForFinished(5000);
            drain();
            return -1;
        }
    }
    drain();
    return m_process->exitStatus() == QProcess::NormalExit ? m_process->exitCode() : -1;
}

bool ChildProcess::isRunning() const
{
    return m_process && m_process->state() != QProcess::NotRunning;
}

qint64 ChildProcess::pid() const
{
    return m_process ? m_process->processId() : 0;
}

QByteArray ChildProcess::output()
{
    drain();
    return m_output;
}

bool Simulator::start(const QString &profile, quint16 port, QString *error)
{
    if (!m_child.start(mbscopePath(),
                       {QStringLiteral("simulate"), QStringLiteral("--profile"), profile, QStringLiteral("--quiet"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:%1").arg(port)},
                       error))
        return false;
    if (!m_child.waitForOutput("listening ", 30000)) {
        *error = QStringLiteral("no 'listening' line from mbscope simulate: ") + QString::fromUtf8(m_child.output());
        return false;
    }
    // Let the rest of the line arrive.
    m_child.waitForOutput("\n", 2000);
    const QByteArray out = m_child.output();
    const qsizetype at = out.indexOf("listening ");
    m_url = QString::fromUtf8(out.mid(at + 10, out.indexOf('\n', at) - at - 10)).section(QLatin1Char(' '), 0, 0).trimmed();
    return true;
}

quint16 Simulator::port() const
{
    return quint16(m_url.section(QLatin1Char(':'), -1).toUInt());
}

QString programPath(const QString &name)
{
    const QString found = QStandardPaths::findExecutable(name);
    return found.isEmpty() ? QStandardPaths::findExecutable(name, {QStringLiteral("/usr/sbin"), QStringLiteral("/usr/bin")}) : found;
}

bool haveProgram(const QString &name, const QString &package, QString *why)
{
    if (!programPath(name).isEmpty())
        return true;
    *why = QStringLiteral("%1 is not installed (Debian: %2; scripts/install-deps.sh --tests)").arg(name, package);
    return false;
}

namespace {

bool waitForPort(quint16 port, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    while (!deadline.hasExpired()) {
        QTcpSocket socket;
        socket.connectToHost(QStringLiteral("127.0.0.1"), port);
        if (socket.waitForConnected(500))
            return true;
        QThread::msleep(100);
    }
    return false;
}

} // namespace

bool Prometheus::start(const QStringList &targets, const QString &scrapeInterval, QString *error)
{
    if (!haveProgram(QStringLiteral("prometheus"), QStringLiteral("prometheus"), error) || !m_dir.isValid())
        return false;
    const quint16 port = closedPort();
    QFile config(m_dir.filePath(QStringLiteral("prometheus.yml")));
    if (!config.open(QIODevice::WriteOnly))
        return false;
    QByteArray yaml = "global:\n  scrape_interval: " + scrapeInterval.toUtf8() + "\n  scrape_timeout: " + scrapeInterval.toUtf8() +
                      "\n  evaluation_interval: " + scrapeInterval.toUtf8() + "\nscrape_configs:\n  - job_name: mbscope\n    static_configs:\n      - targets:\n";
    for (const QString &t : targets)
        yaml += "          - '" + t.toUtf8() + "'\n";
    config.write(yaml);
    config.close();
    m_url = QStringLiteral("http://127.0.0.1:%1").arg(port);
    if (!m_child.start(programPath(QStringLiteral("prometheus")),
                       {QStringLiteral("--config.file=") + config.fileName(), QStringLiteral("--storage.tsdb.path=") + m_dir.filePath(QStringLiteral("data")),
                        QStringLiteral("--web.listen-address=127.0.0.1:%1").arg(port), QStringLiteral("--log.level=warn")},
                       error))
        return false;
    const QDeadlineTimer deadline(60000);
    while (!deadline.hasExpired() && m_child.isRunning()) {
        if (httpGet(m_url + QStringLiteral("/-/ready"), {}, 2000).status == 200)
            return true;
        QThread::msleep(200);
    }
    *error = QStringLiteral("prometheus did not become ready: ") + QString::fromUtf8(m_child.output());
    return false;
}

QJsonObject Prometheus::query(const QString &promql, QString *error)
{
    QUrlQuery q;
    q.addQueryItem(QStringLiteral("query"), promql);
    QUrl url(m_url + QStringLiteral("/api/v1/query"));
    url.setQuery(q);
    const HttpReply reply = httpGet(url.toString(QUrl::FullyEncoded));
    const QJsonObject o = QJsonDocument::fromJson(reply.body).object();
    if (o.value(QStringLiteral("status")).toString() != QLatin1String("success")) {
        if (error)
            *error = QStringLiteral("%1: %2 %3").arg(promql, reply.error, QString::fromUtf8(reply.body));
        return {};
    }
    return o.value(QStringLiteral("data")).toObject();
}

std::optional<double> Prometheus::scalar(const QString &promql, QString *error)
{
    const QJsonArray result = query(promql, error).value(QStringLiteral("result")).toArray();
    if (result.isEmpty())
        return std::nullopt;
    return result.first().toObject().value(QStringLiteral("value")).toArray().at(1).toString().toDouble();
}

bool Prometheus::waitFor(const QString &promql, const std::function<bool(double)> &test, int timeoutMs, double *last)
{
    const QDeadlineTimer deadline(timeoutMs);
    while (!deadline.hasExpired()) {
        const std::optional<double> v = scalar(promql);
        if (v && last)
            *last = *v;
        if (v && test(*v))
            return true;
        QThread::msleep(250);
    }
    return false;
}

bool Mosquitto::start(QString *error, quint16 port)
{
    if (!haveProgram(QStringLiteral("mosquitto"), QStringLiteral("mosquitto"), error))
        return false;
    m_port = port != 0 ? port : closedPort();
    QFile config(m_dir.filePath(QStringLiteral("mosquitto.conf")));
    if (!config.open(QIODevice::WriteOnly))
        return false;
    config.write("listener " + QByteArray::number(m_port) + " 127.0.0.1\nallow_anonymous true\npersistence false\nlog_dest stderr\n");
    config.close();
    if (!m_child.start(programPath(QStringLiteral("mosquitto")), {QStringLiteral("-c"), config.fileName()}, error))
        return false;
    if (!waitForPort(m_port, 20000)) {
        *error = QStringLiteral("mosquitto does not listen on %1: ").arg(m_port) + QString::fromUtf8(m_child.output());
        return false;
    }
    return true;
}

QString Mosquitto::url(const QString &prefix) const
{
    return QStringLiteral("mqtt://127.0.0.1:%1/%2").arg(m_port).arg(prefix);
}

bool Subscriber::start(quint16 port, const QString &filter, QString *error)
{
    if (!haveProgram(QStringLiteral("mosquitto_sub"), QStringLiteral("mosquitto-clients"), error))
        return false;
    if (!m_child.start(programPath(QStringLiteral("mosquitto_sub")),
                       {QStringLiteral("-h"), QStringLiteral("127.0.0.1"), QStringLiteral("-p"), QString::number(port), QStringLiteral("-t"), filter,
                        QStringLiteral("-F"), QStringLiteral("%t %r %p")},
                       error))
        return false;
    QThread::msleep(300); // subscribed before the test goes on
    return true;
}

void Subscriber::read()
{
    m_partial += m_child.process()->readAll();
    qsizetype nl = 0;
    while ((nl = m_partial.indexOf('\n')) >= 0) {
        const QByteArray line = m_partial.left(nl);
        m_partial.remove(0, nl + 1);
        const qsizetype a = line.indexOf(' ');
        const qsizetype b = line.indexOf(' ', a + 1);
        if (a < 0 || b < 0)
            continue;
        m_messages.append(Message{QString::fromUtf8(line.left(a)), line.mid(a + 1, b - a - 1) == "1", line.mid(b + 1)});
    }
}

std::optional<Subscriber::Message> Subscriber::waitFor(const QString &topic, const QByteArray &contains, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    qsizetype seen = 0;
    while (true) {
        read();
        for (; seen < m_messages.size(); ++seen) {
            const Message &m = m_messages.at(seen);
            if (m.topic == topic && m.payload.contains(contains))
                return m;
        }
        if (deadline.hasExpired() || !m_child.isRunning())
            return std::nullopt;
        m_child.process()->waitForReadyRead(int(qMin<qint64>(200, qMax<qint64>(1, deadline.remainingTime()))));
    }
}

QList<Subscriber::Message> Subscriber::messages()
{
    read();
    return m_messages;
}

bool publish(quint16 port, const QString &topic, const QByteArray &payload, QString *error)
{
    if (!haveProgram(QStringLiteral("mosquitto_pub"), QStringLiteral("mosquitto-clients"), error))
        return false;
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(programPath(QStringLiteral("mosquitto_pub")),
            {QStringLiteral("-h"), QStringLiteral("127.0.0.1"), QStringLiteral("-p"), QString::number(port), QStringLiteral("-q"),
             QStringLiteral("1"), QStringLiteral("-t"), topic, QStringLiteral("-m"), QString::fromUtf8(payload)});
    if (!p.waitForFinished(10000) || p.exitCode() != 0) {
        *error = QStringLiteral("mosquitto_pub failed: ") + QString::fromUtf8(p.readAll());
        return false;
    }
    return true;
}

} // namespace mbscope::testcli
