#pragma once

#include "fieldtree.h"
#include "framing.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// Why the dissector chose a framing or a direction it was asked to detect. The text is written
// when it is read: the direction's reason quotes the first problem of the frame read both ways,
// which took several times as long as the dissection itself, and most frames' reasons are never
// read (issue 32). The writer is a pure function of the frame, so the text is the same whenever
// it is read. Reads like the QString it used to be.
class DetectionReason
{
public:
    using Writer = QString (*)(const QByteArray &frame, int a, int b);

    DetectionReason() = default;
    DetectionReason(const QString &text) : m_text(text) {} // implicit, like the QString it was
    [[nodiscard]] static DetectionReason deferred(Writer writer, const QByteArray &frame, int a, int b = 0)
    {
        DetectionReason r;
        r.m_writer = writer;
        r.m_frame = frame;
        r.m_a = a;
        r.m_b = b;
        return r;
    }

    [[nodiscard]] QString toString() const { return m_writer ? m_writer(m_frame, m_a, m_b) : m_text; }
    operator QString() const { return toString(); }
    // A writer never writes an empty text.
    [[nodiscard]] bool isEmpty() const { return !m_writer && m_text.isEmpty(); }
    [[nodiscard]] bool contains(QStringView text) const { return toString().contains(text); }
    void clear()
    {
        m_text.clear();
        m_frame.clear();
        m_writer = nullptr;
    }

private:
    QString m_text;
    QByteArray m_frame;
    Writer m_writer = nullptr;
    int m_a = 0;
    int m_b = 0;
};

// The result of dissecting one frame: how it was read and the fields found.
struct Dissection {
    Framing framing = Framing::Auto;       // the framing used (detected when asked for Auto)
    Direction direction = Direction::Auto; // the direction used (detected when asked for Auto)
    DetectionReason framingReason;   // why this framing was chosen, when it was detected
    DetectionReason directionReason; // why this direction was chosen, when it was detected
    QString note;            // how to read the offsets when it is not obvious (ASCII frames)
    FieldTree fields;

    [[nodiscard]] bool isValid() const { return !fields.isEmpty() && fields.worstSeverity() < Severity::Error; }
    // One line: "RTU request, unit 1: Read Holding Registers, 22 registers from 121 (0x0079)".
    [[nodiscard]] QString summary() const;
};

} // namespace mbscope
