#pragma once

#include "profile/deviceprofile.h"

#include <QtCore/QByteArray>
#include <QtCore/QObject>

#include <functional>

namespace mbscope {

class AnalysisDock;
class LatencyTimePanel;
class LinkController;
class RegisterTable;
class RegisterTrendPanel;
class SweepPanel;

// The Analysis dock's time panels, wired to the window's link: Register trends get every
// transaction batch (cleared when the target changes; Latency over time gets its batches from
// LatencyAnalysis's source, the bench or a watch), the trends read the
// link's framing and take registers from the Registers table, and Sweep polls the composer's
// request through the same LinkController. MainWindow only constructs this and passes profiles.
class TrendPanels : public QObject
{
    Q_OBJECT

public:
    TrendPanels(AnalysisDock *dock, LinkController *link, RegisterTable *registers,
                std::function<QByteArray()> requestSource, QObject *parent = nullptr);

    // The profile whose register names, formats and scaling the trend list offers.
    void setProfile(const UnitProfile &unit, const QString &profileName);

    [[nodiscard]] LatencyTimePanel *latency() const { return m_latency; }
    [[nodiscard]] RegisterTrendPanel *trends() const { return m_trends; }
    [[nodiscard]] SweepPanel *sweep() const { return m_sweep; }

private:
    LatencyTimePanel *m_latency;
    RegisterTrendPanel *m_trends;
    SweepPanel *m_sweep;
};

} // namespace mbscope
