#include "serialportcombo.h"

namespace mbscope {

SerialPortCombo::SerialPortCombo(QWidget *parent)
    : QComboBox(parent)
{
}

void SerialPortCombo::showPopup()
{
    if (m_refresh)
        m_refresh();
    QComboBox::showPopup();
}

} // namespace mbscope
