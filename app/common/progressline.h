#pragma once

#include <QtCore/QString>

namespace mbscope::app {

// A live status line on the terminal: each show() rewrites it in place (carriage return, erase to
// the end of the line), cut to the terminal's width so that it never wraps. Only when standard
// error is a terminal: redirected to a file or a pipe it writes nothing, so logs and scripts see
// only the results. Standard error keeps standard output clean for the statistics or JSON.
class ProgressLine
{
public:
    ProgressLine();
    ~ProgressLine(); // clears the line

    [[nodiscard]] bool isEnabled() const { return m_enabled; }
    void show(const QString &text);
    // Erases the line, leaving the cursor at its start for what follows.
    void clear();

private:
    bool m_enabled = false;
    bool m_shown = false;
};

} // namespace mbscope::app
