// Every shell example of the README and the user guide runs as written (issue 26, item 17): the
// fenced sh and console blocks of README.md and docs/guide/*.md (tests/docs/shellblocks.h says
// how they are read and how a block is marked to be skipped, for a serial adapter, a display or
// root), each in a folder of its own with `mbscope` on PATH (the build's; `build/app/mbscope` and
// the source's docs/examples/ and tests/ are there too, as in a source tree). A block passes when
// it ends in time with the exit status expected (0 unless marked); whatever it started in the
// background is stopped afterwards (the block runs in a process group of its own).
//
// The examples name the ports users know (rtu-tcp://127.0.0.1:4001, a device server's), which
// other tests running in parallel, or the window's simulator, may hold: each block's loopback
// ports (127.0.0.1:N, in the block and in the docs/examples it reads) are mapped to free ports
// for its run, and /tmp/ to the block's folder, so that blocks never collide with anything.
//
// The examples of every subcommand's --help run the same way (rows "help:NAME:N"): each help has
// one at least, and a simulator it needs is named on its first line (shellblocks.h, helpBlocks).
//
// The blocks take minutes in all, most of it waiting on simulators and timers, so CTest runs them
// as several tests (tst_docexamples_1of3 ...): MBSCOPE_DOC_SHARD=K/N runs every Nth block from
// the Kth (1-based); without it, every block runs.
#include "shellblocks.h"

#include <QtCore/QDir>
#include <QtCore/QDirIterator>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QHash>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtNetwork/QTcpServer>
#include <QtTest/QtTest>

#include <csignal>
#include <memory>
#include <unistd.h>
#include <vector>

using namespace mbscope::testdocs;

namespace {

const QString kSourceDir = QStringLiteral(MBSCOPE_SOURCE_DIR);
const QString kExecutable = QStringLiteral(MBSCOPE_EXECUTABLE);

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

bool writeText(const QString &path, const QString &text)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(text.toUtf8()) == text.toUtf8().size();
}

// The pages run: README.md and the guide's.
QStringList markdownFiles()
{
    QStringList files{kSourceDir + QStringLiteral("/README.md")};
    const QDir guide(kSourceDir + QStringLiteral("/docs/guide"));
    for (const QString &name : guide.entryList({QStringLiteral("*.md")}, QDir::Files, QDir::Name))
        files.append(guide.filePath(name));
    return files;
}

const QRegularExpression &loopbackPort()
{
    static const QRegularExpression re(QStringLiteral(R"(127\.0\.0\.1:(\d+))"));
    return re;
}

// A free port for every fixed loopback port named in texts (all held while choosing, so that
// they differ).
QHash<QString, QString> freePortsFor(const QStringList &texts)
{
    QHash<QString, QString> map;
    std::vector<std::unique_ptr<QTcpServer>> held;
    for (const QString &text : texts) {
        for (auto it = loopbackPort().globalMatch(text); it.hasNext();) {
            const QString port = it.next().captured(1);
            if (port == QLatin1String("0") || map.contains(port))
                continue;
            auto server = std::make_unique<QTcpServer>();
            if (!server->listen(QHostAddress::LocalHost, 0))
                continue;
            map.insert(port, QString::number(server->serverPort()));
            held.push_back(std::move(server));
        }
    }
    return map;
}

QString mapped(QString text, const QHash<QString, QString> &ports, const QString &folder)
{
    QString out;
    qsizetype last = 0;
    for (auto it = loopbackPort().globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        out += text.mid(last, m.capturedStart(1) - last) + ports.value(m.captured(1), m.captured(1));
        last = m.capturedEnd(1);
    }
    out += text.mid(last);
    return out.replace(QStringLiteral("/tmp/"), folder + QStringLiteral("/tmp/"));
}

