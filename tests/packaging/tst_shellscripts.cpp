// The project's shell scripts (scripts/*.sh, .ci/run and the executables under packaging/):
// each parses under the shell its first line names (`sh -n` is dash on Debian, which refuses
// bash's arrays and [[ ]]: session 7's fuzz.sh did, and `make test` stopped there), and
// shellcheck finds no warning in it for that dialect.
#include "processrun.h"

#include <QtCore/QDir>
#include <QtCore/QDirIterator>
#include <QtCore/QFile>
#include <QtTest/QtTest>

using namespace mbscope::testpackaging;

namespace {

// The scripts with a #! line, relative to the source folder.
QStringList projectScripts()
{
    const QDir root(QStringLiteral(MBSCOPE_SOURCE_DIR));
    QStringList found;
    const QStringList places{QStringLiteral("scripts"), QStringLiteral(".ci"), QStringLiteral("packaging")};
    for (const QString &place : places) {
        QDirIterator it(root.filePath(place), QDir::Files);
        while (it.hasNext()) {
            const QString path = it.next();
            QFile f(path);
            if (f.open(QIODevice::ReadOnly) && f.peek(2) == "#!")
                found.append(root.relativeFilePath(path));
        }
    }
    found.sort();
    return found;
}

// "sh" or "bash" from the first line, or empty for another interpreter.
QString shellOf(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    const QByteArray first = f.readLine().trimmed();
    if (first == "#!/bin/sh")
        return QStringLiteral("sh");
    if (first == "#!/bin/bash" || first == "#!/usr/bin/env bash")
        return QStringLiteral("bash");
    return {};
}

} // namespace

class TestShellScripts : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void parses_data();
    void parses();
    void shellcheckClean_data() { parses_data(); }
    void shellcheckClean();
};

void TestShellScripts::parses_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("shell");
    const QStringList scripts = projectScripts();
    QVERIFY2(scripts.contains(QStringLiteral("scripts/fuzz.sh")), "scripts/fuzz.sh is found");
    const QDir root(QStringLiteral(MBSCOPE_SOURCE_DIR));
    for (const QString &script : scripts) {
        const QString shell = shellOf(root.filePath(script));
        if (!shell.isEmpty())
            QTest::newRow(qPrintable(script)) << root.filePath(script) << shell;
    }
}

void TestShellScripts::parses()
{
    QFETCH(QString, path);
    QFETCH(QString, shell);
    const ProcessRun run = runProcess(shell, {QStringLiteral("-n"), path}, {}, 30000);
    QVERIFY2(run.started, qPrintable(shell + QStringLiteral(" is not installed")));
    QVERIFY2(run.succeeded(), run.describe().constData());
}

void TestShellScripts::shellcheckClean()
{
    QFETCH(QString, path);
    QFETCH(QString, shell);
    if (findProgram(QStringLiteral("shellcheck")).isEmpty())
        QSKIP("shellcheck is not installed (scripts/install-deps.sh --tests installs it)");
    const ProcessRun run = runProcess(QStringLiteral("shellcheck"),
                                      {QStringLiteral("--shell=") + shell, QStringLiteral("--severity=warning"), path},
                                      {}, 60000);
    QVERIFY2(run.succeeded(), run.describe().constData());
}

QTEST_GUILESS_MAIN(TestShellScripts)
#include "tst_shellscripts.moc"
