#pragma once

#include <QtWidgets/QDialog>

#include <chrono>

class QCheckBox;
class QLabel;
class QSpinBox;

namespace mbscope {

struct DeviceLimits;

// The device's pace on the window's target (the URL's gap=, warmup= and close=each, which every
// request the window sends keeps: the composer's Send, Poll and sweeps): the gap between
// requests, the wait after the link opens, and a new connection for each request. "From
// profile…" fills them from a device profile's limits (minGapMs, warmUpMs, closesAfterAnswer,
// with some to spare: DeviceLimits::clientGap), as poll --profile keeps them.
class PaceDialog : public QDialog
{
    Q_OBJECT
public:
    struct Pace {
        std::chrono::milliseconds gap{0};
        std::chrono::milliseconds warmUp{0};
        bool closeAfterAnswer = false;
        friend bool operator==(const Pace &, const Pace &) = default;
    };

    // streamLink: the target is a stream (tcp, rtu-tcp, ascii-tcp, tls), where a device can hang
    // up after each answer; elsewhere that box is off and disabled.
    PaceDialog(const Pace &pace, bool streamLink, QWidget *parent = nullptr);

    [[nodiscard]] Pace pace() const;
    // Fills the fields from a profile file (what "From profile…" does after its file dialog);
    // false with the status line saying what is wrong.
    bool takeProfile(const QString &path);

private:
    void chooseProfile();

    QSpinBox *m_gap = nullptr;
    QSpinBox *m_warmUp = nullptr;
    QCheckBox *m_close = nullptr;
    QLabel *m_status = nullptr;
    bool m_streamLink = false;
};

} // namespace mbscope