// Every subcommand's --help, by name, as `mbscope --help-all` prints them ("== mbscope NAME ==").
const QHash<QString, QString> &helpTexts()
{
    static const QHash<QString, QString> texts = [] {
        QHash<QString, QString> helps;
        QProcess process;
        process.start(kExecutable, {QStringLiteral("--help-all")});
        if (!process.waitForFinished(60000))
            return helps;
        static const QRegularExpression heading(QStringLiteral(R"(^== mbscope (\S+) ==$)"), QRegularExpression::MultilineOption);
        const QString all = QString::fromUtf8(process.readAllStandardOutput());
        QRegularExpressionMatch m = heading.match(all);
        while (m.hasMatch()) {
            const QRegularExpressionMatch next = heading.match(all, m.capturedEnd());
            helps.insert(m.captured(1), all.mid(m.capturedEnd(), next.hasMatch() ? next.capturedStart() - m.capturedEnd() : -1));
            m = next;
        }
        return helps;
    }();
    return texts;
}

// The blocks of a row's source: a Markdown page, or "help:NAME", a subcommand's --help.
QList<ShellBlock> blocksOf(const QString &source)
{
    if (source.startsWith(QLatin1String("help:"))) {
        const QString name = source.mid(5);
        return helpBlocks(helpTexts().value(name), name);
    }
    return shellBlocks(readText(source));
}

QByteArray tail(const QByteArray &bytes, int size = 4000)
{
    return bytes.size() <= size ? bytes : "..." + bytes.right(size);
}

// Stops every process of the group a block ran in: SIGTERM (simulate and watch stop cleanly on
// it), then SIGKILL for what is left after two seconds.
void stopGroup(pid_t group)
{
    if (group <= 0)
        return;
    ::kill(-group, SIGTERM);
    for (int i = 0; i < 20 && ::kill(-group, 0) == 0; ++i)
        QThread::msleep(100);
    ::kill(-group, SIGKILL);
}

} // namespace

class TestDocExamples : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void blocks_data();
    void blocks();
    void cleanupTestCase();

private:
    QTemporaryDir m_bin; // holds `mbscope`, first on PATH
    QElapsedTimer m_clock;
    int m_ran = 0;
    int m_skipped = 0;
};

void TestDocExamples::initTestCase()
{
    m_clock.start();
    QVERIFY(m_bin.isValid());
    QVERIFY2(QFileInfo(kExecutable).isExecutable(), qPrintable(kExecutable + QStringLiteral(" is not built")));
    QVERIFY(QFile::link(kExecutable, m_bin.filePath(QStringLiteral("mbscope"))));
    QVERIFY2(!QStandardPaths::findExecutable(QStringLiteral("bash")).isEmpty(), "bash runs the examples");
}

void TestDocExamples::blocks_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("index");
    int shard = 1;
    int shards = 1;
    const QString spec = qEnvironmentVariable("MBSCOPE_DOC_SHARD");
    if (!spec.isEmpty()) {
        bool okShard = false;
        bool okShards = false;
        shard = spec.section(QLatin1Char('/'), 0, 0).toInt(&okShard);
        shards = spec.section(QLatin1Char('/'), 1, 1).toInt(&okShards);
        if (!okShard || !okShards || shards < 1 || shard < 1 || shard > shards)
            QFAIL(qPrintable(QStringLiteral("MBSCOPE_DOC_SHARD=%1: expected K/N with 1 <= K <= N").arg(spec)));
    }
    int counter = 0;
    QStringList sources = markdownFiles();
    QStringList names = helpTexts().keys();
    if (names.size() < 10)
        QFAIL(qPrintable(QStringLiteral("mbscope --help-all listed %1 subcommands").arg(names.size())));
    names.sort();
    for (const QString &name : std::as_const(names))
        sources.append(QStringLiteral("help:") + name);
    for (const QString &file : std::as_const(sources)) {
        const QString relative = file.startsWith(QLatin1String("help:")) ? file : QDir(kSourceDir).relativeFilePath(file);
        const QList<ShellBlock> blocks = blocksOf(file);
        for (int i = 0; i < blocks.size(); ++i) {
            if (counter++ % shards == shard - 1)
                QTest::addRow("%s:%d", qPrintable(relative), blocks.at(i).line) << file << i;
        }
    }
}

