#pragma once

#include <QtWidgets/QDialog>

class QComboBox;
class QLineEdit;
class QSpinBox;

namespace mbscope {

// Watches > New watches from a device profile: which profile (a shipped one by name, or a file),
// which unit of it, the target and the interval. The workspace makes a watch per group of
// entries (WatchFactory::fromProfile).
class WatchProfileDialog : public QDialog
{
    Q_OBJECT
public:
    explicit WatchProfileDialog(QWidget *parent = nullptr);

    void setTarget(const QString &target);
    void setProfile(const QString &nameOrPath);

    [[nodiscard]] QString profile() const;
    [[nodiscard]] int unit() const;
    [[nodiscard]] QString target() const;
    [[nodiscard]] int intervalMs() const;

private:
    QComboBox *m_profile;
    QSpinBox *m_unit;
    QLineEdit *m_target;
    QSpinBox *m_interval;
};

} // namespace mbscope
