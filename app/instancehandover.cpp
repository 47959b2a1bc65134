#include "instancehandover.h"

#include <QtCore/QCryptographicHash>
#include <QtCore/QJsonDocument>
#include <QtCore/QStandardPaths>
#include <QtNetwork/QLocalServer>
#include <QtNetwork/QLocalSocket>

namespace mbscope::app {

namespace {

constexpr int kLineLimit = 64 * 1024; // a request is a few paths: anything longer is not ours

} // namespace

InstanceHandover::InstanceHandover(QObject *parent)
    : QObject(parent)
    , m_server(new QLocalServer(this))
{
    connect(m_server, &QLocalServer::newConnection, this, &InstanceHandover::serve);
}

InstanceHandover::~InstanceHandover() = default;

QString InstanceHandover::serverName()
{
    const QString data = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    const QByteArray hash = QCryptographicHash::hash(data.toUtf8(), QCryptographicHash::Sha1).toHex().left(16);
    return QStringLiteral("mbscope-window-") + QString::fromLatin1(hash);
}

bool InstanceHandover::handOver(const QJsonObject &request, QString *answer, int timeoutMs)
{
    answer->clear();
    QLocalSocket socket;
    socket.connectToServer(serverName());
    if (!socket.waitForConnected(1000))
        return false; // nobody listens (or a socket a crash left): this start is the window
    socket.write(QJsonDocument(request).toJson(QJsonDocument::Compact) + '\n');
    socket.flush();
    QByteArray line;
    while (!line.contains('\n')) {
        if (!socket.waitForReadyRead(timeoutMs)) {
            *answer = QStringLiteral("error: the running window (%1) did not answer; --new-instance opens a window of its own")
                          .arg(serverName());
            return true;
        }
        line += socket.readAll();
    }
    *answer = QString::fromUtf8(line.left(line.indexOf('\n')));
    return true;
}

bool InstanceHandover::listen(Handler handler)
{
    m_handler = std::move(handler);
    m_server->setSocketOptions(QLocalServer::UserAccessOption);
    if (m_server->listen(serverName()))
        return true;
    // A socket file a crashed window left: nobody answered handOver(), so it is taken over.
    QLocalServer::removeServer(serverName());
    return m_server->listen(serverName());
}

QString InstanceHandover::errorString() const
{
    return m_server->errorString();
}

void InstanceHandover::serve()
{
    while (QLocalSocket *socket = m_server->nextPendingConnection()) {
        connect(socket, &QLocalSocket::disconnected, socket, &QObject::deleteLater);
        connect(socket, &QLocalSocket::readyRead, this, [this, socket] {
            if (!socket->canReadLine()) {
                if (socket->bytesAvailable() > kLineLimit)
                    socket->abort();
                return;
            }
            QJsonParseError error{};
            const QJsonDocument document = QJsonDocument::fromJson(socket->readLine(kLineLimit), &error);
            const QString answer = document.isObject() && m_handler
                ? m_handler(document.object())
                : QStringLiteral("error: the request is not a JSON object (%1)").arg(error.errorString());
            socket->write(answer.toUtf8() + '\n');
            socket->flush();
            socket->disconnectFromServer();
        });
    }
}

} // namespace mbscope::app