void TestDocExamples::blocks()
{
    QFETCH(QString, file);
    QFETCH(int, index);
    const ShellBlock block = blocksOf(file).at(index);
    QVERIFY2(block.problems.isEmpty(), qPrintable(block.problems.join(QLatin1String("; "))));
    if (!block.skip.isEmpty()) {
        ++m_skipped;
        QSKIP(qPrintable(block.skip));
    }
    ++m_ran;

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString folder = dir.path();
    QVERIFY(QDir(folder).mkpath(QStringLiteral("tmp")));
    QVERIFY(QDir(folder).mkpath(QStringLiteral("build/app")));
    QVERIFY(QFile::link(kExecutable, dir.filePath(QStringLiteral("build/app/mbscope"))));
    QVERIFY(QFile::link(kSourceDir + QStringLiteral("/tests"), dir.filePath(QStringLiteral("tests"))));

    QString script = block.setup.join(QLatin1Char('\n')) + QLatin1Char('\n') + block.script;
    for (const auto &[from, to] : block.substitutions) {
        QVERIFY2(script.contains(from), qPrintable(QStringLiteral("sub: '%1' is not in the block").arg(from)));
        script.replace(from, to);
    }
    // The session files the examples read, with the same ports mapped.
    QStringList texts{script};
    QHash<QString, QString> examples;
    for (QDirIterator it(kSourceDir + QStringLiteral("/docs/examples"), QDir::Files); it.hasNext();) {
        const QString path = it.next();
        examples.insert(QStringLiteral("docs/examples/") + it.fileName(), readText(path));
        texts.append(examples.value(QStringLiteral("docs/examples/") + it.fileName()));
    }
    const QHash<QString, QString> ports = freePortsFor(texts);
    QVERIFY(QDir(folder).mkpath(QStringLiteral("docs/examples")));
    for (auto it = examples.cbegin(); it != examples.cend(); ++it)
        QVERIFY(writeText(dir.filePath(it.key()), mapped(it.value(), ports, folder)));

    const QString run = QStringLiteral("set -e\n"
                                       "trap 'status=$?; echo \"docs-test: \\\"$BASH_COMMAND\\\" exited with $status\" >&2' ERR\n")
                        + mapped(script, ports, folder) + QLatin1Char('\n');
    QProcess bash;
    bash.setWorkingDirectory(folder);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("PATH"), m_bin.path() + QLatin1Char(':') + env.value(QStringLiteral("PATH")));
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    for (const char *name : {"XDG_DATA_HOME", "XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"})
        env.insert(QLatin1String(name), folder + QStringLiteral("/.home/") + QLatin1String(name));
    bash.setProcessEnvironment(env);
    bash.setChildProcessModifier([] { ::setsid(); });
    bash.setStandardInputFile(QProcess::nullDevice());
    bash.start(QStringLiteral("bash"), {QStringLiteral("-c"), run});
    QVERIFY2(bash.waitForStarted(30000), qPrintable(bash.errorString()));
    const pid_t group = pid_t(bash.processId());
    const int limitMs = (block.stopAfterSeconds > 0 ? block.stopAfterSeconds : block.timeoutSeconds) * 1000;
    const bool finished = bash.waitForFinished(limitMs);
    stopGroup(group);
    if (!finished)
        bash.waitForFinished(5000);
    const QByteArray out = bash.readAllStandardOutput();
    const QByteArray err = bash.readAllStandardError();
    const QString report = QStringLiteral("\n--- script (ports %1)\n%2--- stdout\n%3\n--- stderr\n%4")
                               .arg(QStringList(ports.keys()).join(QLatin1Char(',')), run, QString::fromUtf8(tail(out)),
                                    QString::fromUtf8(tail(err)));
    if (block.stopAfterSeconds > 0) {
        QVERIFY2(!finished, qPrintable(QStringLiteral("ended before it was stopped, with exit status %1").arg(bash.exitCode()) + report));
        return;
    }
    QVERIFY2(finished, qPrintable(QStringLiteral("did not end in %1 s").arg(block.timeoutSeconds) + report));
    QVERIFY2(bash.exitStatus() == QProcess::NormalExit && bash.exitCode() == block.exitStatus,
             qPrintable(QStringLiteral("exit status %1, expected %2").arg(bash.exitCode()).arg(block.exitStatus) + report));
}

void TestDocExamples::cleanupTestCase()
{
    qInfo("%d blocks run, %d skipped, in %.1f s", m_ran, m_skipped, double(m_clock.elapsed()) / 1000.0);
}

QTEST_GUILESS_MAIN(TestDocExamples)
#include "tst_docexamples.moc"
