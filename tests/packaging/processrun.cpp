#include "processrun.h"

#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>

namespace mbscope::testpackaging {

QByteArray ProcessRun::describe() const
{
    QByteArray text = command.toLocal8Bit();
    if (!started)
        return text + ": could not be started";
    text += finished ? QByteArray(": exit status ") + QByteArray::number(exitCode) : QByteArray(": killed after the time allowed");
    text += "\n--- stdout:\n" + out.left(4000) + "\n--- stderr:\n" + err.left(4000);
    return text;
}

ProcessRun runProcess(const QString &program, const QStringList &arguments, const QString &workDir, int timeoutMs)
{
    ProcessRun run;
    run.command = (QStringList{program} + arguments).join(QLatin1Char(' '));
    QProcess process;
    if (!workDir.isEmpty())
        process.setWorkingDirectory(workDir);
    process.setStandardInputFile(QProcess::nullDevice());
    process.start(program, arguments);
    run.started = process.waitForStarted(30000);
    if (!run.started)
        return run;
    run.finished = process.waitForFinished(timeoutMs) && process.exitStatus() == QProcess::NormalExit;
    if (!run.finished) {
        process.kill();
        process.waitForFinished(5000);
    }
    run.exitCode = process.exitCode();
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

QString findProgram(const QString &name)
{
    return QStandardPaths::findExecutable(name);
}

} // namespace mbscope::testpackaging
