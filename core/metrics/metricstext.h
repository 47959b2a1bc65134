#pragma once

#include "metricsregistry.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>

namespace mbscope {

// The text exposition of a registry: Prometheus's text format 0.0.4 (what `promtool check metrics`
// reads and most scrapers accept) or OpenMetrics 1.0.0 (what Prometheus asks for first). They differ
// in a counter's family name (OpenMetrics names it without _total), in escaping '"' in help text,
// and in the closing "# EOF" line. Histogram bounds are written the same way in both ("1.0", never
// "1"), so that a series keeps its labels whichever format a scrape negotiated.
class MetricsText
{
public:
    enum class Format : quint8 { Prometheus, OpenMetrics };

    [[nodiscard]] static QByteArray write(const MetricsRegistry &registry, Format format);
    [[nodiscard]] static QByteArray contentType(Format format);
    // OpenMetrics when the Accept header names it (as Prometheus's scrapes do), else the text format.
    [[nodiscard]] static Format negotiate(QByteArrayView acceptHeader);

    // Go's strconv formatting as the formats expect it: shortest round trip, "+Inf", "-Inf", "NaN".
    [[nodiscard]] static QByteArray number(double value);
    // A label value: backslash, double quote and line feed escaped.
    [[nodiscard]] static QByteArray escapeLabelValue(const QString &value);
};

} // namespace mbscope
