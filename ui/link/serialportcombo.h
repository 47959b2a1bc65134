#pragma once

#include <QtWidgets/QComboBox>

#include <functional>

namespace mbscope {

// The serial port list of the connection bar: an editable combo that looks for ports again each
// time it opens, so an adapter plugged in after the window started is there without Refresh.
class SerialPortCombo : public QComboBox
{
    Q_OBJECT
public:
    explicit SerialPortCombo(QWidget *parent = nullptr);

    // Called before the list opens (ConnectionBar::refreshSerialPorts).
    void setRefresh(std::function<void()> refresh) { m_refresh = std::move(refresh); }

    void showPopup() override;

private:
    std::function<void()> m_refresh;
};

} // namespace mbscope
