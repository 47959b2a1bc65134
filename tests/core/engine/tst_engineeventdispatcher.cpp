#include "engine/engineeventdispatcher.h"
#include "transport/directsocketnotifier.h"

#include <QtCore/QPointer>
#include <QtCore/QScopeGuard>
#include <QtCore/QSocketNotifier>
#include <QtCore/QThread>
#include <QtCore/QTimer>
#include <QtTest/QtTest>

#include <atomic>
#include <sys/socket.h>
#include <unistd.h>

using namespace mbscope;

namespace {

constexpr int kWaitMs = 10000; // generous: a loaded machine must not fail the test

// A thread running an EngineEventDispatcher, and a way to run code in it and wait for the result.
class DispatcherThread
{
public:
    DispatcherThread()
    {
        m_thread.setEventDispatcher(new EngineEventDispatcher);
        m_thread.start();
        m_context.moveToThread(&m_thread);
    }
    ~DispatcherThread()
    {
        m_thread.quit();
        m_thread.wait();
    }
    [[nodiscard]] QObject *context() { return &m_context; }
    [[nodiscard]] QThread *thread() { return &m_thread; }
    template<typename F>
    void run(F &&f)
    {
        QMetaObject::invokeMethod(&m_context, std::forward<F>(f), Qt::BlockingQueuedConnection);
    }

private:
    QThread m_thread;
    QObject m_context;
};

// Counts its activations; an event filter on it counts the SockAct events it is sent.
class CountingNotifier final : public DirectSocketNotifier
{
public:
    CountingNotifier(int fd, QObject *parent)
        : DirectSocketNotifier(QSocketNotifier::Read, parent)
        , m_fd(fd)
    {
        setSocket(fd);
        setEnabled(true);
    }
    void activate() override
    {
        char buffer[64];
        (void)::read(m_fd, buffer, sizeof buffer);
        ++activations;
    }
    std::atomic<int> activations{0};

private:
    int m_fd;
};

class EventCounter final : public QObject
{
public:
    bool eventFilter(QObject *, QEvent *e) override
    {
        if (e->type() == QEvent::SockAct)
            ++events;
        return false;
    }
    std::atomic<int> events{0};
};

} // namespace

class TestEngineEventDispatcher : public QObject
{
    Q_OBJECT
private slots:
    void isTheThreadsDispatcher()
    {
        DispatcherThread t;
        bool ours = false;
        t.run([&] { ours = qobject_cast<EngineEventDispatcher *>(QAbstractEventDispatcher::instance()) != nullptr; });
        QVERIFY(ours);
    }

    // Calls posted from another thread are run, in order, and a quit() ends the loop at once
    // (a blocked ppoll() is woken).
    void postedCallsAndQuit()
    {
        auto t = std::make_unique<DispatcherThread>();
        std::atomic<int> sum{0};
        QList<int> order;
        for (int i = 1; i <= 100; ++i)
            QMetaObject::invokeMethod(t->context(), [&order, &sum, i] { order.append(i); sum += i; });
        QTRY_COMPARE_WITH_TIMEOUT(sum.load(), 5050, kWaitMs);
        QCOMPARE(order.size(), 100);
        QVERIFY(std::is_sorted(order.cbegin(), order.cend()));
        QElapsedTimer clock;
        clock.start();
        t.reset(); // quit() and wait(): returns only once the loop has ended
        QVERIFY(clock.elapsed() < kWaitMs);
    }

