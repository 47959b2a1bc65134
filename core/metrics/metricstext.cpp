#include "metricstext.h"

#include <charconv>
#include <cmath>

namespace mbscope {

namespace {

// Help text: backslash and line feed escaped, and in OpenMetrics the double quote too.
QByteArray escapeHelp(const QString &help, MetricsText::Format format)
{
    const QByteArray utf8 = help.toUtf8();
    QByteArray out;
    out.reserve(utf8.size());
    for (const char c : utf8) {
        if (c == '\\')
            out += "\\\\";
        else if (c == '\n')
            out += "\\n";
        else if (c == '"' && format == MetricsText::Format::OpenMetrics)
            out += "\\\"";
        else
            out += c;
    }
    return out;
}

// A bound as OpenMetrics's canonical form writes it: a whole number keeps ".0".
QByteArray boundText(double bound)
{
    QByteArray text = MetricsText::number(bound);
    if (std::isfinite(bound) && !text.contains('.') && !text.contains('e'))
        text += ".0";
    return text;
}

void writeLabels(QByteArray &out, const QStringList &names, const QStringList &values, const char *extraName = nullptr,
                 const QByteArray &extraValue = {})
{
    if (names.isEmpty() && !extraName)
        return;
    out += '{';
    bool first = true;
    for (qsizetype i = 0; i < names.size(); ++i) {
        if (!first)
            out += ',';
        first = false;
        out += names.at(i).toLatin1();
        out += "=\"";
        out += MetricsText::escapeLabelValue(values.value(i));
        out += '"';
    }
    if (extraName) {
        if (!first)
            out += ',';
        out += extraName;
        out += "=\"";
        out += extraValue;
        out += '"';
    }
    out += '}';
}

void writeSample(QByteArray &out, const QByteArray &name, const QStringList &labelNames, const QStringList &values,
                 double value, const char *extraName = nullptr, const QByteArray &extraValue = {})
{
    out += name;
    writeLabels(out, labelNames, values, extraName, extraValue);
    out += ' ';
    out += MetricsText::number(value);
    out += '\n';
}

const char *typeName(MetricType type)
{
    switch (type) {
    case MetricType::Gauge:
        return "gauge";
    case MetricType::Counter:
        return "counter";
    case MetricType::Histogram:
        return "histogram";
    }
    return "untyped";
}

void writeFamily(QByteArray &out, const MetricFamily &family, MetricsText::Format format)
{
    const QByteArray name = family.name().toLatin1();
    QByteArray familyName = name;
    // OpenMetrics names a counter's family without the _total its samples carry.
    if (format == MetricsText::Format::OpenMetrics && family.type() == MetricType::Counter && name.endsWith("_total"))
        familyName.chop(6);
    out += "# HELP " + familyName + ' ' + escapeHelp(family.help(), format) + '\n';
    out += "# TYPE " + familyName + ' ' + typeName(family.type()) + '\n';
    const QStringList &labels = family.labelNames();
    for (const auto &[values, series] : family.series()) {
        if (family.type() != MetricType::Histogram) {
            writeSample(out, name, labels, values, series.value);
            continue;
        }
        quint64 cumulative = 0;
        const QByteArray bucket = name + "_bucket";
        for (qsizetype i = 0; i < family.buckets().size(); ++i) {
            cumulative += series.bucketCounts.value(i);
            writeSample(out, bucket, labels, values, double(cumulative), "le", boundText(family.buckets().at(i)));
        }
        writeSample(out, bucket, labels, values, double(series.count), "le", "+Inf");
        writeSample(out, name + "_sum", labels, values, series.sum);
        writeSample(out, name + "_count", labels, values, double(series.count));
    }
}

} // namespace

QByteArray MetricsText::write(const MetricsRegistry &registry, Format format)
{
    QByteArray out;
    for (const MetricFamily *family : registry.families())
        writeFamily(out, *family, format);
    if (format == Format::OpenMetrics)
        out += "# EOF\n";
    return out;
}

QByteArray MetricsText::contentType(Format format)
{
    return format == Format::OpenMetrics ? QByteArrayLiteral("application/openmetrics-text; version=1.0.0; charset=utf-8")
                                         : QByteArrayLiteral("text/plain; version=0.0.4; charset=utf-8");
}

MetricsText::Format MetricsText::negotiate(QByteArrayView acceptHeader)
{
    return QByteArray(acceptHeader.data(), acceptHeader.size()).contains("application/openmetrics-text")
        ? Format::OpenMetrics
        : Format::Prometheus;
}

QByteArray MetricsText::number(double value)
{
    if (std::isnan(value))
        return QByteArrayLiteral("NaN");
    if (std::isinf(value))
        return value > 0 ? QByteArrayLiteral("+Inf") : QByteArrayLiteral("-Inf");
    char buffer[32];
    // General notation (as Go's %g): 0.0005 stays "0.0005", 1e-09 and 1.5e+300 take an exponent.
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general);
    return QByteArray(buffer, result.ptr - buffer);
}

QByteArray MetricsText::escapeLabelValue(const QString &value)
{
    const QByteArray utf8 = value.toUtf8();
    QByteArray out;
    out.reserve(utf8.size());
    for (const char c : utf8) {
        if (c == '\\')
            out += "\\\\";
        else if (c == '"')
            out += "\\\"";
        else if (c == '\n')
            out += "\\n";
        else
            out += c;
    }
    return out;
}

} // namespace mbscope
