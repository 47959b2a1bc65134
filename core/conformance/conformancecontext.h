#pragma once

#include "conformancelink.h"
#include "conformancesettings.h"

#include <QtCore/QByteArray>
#include <QtCore/QMap>
#include <QtCore/QString>

namespace mbscope {

// Whether the device supports a function code, as its answers (the survey) say. (Not
// discovery's FunctionSupport, the map scan's record of one function: one name, two types, broke
// the build once both reached one translation unit.)
enum class SurveyedSupport : quint8 {
    Unknown,     // not asked, or no usable answer
    Supported,   // a normal answer, or an exception other than 01
    Unsupported, // exception 01
    Silent,      // no answer at all to a well-formed request
    NotSurveyed, // the link closed each time the survey asked: nothing is known, its checks are skipped
};

// What a check works with: the settings, the link, and what the survey learnt of the device.
class ConformanceContext
{
public:
    ConformanceContext(const ConformanceSettings &settings, ConformanceLink &link)
        : m_settings(settings)
        , m_link(link)
    {
        m_readable = settings.readable;
    }

    [[nodiscard]] const ConformanceSettings &settings() const { return m_settings; }
    [[nodiscard]] ConformanceLink &link() { return m_link; }
    [[nodiscard]] quint8 unit() const { return m_settings.unit; }

    [[nodiscard]] SurveyedSupport support(quint8 function) const { return m_support.value(function, SurveyedSupport::Unknown); }
    void setSupport(quint8 function, SurveyedSupport support) { m_support.insert(function, support); }
    [[nodiscard]] const QMap<quint8, SurveyedSupport> &supportTable() const { return m_support; }
    // Functions whose every ask by the survey was sent and met the connection closing instead of
    // an answer (their support is Silent: no answer at all).
    [[nodiscard]] const QList<quint8> &closedOn() const { return m_closedOn; }
    void setClosedOn(quint8 function) { m_closedOn.append(function); }
    // An address of table the device answered a read of (-1: none known).
    [[nodiscard]] int readable(SimTable table) const { return m_readable[int(table)]; }
    void setReadable(SimTable table, int address) { m_readable[int(table)] = address; }

    // pdu to the unit under test, in the link's framing.
    [[nodiscard]] ConformanceExchange ask(const QByteArray &pdu) { return m_link.ask(unit(), pdu); }

private:
    const ConformanceSettings &m_settings;
    ConformanceLink &m_link;
    QMap<quint8, SurveyedSupport> m_support;
    QList<quint8> m_closedOn;
    std::array<int, SimTableCount> m_readable{};
};

} // namespace mbscope
