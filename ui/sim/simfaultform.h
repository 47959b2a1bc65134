#pragma once

#include "profile/faultrule.h"

#include <QtWidgets/QWidget>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace mbscope {

// The fault rules of one running simulator, switched while clients poll: a form for every kind of
// the profile language (docs/profiles.md: delay drawn from a distribution, drop, wrong CRC or LRC,
// wrong transaction id or unit, exception, fewer registers, chunks, trickle, junk, duplicate,
// close) with its parameters, each for a unit, a function code and an address range or for all,
// with a probability; the rules in force
// as a list (remove one, remove all); and a rules file (the format of `mbscope simulate
// --faults`, docs/profiles.md) that replaces them. Every change emits rulesChanged with the whole
// set: the simulator's next request sees it. A file that does not read is reported with where it
// is wrong, and the rules in force stay.
class SimFaultForm : public QWidget
{
    Q_OBJECT

public:
    explicit SimFaultForm(QWidget *parent = nullptr);

    // Shows the rules in force (the selected simulator's); emits nothing.
    void setRules(const FaultRuleSet &rules);
    [[nodiscard]] FaultRuleSet rules() const { return m_rules; }
    // The rule the form describes now.
    [[nodiscard]] FaultRule formRule() const;
    // Adds formRule() to the rules in force.
    void addFormRule();
    void removeRule(int index);
    void clearRules();
    // Replaces the rules by a faults file's; false (the rules in force kept) when it does not read.
    bool loadRulesFile(const QString &path);
    [[nodiscard]] QString message() const;

    // "exception 06 for unit 1, function 03 (probability 0.5)" and the like.
    [[nodiscard]] static QString describe(const FaultRule &rule);

Q_SIGNALS:
    void rulesChanged(const mbscope::FaultRuleSet &rules);

private:
    void buildForm();
    void updateFieldVisibility();
    void showRules();
    void apply(const FaultRuleSet &rules);
    void chooseRulesFile();

    FaultRuleSet m_rules;
    QFormLayout *m_form = nullptr;
    QComboBox *m_kind = nullptr;
    QSpinBox *m_unit = nullptr;
    QSpinBox *m_function = nullptr;
    QDoubleSpinBox *m_probability = nullptr;
    QComboBox *m_distribution = nullptr;
    QDoubleSpinBox *m_fixedMs = nullptr;
    QDoubleSpinBox *m_meanMs = nullptr;
    QDoubleSpinBox *m_stddevMs = nullptr;
    QDoubleSpinBox *m_minMs = nullptr;
    QDoubleSpinBox *m_maxMs = nullptr;
    QSpinBox *m_exceptionCode = nullptr;
    QSpinBox *m_firstAddress = nullptr;
    QSpinBox *m_lastAddress = nullptr;
    QSpinBox *m_delta = nullptr;
    QSpinBox *m_fewer = nullptr;
    QSpinBox *m_chunkBytes = nullptr;
    QDoubleSpinBox *m_gapMs = nullptr;
    QSpinBox *m_junkBefore = nullptr;
    QSpinBox *m_junkAfter = nullptr;
    QSpinBox *m_copies = nullptr;
    QDoubleSpinBox *m_bitErrorRate = nullptr;
    QComboBox *m_closeWhen = nullptr;
    QPushButton *m_add = nullptr;
    QListWidget *m_list = nullptr;
    QPushButton *m_remove = nullptr;
    QPushButton *m_clear = nullptr;
    QPushButton *m_load = nullptr;
    QLabel *m_message = nullptr;
};

} // namespace mbscope
