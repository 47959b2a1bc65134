#pragma once

#include <QtCore/QJsonObject>
#include <QtCore/QObject>
#include <QtCore/QString>

#include <functional>

class QLocalServer;

namespace mbscope::app {

// One window per user's data (its capture folder and journal, its saved layout): a second start of
// the window hands what it was asked (a session to open, a tab, a dock) to the window already
// running, over a local socket, and ends; `mbscope --new-instance` opts out. The socket is named
// after the data folder, so a run with folders of its own (a test, another HOME) has a window of
// its own too.
//
// One line of JSON goes to the window; one line of text comes back, printed by the second start:
// "ok: ..." (exit 0) or "error: ..." (exit 1).
class InstanceHandover : public QObject
{
    Q_OBJECT

public:
    // What the running window does with a request; the line it answers.
    using Handler = std::function<QString(const QJsonObject &request)>;

    explicit InstanceHandover(QObject *parent = nullptr);
    ~InstanceHandover() override;

    // "mbscope-window-" and a hash of the data folder.
    [[nodiscard]] static QString serverName();
    // Sends request to the running window and waits for its answer (in *answer). False, and
    // *answer empty, when no window listens: this start is the window then.
    static bool handOver(const QJsonObject &request, QString *answer, int timeoutMs = 30000);

    // Takes later starts' requests to handler. False when the name cannot be taken.
    bool listen(Handler handler);
    [[nodiscard]] QString errorString() const;

private:
    void serve();

    QLocalServer *m_server;
    Handler m_handler;
};

} // namespace mbscope::app
