#include "docknavigator.h"

#include <QtCore/QHash>
#include <QtCore/QTimer>
#include <QtGui/QAction>
#include <QtWidgets/QApplication>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QMainWindow>
#include <QtWidgets/QScrollArea>
#include <QtWidgets/QTabBar>

#include <algorithm>
#include <climits>

namespace mbscope {

DockNavigator::DockNavigator(QMainWindow *window)
    : m_window(window)
{
}

void DockNavigator::makeScrollable(const QDockWidget *except)
{
    // A panel taller than its dock scrolls instead of holding the whole window at its minimum
    // height: tabbed docks share one area, sized by the tallest panel's minimum. The traffic list
    // scrolls already.
    for (QDockWidget *dock : m_window->findChildren<QDockWidget *>()) {
        if (dock == except || qobject_cast<QScrollArea *>(dock->widget()))
            continue;
        auto *scroll = new QScrollArea(dock);
        scroll->setObjectName(dock->objectName() + QStringLiteral("Scroll"));
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidgetResizable(true);
        scroll->setWidget(dock->widget());
        dock->setWidget(scroll);
    }
}

QDockWidget *DockNavigator::focusNext()
{
    QList<QDockWidget *> docks;
    for (QDockWidget *dock : m_window->findChildren<QDockWidget *>()) {
        // Tabbed docks behind another are hidden, yet open: raising them brings them forward.
        if (dock->isVisible() || !m_window->tabifiedDockWidgets(dock).isEmpty())
            docks.append(dock);
    }
    if (docks.isEmpty())
        return nullptr;
    // In the order the user sees them: tab by tab, then the docks on their own by name.
    // (findChildren's order is no order: raise() moves a dock to the end of it, which made F6
    // go back and forth between the first two docks.)
    QHash<QDockWidget *, int> rank;
    int tabRank = 0;
    for (QTabBar *tabs : m_window->findChildren<QTabBar *>(QString(), Qt::FindDirectChildrenOnly)) {
        for (int i = 0; i < tabs->count(); ++i)
            rank.insert(reinterpret_cast<QDockWidget *>(tabs->tabData(i).value<quintptr>()), tabRank++);
    }
    std::stable_sort(docks.begin(), docks.end(), [&rank](QDockWidget *a, QDockWidget *b) {
        const int ra = rank.value(a, INT_MAX);
        const int rb = rank.value(b, INT_MAX);
        return ra != rb ? ra < rb : a->objectName() < b->objectName();
    });
    int current = -1;
    for (int i = 0; i < docks.size(); ++i) {
        if (docks.at(i)->isAncestorOf(QApplication::focusWidget()))
            current = i;
    }
    // The next open dock (a closed one stays closed and is passed by). A dock tabbed behind
    // another is open but hidden; it becomes visible only in the next layout pass after its tab
    // is chosen, so "open" is its View menu check, not its visibility (which sent F6 back and
    // forth between the first two docks).
    QDockWidget *next = nullptr;
    for (int step = 1; step <= docks.size() && !next; ++step) {
        QDockWidget *candidate = docks.at((current + step) % docks.size());
        if (candidate->toggleViewAction()->isChecked())
            next = candidate;
    }
    if (!next)
        return nullptr;
    // QMainWindow keeps each tabbed dock's pointer as its tab's data: choosing that tab brings
    // the dock forward.
    for (QTabBar *tabs : m_window->findChildren<QTabBar *>(QString(), Qt::FindDirectChildrenOnly)) {
        for (int i = 0; i < tabs->count(); ++i) {
            if (tabs->tabData(i).value<quintptr>() == quintptr(next))
                tabs->setCurrentIndex(i);
        }
    }
    // The dock's first widget that takes the keyboard (the traffic list's filter, a table),
    // once the dock is shown.
    const auto focusDock = [](QDockWidget *dock) {
        QWidget *target = dock->widget();
        for (QWidget *child : dock->widget()->findChildren<QWidget *>()) {
            if ((child->focusPolicy() & Qt::TabFocus) && child->isVisibleTo(dock)) {
                target = child;
                break;
            }
        }
        target->setFocus(Qt::ShortcutFocusReason);
    };
    if (next->isVisible()) {
        next->raise();
        focusDock(next);
    } else {
        auto *once = new QObject(m_window);
        QObject::connect(next, &QDockWidget::visibilityChanged, once, [once, next, focusDock](bool visible) {
            if (!visible)
                return;
            focusDock(next);
            once->deleteLater();
        });
        QTimer::singleShot(1000, once, &QObject::deleteLater); // never shown: forget it
        next->raise();
    }
    return next;
}

} // namespace mbscope
