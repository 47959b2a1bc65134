#include "sim/lineresponder.h"

#include "profile/linetemplate.h"
#include "sim/simunit.h"

#include <QtCore/QRegularExpressionMatch>

namespace mbscope {

LineAnswer LineResponder::respond(const LineTable &table, QByteArrayView frame, const UnitOf &unitOf)
{
    LineAnswer out;
    // Frames are bytes; Latin-1 maps each byte to one character, so patterns may name any byte
    // (\x05 for ENQ) and the answer's characters go back to the same bytes.
    const QString text = QString::fromLatin1(frame.data(), frame.size());
    for (const LineRule &rule : table.rules) {
        const QRegularExpressionMatch match = rule.request.match(text);
        if (!match.hasMatch())
            continue;
        out.matched = true;
        out.rule = rule.name;
        const bool named = rule.request.namedCaptureGroups().contains(table.unitCapture);
        int id = -1;
        if (named) {
            bool ok = false;
            id = match.captured(table.unitCapture).toInt(&ok, 10);
            if (!ok) {
                out.note = QStringLiteral("%1: unit '%2' is not a number: ignored").arg(rule.name, match.captured(table.unitCapture));
                return out;
            }
        }
        SimUnit *unit = unitOf(id);
        if (!unit) {
            out.note = QStringLiteral("%1: no unit %2 here: ignored").arg(rule.name).arg(id);
            out.unitId = id;
            out.unitMissing = true;
            return out;
        }
        out.unitId = unit->id();
        const auto capture = [&match](const QString &name) { return match.captured(name); };
        const auto lookup = [unit](SimTable t, int first, int count) -> std::optional<QList<quint16>> {
            const QList<quint16> values = unit->values(t, first, count);
            if (values.isEmpty())
                return std::nullopt;
            return values;
        };
        QStringList notes;
        for (const LineWrite &w : rule.writes) {
            QString error;
            const auto address = LineTemplate::expand(w.address, capture, lookup, &error);
            const auto value = LineTemplate::expand(w.value, capture, lookup, &error);
            bool okA = false;
            bool okV = false;
            const int a = address ? address->toInt(&okA, 10) : -1;
            const int v = value ? value->toInt(&okV, 10) : 0;
            if (!okA || !okV || a < 0 || a > 65535 || v < 0 || v > 65535) {
                notes.append(QStringLiteral("write of '%1' at '%2' not done: not numbers").arg(value.value_or(QString()), address.value_or(QString())));
                continue;
            }
            const quint16 stored = isBitTable(w.table) ? quint16(v != 0) : quint16(v);
            if (unit->clientWrite(w.table, a, {stored}))
                notes.append(QStringLiteral("%1 %2 = %3").arg(QLatin1String(simTableName(w.table))).arg(a).arg(stored));
            else
                notes.append(QStringLiteral("%1 %2 cannot be written (missing or read-only)").arg(QLatin1String(simTableName(w.table))).arg(a));
        }
        out.note = notes.join(QStringLiteral("; "));
        if (rule.silent)
            return out;
        QString error;
        const auto answer = LineTemplate::expand(rule.answer, capture, lookup, &error);
        if (!answer) {
            out.note = QStringLiteral("%1: %2: no answer").arg(rule.name, error);
            return out;
        }
        out.answers = true;
        out.bytes = answer->toLatin1();
        return out;
    }
    out.note = QStringLiteral("no rule's request pattern matches: ignored");
    return out;
}

} // namespace mbscope
