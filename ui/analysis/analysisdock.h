#pragma once

#include <QtWidgets/QWidget>

class QTabWidget;

namespace mbscope {

// What the "Analysis" dock holds: one tab per analysis panel (latency histogram, compare, latency
// over time, register trends, sweep). Each panel is its own class and is added by whoever builds
// it; the dock only keeps them side by side.
class AnalysisDock : public QWidget
{
    Q_OBJECT

public:
    explicit AnalysisDock(QWidget *parent = nullptr);

    // Adds panel as a tab named title (the dock takes ownership); the first panel is shown.
    void addPanel(QWidget *panel, const QString &title);
    // Brings panel's tab to the front (a panel that is not in the dock is ignored).
    void showPanel(QWidget *panel);

    [[nodiscard]] QTabWidget *tabs() const { return m_tabs; }

private:
    QTabWidget *m_tabs;
};

} // namespace mbscope
