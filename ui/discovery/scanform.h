#pragma once

#include "job/jobprogress.h"
#include "transport/linkurl.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

#include <functional>
#include <optional>

class QComboBox;
class QFormLayout;
class QHBoxLayout;
class QLabel;
class QLayout;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QWidget;

namespace mbscope {

// What the scan dialogs share: their fields, rows and status line, and how they say a duration.
class ScanForm
{
    Q_DECLARE_TR_FUNCTIONS(ScanForm)
public:
    [[nodiscard]] static QSpinBox *spinBox(QWidget *parent, const char *objectName, int low, int high, int value,
                                           const QString &suffix = {});
    // The four reads (01-04), with the function code as item data; 03 chosen.
    static void addReadFunctions(QComboBox *box);
    // A form row of several fields whose label's mnemonic goes to buddy.
    static void addRow(QWidget *parent, QFormLayout *form, const QString &label, QWidget *buddy, QLayout *fields);
    // Start, Stop and the progress bar, side by side.
    [[nodiscard]] static QHBoxLayout *runRow(QPushButton *start, QPushButton *stop, QProgressBar *progress);
    // The status line in red: what is wrong (a text of several lines keeps them).
    static void showProblem(QLabel *status, const QString &text);
    // The link typed in target; nullopt with the reason (or emptyHint for an empty field) shown.
    [[nodiscard]] static std::optional<LinkUrl> target(const QLineEdit *target, QLabel *status, const QString &emptyHint);
    // A running scan's progress: the bar at done of total, the status line "<counts>, about X left"
    // (counts: "12 of 40 ids asked, 1 found").
    static void showProgress(QProgressBar *bar, QLabel *status, const JobProgress &progress, const QString &counts);
    // Merges what a scan found into an existing profile file at path (read, merge(text, &said,
    // &problem), saved whole or not at all; the file and the result must load as the simulator loads
    // profiles), the status line saying what was recorded or what is wrong. The scans' "Record ... in profile" buttons (ProfileDraft::mergeLimits, mergeUnits).
    using ProfileMerge = std::function<QByteArray(const QByteArray &profile, QString *said, QString *problem)>;
    static bool mergeIntoProfile(const QString &path, const ProfileMerge &merge, QLabel *status);
    // "4.2 s" under a minute, "3 min 20 s" from one.
    [[nodiscard]] static QString duration(qint64 ms);
};

} // namespace mbscope