    // Single-shot and repeating timers of several intervals fire, at or after their time, and a
    // timer stopped from its own timeout does not fire again.
    void timers_data()
    {
        QTest::addColumn<int>("intervalMs");
        QTest::addColumn<bool>("singleShot");
        QTest::newRow("zero, single shot") << 0 << true;
        QTest::newRow("zero, repeating") << 0 << false;
        QTest::newRow("5 ms, single shot") << 5 << true;
        QTest::newRow("20 ms, repeating") << 20 << false;
    }
    void timers()
    {
        QFETCH(int, intervalMs);
        QFETCH(bool, singleShot);
        DispatcherThread t;
        std::atomic<int> fired{0};
        std::atomic<bool> early{false};
        QTimer *timer = nullptr;
        QElapsedTimer clock;
        t.run([&] {
            timer = new QTimer(t.context());
            timer->setTimerType(Qt::PreciseTimer);
            timer->setSingleShot(singleShot);
            timer->setInterval(intervalMs);
            QObject::connect(timer, &QTimer::timeout, timer, [&, timer] {
                const int n = ++fired;
                if (clock.elapsed() < qint64(n) * intervalMs)
                    early = true;
                if (n == 3)
                    timer->stop();
            });
            clock.start();
            timer->start();
        });
        const int expected = singleShot ? 1 : 3;
        QTRY_COMPARE_WITH_TIMEOUT(fired.load(), expected, kWaitMs);
        QTest::qWait(intervalMs * 3 + 50);
        QCOMPARE(fired.load(), expected); // stopped (or single shot): no more
        QVERIFY(!early.load());
        bool active = true;
        t.run([&] { active = timer->isActive(); });
        QVERIFY(!active);
    }

    // remainingTime() and registeredTimers() describe the armed timers.
    void timerIntrospection()
    {
        DispatcherThread t;
        int remaining = -2;
        int registered = 0;
        int unknown = 0;
        t.run([&] {
            auto *timer = new QTimer(t.context());
            timer->start(60000);
            auto *dispatcher = QAbstractEventDispatcher::instance();
            remaining = dispatcher->remainingTime(timer->timerId());
            const auto infos = dispatcher->registeredTimers(timer);
            registered = int(infos.size());
            if (!infos.isEmpty() && infos.first().interval != 60000)
                registered = -1;
            unknown = dispatcher->remainingTime(timer->timerId() + 1000);
            timer->stop();
            if (!dispatcher->registeredTimers(timer).isEmpty())
                registered = -2;
        });
        QVERIFY2(remaining > 59000 && remaining <= 60000, qPrintable(QString::number(remaining)));
        QCOMPARE(registered, 1);
        QCOMPARE(unknown, -1);
    }

