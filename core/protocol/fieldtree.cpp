#include "fieldtree.h"

#include "hexformat.h"

#include <cstring>

namespace mbscope {

QString severityName(Severity severity)
{
    switch (severity) {
    case Severity::Ok: return QStringLiteral("ok");
    case Severity::Info: return QStringLiteral("info");
    case Severity::Warning: return QStringLiteral("warning");
    case Severity::Error: return QStringLiteral("error");
    }
    return QStringLiteral("ok");
}

void FieldTree::reset(const QByteArray &frame)
{
    m_frame = frame;
    m_fields.clear();
    m_links.clear();
    m_top = Links{};
}

int FieldTree::add(int parent, const char *key, const char *name, int offset, int length,
                   quint64 value, ValueFormat format, const char *meaning)
{
    Field &f = m_fields.emplace_back();
    f.key = key;
    f.name = name;
    f.meaning = meaning;
    f.value = value;
    f.offset = offset;
    f.length = length;
    f.parent = parent;
    f.format = format;
    const int index = int(m_fields.size()) - 1;
    m_links.emplace_back();
    if (parent < -1 || parent >= index)
        return index; // no parent to list it under (the dissectors never do this)
    Links &up = parent >= 0 ? m_links[size_t(parent)] : m_top;
    if (up.lastChild >= 0)
        m_links[size_t(up.lastChild)].nextSibling = index;
    else
        up.firstChild = index;
    up.lastChild = index;
    return index;
}

void FieldTree::flag(int index, Severity severity, const QString &message)
{
    Field &f = m_fields[size_t(index)];
    if (severity > f.severity)
        f.severity = severity;
    if (message.isEmpty())
        return;
    if (f.message.isEmpty())
        f.message = message;
    else
        f.message += QStringLiteral("; ") + message;
}

int FieldTree::firstChild(int parent) const
{
    return parent >= 0 ? m_links[size_t(parent)].firstChild : m_top.firstChild;
}

QList<int> FieldTree::children(int parent) const
{
    QList<int> out;
    for (int i = firstChild(parent); i >= 0; i = m_links[size_t(i)].nextSibling)
        out.append(i);
    return out;
}

int FieldTree::indexOf(const char *key, int from) const
{
    for (int i = from; i < size(); ++i) {
        if (std::strcmp(m_fields[size_t(i)].key, key) == 0)
            return i;
    }
    return -1;
}

QList<int> FieldTree::indexesOf(const char *key) const
{
    QList<int> out;
    for (int i = 0; i < size(); ++i) {
        if (std::strcmp(m_fields[size_t(i)].key, key) == 0)
            out.append(i);
    }
    return out;
}

Severity FieldTree::worstSeverity() const
{
    Severity worst = Severity::Ok;
    for (const Field &f : m_fields) {
        if (f.severity > worst)
            worst = f.severity;
    }
    return worst;
}

int FieldTree::count(Severity severity) const
{
    int n = 0;
    for (const Field &f : m_fields)
        n += f.severity == severity ? 1 : 0;
    return n;
}

QByteArray FieldTree::raw(int index) const
{
    const Field &f = at(index);
    if (f.offset < 0 || f.length <= 0 || f.offset >= m_frame.size())
        return {};
    return m_frame.mid(f.offset, qMin<qsizetype>(f.length, m_frame.size() - f.offset));
}

QString FieldTree::name(int index) const
{
    const Field &f = at(index);
    QString n = QString::fromLatin1(f.name);
    if (f.address >= 0)
        n += QLatin1Char(' ') + QString::number(f.address);
    return n;
}

// Hex as wide as the field: two digits per byte.
static QString hexOfWidth(quint64 value, int bytes)
{
    return hex(value, 2 * qBound(1, bytes, 8));
}

QString FieldTree::valueText(int index) const
{
    const Field &f = at(index);
    switch (f.format) {
    case ValueFormat::None:
        return {};
    case ValueFormat::Decimal:
    case ValueFormat::Bit:
        return QString::number(f.value);
    case ValueFormat::Hex:
        return hexOfWidth(f.value, f.length);
    case ValueFormat::Reference5: {
        // Show the six-digit form beside it: 40122 / 400122.
        const quint64 six = (f.value / 10000) * 100000 + f.value % 10000;
        return QString::number(f.value).rightJustified(5, QLatin1Char('0')) + QStringLiteral(" / ")
               + QString::number(six).rightJustified(6, QLatin1Char('0'));
    }
    case ValueFormat::Reference6:
        return QString::number(f.value).rightJustified(6, QLatin1Char('0'));
    case ValueFormat::DecimalHex:
        return QString::number(f.value) + QStringLiteral(" (") + hexOfWidth(f.value, f.length) + QLatin1Char(')');
    case ValueFormat::Bytes:
        return QString::fromLatin1(raw(index).toHex(' ').toUpper());
    case ValueFormat::Ascii: {
        QString text = QStringLiteral("\"");
        for (char c : raw(index)) {
            const auto u = static_cast<unsigned char>(c);
            if (u == '"' || u == '\\')
                text += QStringLiteral("\\") + QLatin1Char(c);
            else if (u >= 0x20 && u < 0x7f)
                text += QLatin1Char(c);
            else
                text += QStringLiteral("\\x") + hexDigits(u, 2);
        }
        return text + QLatin1Char('"');
    }
    }
    return {};
}

QString FieldTree::display(int index) const
{
    const Field &f = at(index);
    QString text = valueText(index);
    if (f.meaning && *f.meaning) {
        if (!text.isEmpty())
            text += QLatin1Char(' ');
        text += QString::fromUtf8(f.meaning);
    }
    return text;
}

} // namespace mbscope
