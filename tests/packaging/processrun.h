#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope::testpackaging {

// What one run of an external program left.
struct ProcessRun {
    bool started = false;  // false: the program is missing or not executable
    bool finished = false; // within the time allowed (else it was killed)
    int exitCode = -1;
    QByteArray out;
    QByteArray err;

    [[nodiscard]] bool succeeded() const { return finished && exitCode == 0; }
    [[nodiscard]] QString outText() const { return QString::fromUtf8(out); }
    [[nodiscard]] QString errText() const { return QString::fromUtf8(err); }
    // For failure messages: the command, its exit status and both streams.
    [[nodiscard]] QByteArray describe() const;

    QString command;
};

// Runs program with arguments in workDir (the current directory when empty) and waits for it,
// killing it after timeoutMs. Standard input is closed.
[[nodiscard]] ProcessRun runProcess(const QString &program, const QStringList &arguments, const QString &workDir = {},
                                    int timeoutMs = 120000);

// The absolute path of a program found on PATH, or empty.
[[nodiscard]] QString findProgram(const QString &name);

} // namespace mbscope::testpackaging
