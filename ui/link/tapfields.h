#pragma once

#include "tapsetup.h"

#include "session/sessiontap.h"

#include <QtWidgets/QWidget>

#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace mbscope {

// The connection bar's Tap row: where masters connect (listening URLs, as `mbscope tap --listen`
// takes them), further routes (`--route`), read-only with how writes are refused, what a master
// gets when its device does not answer, retries, and, while the tap runs, what it has done. The
// bar's target and timeout complete it into a TapSetup; what was typed is kept in QSettings
// ("tap/...") for the next start.
class TapFields : public QWidget
{
    Q_OBJECT
public:
    explicit TapFields(QWidget *parent = nullptr);

    // The tap these fields and the bar's target make: the routes typed, then the target for every
    // unit they leave; nullopt with *error naming the field and what is wrong.
    [[nodiscard]] std::optional<TapSetup> setup(const LinkUrl &target, int timeoutMs, QString *error) const;
    // Fills the fields from a setup (the routes but the last, which is the bar's target).
    void setSetup(const TapSetup &setup);
    // Keeps the fields for the next start.
    void remember() const;
    // The fields as a session keeps them (what was typed, checked when the tap starts), and back.
    [[nodiscard]] SessionTap sessionTap() const;
    void setSessionTap(const SessionTap &tap);

    // A running tap's fields are what it uses: locked until it stops.
    void setRunning(bool running);
    void showCounters(const TapCounters &counters, int waiting);
    [[nodiscard]] QString countersText() const;

    [[nodiscard]] QLineEdit *listenEdit() const { return m_listenEdit; }
    [[nodiscard]] QLineEdit *routesEdit() const { return m_routesEdit; }
    [[nodiscard]] QCheckBox *readOnlyCheck() const { return m_readOnlyCheck; }

Q_SIGNALS:
    void edited();

private:
    QLineEdit *m_listenEdit = nullptr;
    QLineEdit *m_routesEdit = nullptr;
    QCheckBox *m_readOnlyCheck = nullptr;
    QComboBox *m_refusalCombo = nullptr;
    QComboBox *m_noAnswerCombo = nullptr;
    QSpinBox *m_retriesSpin = nullptr;
    QLabel *m_countersLabel = nullptr;
};

} // namespace mbscope
