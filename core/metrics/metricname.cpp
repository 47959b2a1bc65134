#include "metricname.h"

namespace mbscope {

namespace {

bool isNameChar(QChar c, bool first, bool colon)
{
    const char16_t u = c.unicode();
    if ((u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || u == '_')
        return true;
    if (colon && u == ':')
        return true;
    return !first && u >= '0' && u <= '9';
}

} // namespace

QString MetricName::problem(const QString &name, bool counter)
{
    if (name.isEmpty())
        return QStringLiteral("a metric name is empty");
    for (qsizetype i = 0; i < name.size(); ++i) {
        if (!isNameChar(name.at(i), i == 0, true))
            return QStringLiteral("metric name '%1': character %2 ('%3') is not allowed (letters, digits, '_' and ':', not a digit first)")
                .arg(name)
                .arg(i + 1)
                .arg(name.at(i));
    }
    if (counter && !name.endsWith(QLatin1String("_total")))
        return QStringLiteral("counter '%1' does not end in _total").arg(name);
    if (!counter && name.endsWith(QLatin1String("_total")))
        return QStringLiteral("'%1' ends in _total but is not a counter").arg(name);
    return {};
}

QString MetricName::labelProblem(const QString &label)
{
    if (label.isEmpty())
        return QStringLiteral("a label name is empty");
    for (qsizetype i = 0; i < label.size(); ++i) {
        if (!isNameChar(label.at(i), i == 0, false))
            return QStringLiteral("label name '%1': character %2 ('%3') is not allowed (letters, digits and '_', not a digit first)")
                .arg(label)
                .arg(i + 1)
                .arg(label.at(i));
    }
    if (label.startsWith(QLatin1String("__")))
        return QStringLiteral("label name '%1' starts with '__', which Prometheus reserves").arg(label);
    if (label == QLatin1String("le") || label == QLatin1String("quantile"))
        return QStringLiteral("label name '%1' is reserved for histograms and summaries").arg(label);
    return {};
}

} // namespace mbscope
