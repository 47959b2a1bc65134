#pragma once

#include "discovery/timingscanner.h"

#include <QtWidgets/QTreeWidget>

namespace mbscope {

// A timing scan's measurements as a list: the first answer after connecting, each gap tried with
// its answers and failures, the shortest clean gap, the largest read, pipelining and clients at
// once (when the link has them), then the settings they recommend.
class TimingResultTree : public QTreeWidget
{
    Q_OBJECT
public:
    enum Column { MeasureColumn, ResultColumn, ColumnCount };

    explicit TimingResultTree(QWidget *parent = nullptr);

    void showReport(const TimingScanSettings &settings, const TimingReport &report);
    // The recommended settings as text for the clipboard: mbscope's watch link and poll options,
    // and Telegraf's modbus input (the lines `mbscope scan --timing` prints).
    [[nodiscard]] static QString settingsText(const TimingReport &report);
};

} // namespace mbscope