    // A read notifier wakes the thread when bytes arrive on its descriptor; disabled, it stays
    // quiet; a write notifier fires on a writable descriptor.
    void socketNotifiers()
    {
        int fds[2];
        QCOMPARE(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0, fds), 0);
        auto closeFds = qScopeGuard([&] {
            ::close(fds[0]);
            ::close(fds[1]);
        });
        DispatcherThread t;
        std::atomic<int> reads{0};
        std::atomic<int> writes{0};
        QByteArray got;
        QSocketNotifier *reader = nullptr;
        t.run([&] {
            reader = new QSocketNotifier(fds[0], QSocketNotifier::Read, t.context());
            QObject::connect(reader, &QSocketNotifier::activated, reader, [&] {
                char buffer[64];
                const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
                if (n > 0)
                    got.append(buffer, n);
                ++reads;
            });
            auto *writer = new QSocketNotifier(fds[0], QSocketNotifier::Write, t.context());
            QObject::connect(writer, &QSocketNotifier::activated, writer, [&, writer] {
                ++writes;
                writer->setEnabled(false); // once is enough
            });
        });
        QTRY_COMPARE_WITH_TIMEOUT(writes.load(), 1, kWaitMs);
        QCOMPARE(reads.load(), 0);
        QCOMPARE(::write(fds[1], "abc", 3), ssize_t(3));
        QTRY_COMPARE_WITH_TIMEOUT(reads.load(), 1, kWaitMs);
        t.run([&] { reader->setEnabled(false); });
        QCOMPARE(::write(fds[1], "def", 3), ssize_t(3));
        QTest::qWait(50);
        QCOMPARE(reads.load(), 1);
        t.run([&] { reader->setEnabled(true); });
        QTRY_COMPARE_WITH_TIMEOUT(reads.load(), 2, kWaitMs);
        QString text;
        t.run([&] { text = QString::fromLatin1(got); });
        QCOMPARE(text, QStringLiteral("abcdef"));
        QCOMPARE(writes.load(), 1);
    }

    // awake() and aboutToBlock() are emitted once something listens (and only then: the
    // dispatcher skips them otherwise), and stop when it goes.
    void turnSignals()
    {
        DispatcherThread t;
        std::atomic<int> awake{0};
        std::atomic<int> blocking{0};
        QMetaObject::Connection a;
        QMetaObject::Connection b;
        t.run([&] {
            auto *dispatcher = QAbstractEventDispatcher::instance();
            a = connect(dispatcher, &QAbstractEventDispatcher::awake, dispatcher, [&] { ++awake; }, Qt::DirectConnection);
            b = connect(dispatcher, &QAbstractEventDispatcher::aboutToBlock, dispatcher, [&] { ++blocking; },
                        Qt::DirectConnection);
        });
        for (int i = 0; i < 5; ++i)
            t.run([] {}); // a turn each
        QTRY_VERIFY_WITH_TIMEOUT(awake.load() >= 5 && blocking.load() >= 5, kWaitMs);
        t.run([&] {
            disconnect(a);
            disconnect(b);
        });
        const int awakeBefore = awake.load();
        const int blockingBefore = blocking.load();
        for (int i = 0; i < 5; ++i)
            t.run([] {});
        QCOMPARE(awake.load(), awakeBefore);
        QCOMPARE(blocking.load(), blockingBefore);
    }

    // A DirectSocketNotifier is activated by a direct call, without an event (its event filter
    // sees none); under Qt's own dispatcher the event reaches the same activate().
    void directNotifiers_data()
    {
        QTest::addColumn<bool>("engineDispatcher");
        QTest::newRow("engine dispatcher") << true;
        QTest::newRow("Qt's dispatcher") << false;
    }
    void directNotifiers()
    {
        QFETCH(bool, engineDispatcher);
        int fds[2];
        QCOMPARE(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0, fds), 0);
        auto closeFds = qScopeGuard([&] {
            ::close(fds[0]);
            ::close(fds[1]);
        });
        QThread thread;
        if (engineDispatcher)
            thread.setEventDispatcher(new EngineEventDispatcher);
        thread.start();
        QObject context;
        context.moveToThread(&thread);
        CountingNotifier *notifier = nullptr;
        EventCounter counter;
        counter.moveToThread(&thread);
        auto stop = qScopeGuard([&] { // before the objects of the thread go
            thread.quit();
            thread.wait();
        });
        QMetaObject::invokeMethod(&context, [&] {
            notifier = new CountingNotifier(fds[0], &context);
            notifier->installEventFilter(&counter);
        }, Qt::BlockingQueuedConnection);
        QCOMPARE(::write(fds[1], "x", 1), ssize_t(1));
        QTRY_COMPARE_WITH_TIMEOUT(notifier->activations.load(), 1, kWaitMs);
        QCOMPARE(counter.events.load(), engineDispatcher ? 0 : 1);
        QMetaObject::invokeMethod(&context, [&] { delete notifier; }, Qt::BlockingQueuedConnection);
    }

    // deleteLater() in the thread deletes the object.
    void deferredDelete()
    {
        DispatcherThread t;
        QPointer<QObject> doomed;
        t.run([&] {
            doomed = new QObject;
            doomed->deleteLater();
        });
        QTRY_VERIFY_WITH_TIMEOUT(doomed.isNull(), kWaitMs);
    }
};

QTEST_GUILESS_MAIN(TestEngineEventDispatcher)
#include "tst_engineeventdispatcher.moc"
