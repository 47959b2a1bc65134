#pragma once

#include "watch/watchdefinition.h"

#include <QtWidgets/QDialog>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace mbscope {

// Watches > CSV log settings: the folder the watches' CSV files go to, a row per poll or only
// when a value changed, and when a new file starts (a size in MiB, an age in minutes; 0: never).
class WatchLogDialog : public QDialog
{
    Q_OBJECT
public:
    explicit WatchLogDialog(QWidget *parent = nullptr);

    void setSettings(const WatchLogSettings &settings);
    [[nodiscard]] WatchLogSettings settings() const;

    [[nodiscard]] QLineEdit *folderEdit() const { return m_folder; }
    [[nodiscard]] QComboBox *modeBox() const { return m_mode; }
    [[nodiscard]] QSpinBox *rollMiBSpin() const { return m_rollMiB; }
    [[nodiscard]] QSpinBox *rollMinutesSpin() const { return m_rollMinutes; }

private:
    QLineEdit *m_folder;
    QComboBox *m_mode;
    QSpinBox *m_rollMiB;
    QSpinBox *m_rollMinutes;
    QCheckBox *m_enabled;
};

} // namespace mbscope
