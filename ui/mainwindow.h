#pragma once

#include <QtWidgets/QMainWindow>

class QTabWidget;

namespace mbscope {

class DecodePanel;

// The window only assembles: panels are their own classes, and each later feature (connection,
// traffic, polling, simulator) adds a tab or a dock here, not its logic.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);

    [[nodiscard]] DecodePanel *decodePanel() const { return m_decodePanel; }

private:
    void createMenus();
    void showAbout();

    QTabWidget *m_tabs = nullptr;
    DecodePanel *m_decodePanel = nullptr;
};

} // namespace mbscope
