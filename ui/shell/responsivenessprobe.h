#pragma once

#include <QtCore/QElapsedTimer>
#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QTimer>

class QAbstractItemView;
class QMainWindow;
class QWidget;

namespace mbscope {

// How fast the window answers a person while it works (issue 31: menus open in under 100 ms, the
// traffic list scrolls smoothly through a million rows). Every everyMs it asks, in turn, for the
// next menu of the menu bar to open, or for the list to show a row picked at random, and times
// from the asking to the widget's next paint: what a person waits for after a click, with the
// window's own work (its poll, its plots) in the way. `MBSCOPE_RESPONSIVENESS_MS=N` turns it on
// for the window (bench_windowsoak), which says summary() on standard error when it quits.
class ResponsivenessProbe : public QObject
{
    Q_OBJECT
public:
    ResponsivenessProbe(QMainWindow *window, QAbstractItemView *list, int everyMs, QObject *parent = nullptr);

    // "menus: 90 opened, median 2.1 ms, p95 6.0 ms, max 31.2 ms; list: 88 jumps through up to
    // 812,345 rows, median ..."
    [[nodiscard]] QString summary() const;
    [[nodiscard]] const QList<double> &menuMs() const { return m_menuMs; }
    [[nodiscard]] const QList<double> &scrollMs() const { return m_scrollMs; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void step();
    void openMenu();
    void jump();

    QMainWindow *m_window;
    QPointer<QAbstractItemView> m_list;
    QTimer m_timer;
    QElapsedTimer m_clock;
    QPointer<QWidget> m_waitingOn; // the widget whose next paint ends the measurement
    bool m_menuNext = true;
    int m_nextMenu = 0;
    int m_mostRows = 0;
    quint32 m_seed = 1;
    QList<double> m_menuMs;
    QList<double> m_scrollMs;
};

} // namespace mbscope
