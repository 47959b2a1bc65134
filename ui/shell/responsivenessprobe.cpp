#include "responsivenessprobe.h"

#include <QtCore/QEvent>
#include <QtCore/QLocale>
#include <QtWidgets/QAbstractItemView>
#include <QtWidgets/QMainWindow>
#include <QtWidgets/QMenu>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QScrollBar>

#include <algorithm>

namespace mbscope {

namespace {

// Median, p95 and max of a list of milliseconds, for a person.
QString figures(QList<double> ms)
{
    if (ms.isEmpty())
        return QStringLiteral("none measured");
    std::sort(ms.begin(), ms.end());
    const auto at = [&ms](double q) { return ms.at(qMin(ms.size() - 1, qsizetype(q * double(ms.size() - 1) + 0.5))); };
    return QStringLiteral("median %1 ms, p95 %2 ms, max %3 ms")
        .arg(at(0.5), 0, 'f', 1)
        .arg(at(0.95), 0, 'f', 1)
        .arg(ms.constLast(), 0, 'f', 1);
}

} // namespace

ResponsivenessProbe::ResponsivenessProbe(QMainWindow *window, QAbstractItemView *list, int everyMs, QObject *parent)
    : QObject(parent)
    , m_window(window)
    , m_list(list)
{
    m_timer.setInterval(qMax(10, everyMs));
    connect(&m_timer, &QTimer::timeout, this, &ResponsivenessProbe::step);
    m_timer.start();
}

QString ResponsivenessProbe::summary() const
{
    return QStringLiteral("menus: %1 opened, %2; traffic list: %3 jumps to a random row of up to %4 rows, %5")
        .arg(m_menuMs.size())
        .arg(figures(m_menuMs))
        .arg(m_scrollMs.size())
        .arg(QLocale::c().toString(m_mostRows))
        .arg(figures(m_scrollMs));
}

void ResponsivenessProbe::step()
{
    if (m_waitingOn) // the last one not painted yet: it is still being waited for
        return;
    const bool menu = m_menuNext || !m_list;
    m_menuNext = !m_menuNext;
    if (menu)
        openMenu();
    else
        jump();
}

void ResponsivenessProbe::openMenu()
{
    QList<QMenu *> menus;
    for (QAction *action : m_window->menuBar()->actions()) {
        if (action->menu() && action->isVisible() && action->isEnabled())
            menus.append(action->menu());
    }
    if (menus.isEmpty())
        return;
    QMenu *menu = menus.at(m_nextMenu++ % menus.size());
    menu->installEventFilter(this);
    m_waitingOn = menu;
    m_clock.start();
    menu->popup(m_window->mapToGlobal(QPoint(20, 20)));
}

void ResponsivenessProbe::jump()
{
    QAbstractItemModel *model = m_list->model();
    const int rows = model ? model->rowCount() : 0;
    if (rows < 1000)
        return; // nothing to scroll through yet
    m_mostRows = qMax(m_mostRows, rows);
    m_seed = m_seed * 1664525u + 1013904223u;
    const int row = int(m_seed % quint32(rows));
    QScrollBar *bar = m_list->verticalScrollBar();
    const int before = bar->value();
    m_list->viewport()->installEventFilter(this);
    m_waitingOn = m_list->viewport();
    m_clock.start();
    m_list->scrollTo(model->index(row, 0), QAbstractItemView::PositionAtCenter);
    if (bar->value() == before) { // already in view: nothing to paint
        m_list->viewport()->removeEventFilter(this);
        m_waitingOn = nullptr;
    }
}

bool ResponsivenessProbe::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Paint && watched == m_waitingOn) {
        const double ms = double(m_clock.nsecsElapsed()) / 1e6;
        QWidget *widget = m_waitingOn;
        widget->removeEventFilter(this);
        m_waitingOn = nullptr;
        if (auto *menu = qobject_cast<QMenu *>(widget)) {
            m_menuMs.append(ms);
            QTimer::singleShot(0, menu, &QMenu::hide); // once this paint is done
        } else {
            m_scrollMs.append(ms);
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace mbscope
