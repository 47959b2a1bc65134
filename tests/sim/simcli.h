#pragma once

// `mbscope simulate` as the tests run it: the product executable (MBSCOPE_EXECUTABLE, passed in by
// CMake) with the subcommand first, on ports the OS chooses, stopped with SIGINT as Ctrl-C stops it.

#include <QtCore/QByteArray>
#include <QtCore/QMap>
#include <QtCore/QProcess>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <memory>

namespace mbscope::simtest {

// What one finished process left.
struct Run {
    int exitCode = -1; // -1: did not start, crashed or timed out
    QByteArray out;
    QByteArray err;
};

[[nodiscard]] QString mbscopePath();
// Runs program to its end (killed after timeoutMs), standard input closed.
[[nodiscard]] Run runProcess(const QString &program, const QStringList &args, int timeoutMs = 60000);
// `mbscope simulate ARGS...` to its end.
[[nodiscard]] Run runSimulate(const QStringList &args, int timeoutMs = 60000);

// `mbscope simulate ARGS...` running: started, its endpoints read from its "listening" lines,
// stopped with SIGINT (killed by the destructor when a test fails half-way).
class SimCli
{
public:
    SimCli() = default;
    ~SimCli();
    SimCli(const SimCli &) = delete;
    SimCli &operator=(const SimCli &) = delete;

    // Starts and waits for `endpoints` "listening URL (units ...)" lines; false with *error set.
    [[nodiscard]] bool start(const QStringList &args, int endpoints, QString *error);
    // The port of the index-th endpoint listed ("tcp://127.0.0.1:PORT (unit...", 0 for a device).
    [[nodiscard]] quint16 port(int index) const;
    [[nodiscard]] const QStringList &listening() const { return m_listening; }

    // Reads standard output while it runs until it holds text (false after timeoutMs).
    [[nodiscard]] bool waitForOutput(const QByteArray &text, int timeoutMs);
    // SIGINT, as Ctrl-C; the exit code (-1 when it did not stop).
    int stop();
    [[nodiscard]] const QByteArray &output() const { return m_out; }
    [[nodiscard]] const QByteArray &errors() const { return m_err; }

private:
    std::unique_ptr<QProcess> m_process;
    QStringList m_listening;
    QByteArray m_out;
    QByteArray m_err;
};

// A throwaway CA and a server and client certificate it signed (EC P-256, two days), made with
// openssl in dir: ca.pem, server.pem/server.key (subjectAltName IP:127.0.0.1), client.pem/client.key.
// False with *error set (openssl missing or failing).
[[nodiscard]] bool makeTestCertificates(const QString &dir, QString *error);

// mbpoll's "[122]: 	1050" lines, by reference.
[[nodiscard]] QMap<int, int> mbpollValues(const QByteArray &output);

} // namespace mbscope::simtest
