#pragma once

#include <QtCore/QString>

namespace mbscope {

// The names the exposition format allows and the conventions Prometheus asks of them
// (prometheus.io/docs/practices/naming): what is wrong with a name, or an empty string.
class MetricName
{
public:
    // [a-zA-Z_:][a-zA-Z0-9_:]*; counters end in _total and name no other suffix after it.
    [[nodiscard]] static QString problem(const QString &name, bool counter);
    // [a-zA-Z_][a-zA-Z0-9_]*, not starting with "__" (reserved), not "le" or "quantile"
    // (histograms and summaries use them).
    [[nodiscard]] static QString labelProblem(const QString &label);
};

} // namespace mbscope
