#pragma once
// The frames lab papers published (tests/data/published-frames.json, sources in
// tests/data/README.md) as rows of a data-driven GUI test: bytes, framing and direction.

#include "protocol/framing.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtTest/QTest>

namespace mbscope::guitest {

// Adds the columns "frame" (QByteArray), "framing" (int: Framing) and "direction" (int: Direction)
// and one row per published frame, named by its id. Returns the number of rows.
inline int addPublishedFrameRows()
{
    QTest::addColumn<QByteArray>("frame");
    QTest::addColumn<int>("framing");
    QTest::addColumn<int>("direction");
    QFile file(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/published-frames.json"));
    if (!file.open(QIODevice::ReadOnly))
        return 0;
    const QJsonArray frames = QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("frames")).toArray();
    int rows = 0;
    for (const QJsonValue &v : frames) {
        const QJsonObject o = v.toObject();
        const QByteArray bytes = o.contains(QStringLiteral("ascii"))
                                     ? o.value(QStringLiteral("ascii")).toString().toLatin1()
                                     : QByteArray::fromHex(o.value(QStringLiteral("hex")).toString().toLatin1());
        const std::optional<Framing> framing = framingFromName(o.value(QStringLiteral("framing")).toString());
        const std::optional<Direction> direction = directionFromName(o.value(QStringLiteral("direction")).toString());
        QTest::newRow(qPrintable(o.value(QStringLiteral("id")).toString()))
            << bytes << int(framing.value_or(Framing::Auto)) << int(direction.value_or(Direction::Auto));
        ++rows;
    }
    return rows;
}

} // namespace mbscope::guitest
