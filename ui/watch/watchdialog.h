#pragma once

#include "watch/watchdefinition.h"

#include <QtWidgets/QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace mbscope {

class AddressField;
class WatchPointTable;
class WatchRuleTable;

// Watches > New watch (and Edit watch): a watch typed in full. The target (a link URL), unit,
// function, start address (as the composer's address field: decimal, hex or Modicon), quantity,
// interval and Enron 32-bit flag; its points (names, formats, units, scaling, writable) and its
// rules. OK is refused with every problem listed, each saying where.
class WatchDialog : public QDialog
{
    Q_OBJECT
public:
    explicit WatchDialog(QWidget *parent = nullptr);

    void setWatch(const WatchDefinition &watch);
    // The watch as typed; problems lists what is wrong (empty: usable).
    [[nodiscard]] WatchDefinition watch(QStringList *problems) const;
    // Names of the other watches (a name must be unique in the session).
    void setTakenNames(const QStringList &names) { m_taken = names; }

    [[nodiscard]] QLineEdit *nameEdit() const { return m_name; }
    [[nodiscard]] QLineEdit *targetEdit() const { return m_target; }
    [[nodiscard]] QComboBox *functionBox() const { return m_function; }
    [[nodiscard]] AddressField *addressField() const { return m_address; }
    [[nodiscard]] QSpinBox *quantitySpin() const { return m_quantity; }
    [[nodiscard]] QSpinBox *intervalSpin() const { return m_interval; }
    [[nodiscard]] QSpinBox *unitSpin() const { return m_unit; }
    [[nodiscard]] QCheckBox *enronBox() const { return m_enron; }
    [[nodiscard]] WatchPointTable *pointTable() const { return m_points; }
    [[nodiscard]] WatchRuleTable *ruleTable() const { return m_rules; }

    void done(int result) override;

private:
    void onFunctionChanged();

    QLineEdit *m_name = nullptr;
    QLineEdit *m_target = nullptr;
    QSpinBox *m_unit = nullptr;
    QComboBox *m_function = nullptr;
    AddressField *m_address = nullptr;
    QSpinBox *m_quantity = nullptr;
    QSpinBox *m_interval = nullptr;
    QCheckBox *m_enron = nullptr;
    QCheckBox *m_enabled = nullptr;
    WatchPointTable *m_points = nullptr;
    WatchRuleTable *m_rules = nullptr;
    QLabel *m_problems = nullptr;
    QStringList m_taken;
    QString m_profileBlock;
};

} // namespace mbscope
