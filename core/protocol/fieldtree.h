#pragma once

#include "field.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QList>
#include <QtCore/QString>

#include <vector>

namespace mbscope {

// The fields of one dissected frame, flat, in depth-first order (a parent always comes before
// its children). Reusing a tree (reset) keeps its capacity, so a dissector that runs on the
// receive path allocates nothing per frame once warmed up.
class FieldTree
{
public:
    FieldTree() = default;

    void reset(const QByteArray &frame);

    // Appends a field and returns its index. offset and length are in frame bytes.
    int add(int parent, const char *key, const char *name, int offset, int length,
            quint64 value = 0, ValueFormat format = ValueFormat::None, const char *meaning = nullptr);
    // Records a problem on a field; the worst severity wins, messages are joined with "; ".
    void flag(int index, Severity severity, const QString &message);
    void setAddress(int index, int address) { m_fields[size_t(index)].address = address; }
    void setMeaning(int index, const char *meaning) { m_fields[size_t(index)].meaning = meaning; }
    void setSpan(int index, int offset, int length)
    {
        m_fields[size_t(index)].offset = offset;
        m_fields[size_t(index)].length = length;
    }
    void setValue(int index, quint64 value) { m_fields[size_t(index)].value = value; }

    [[nodiscard]] const QByteArray &frame() const { return m_frame; }
    [[nodiscard]] int size() const { return int(m_fields.size()); }
    [[nodiscard]] bool isEmpty() const { return m_fields.empty(); }
    [[nodiscard]] const Field &at(int index) const { return m_fields[size_t(index)]; }
    [[nodiscard]] const std::vector<Field> &fields() const { return m_fields; }

    // parent -1: the top-level fields. O(number of children): each field links to its next
    // sibling as it is added (a scan of the whole tree per call made the JSON and table output
    // quadratic, the dissector's fuzz target 30 times slower than the others: issue 19).
    [[nodiscard]] QList<int> children(int parent) const;
    [[nodiscard]] int firstChild(int parent) const; // -1 when none
    [[nodiscard]] int nextSibling(int index) const { return m_links[size_t(index)].nextSibling; }
    [[nodiscard]] int indexOf(const char *key, int from = 0) const; // first field with key, or -1
    [[nodiscard]] QList<int> indexesOf(const char *key) const;
    [[nodiscard]] Severity worstSeverity() const;
    [[nodiscard]] int count(Severity severity) const;

    // Presentation, computed on demand.
    [[nodiscard]] QByteArray raw(int index) const;
    [[nodiscard]] QString name(int index) const;    // name plus address where there is one
    [[nodiscard]] QString valueText(int index) const; // the value alone, in the field's format
    [[nodiscard]] QString display(int index) const; // value and meaning: "0x03 Read Holding Registers"

private:
    struct Links {
        int firstChild = -1;
        int lastChild = -1;
        int nextSibling = -1;
    };
    QByteArray m_frame;
    std::vector<Field> m_fields;
    std::vector<Links> m_links; // one per field, in step with m_fields
    Links m_top;                // the top-level fields' chain
};

} // namespace mbscope
