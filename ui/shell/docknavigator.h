#pragma once

class QDockWidget;
class QMainWindow;

namespace mbscope {

// How the window's docks are reached: every dock's panel in a scroll area (so a tall panel
// scrolls instead of holding the whole window at its minimum height), and F6 to the next open
// dock in the order the user sees them (tab by tab, then the docks on their own by name), its
// first widget that takes the keyboard focused.
class DockNavigator
{
public:
    explicit DockNavigator(QMainWindow *window);

    // Puts each dock's panel in a scroll area, except the dock given (one that scrolls already).
    void makeScrollable(const QDockWidget *except);
    // Brings the open dock after the focused one forward and focuses it; the dock, or nullptr
    // when no dock is open.
    QDockWidget *focusNext();

private:
    QMainWindow *m_window;
};

} // namespace mbscope
