#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>
#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

// What a traffic journal was recording, written as its first record (trafficjournal.h, record
// kind 3) so that a journal alone is enough to analyze, export and replay: which command on
// which host, against which target (or serving which endpoints), with which profile, and the
// requests it was told to send. Read back by TrafficJournalRecovery::metadata.
//
// The JSON object (keys in snake case; absent when empty):
//   {"format": "mbscope-journal-metadata", "format_version": 1,
//    "mbscope": "0.9.0", "host": "bench-3", "started": "2024-05-01T10:00:00.123Z",
//    "command": "poll", "arguments": ["--target", "tcp://...", ...],
//    "role": "client" | "server",
//    "target": "tcp://127.0.0.1:1502",                 (client: where requests went)
//    "listen": ["rtu-tcp://127.0.0.1:4001"],           (server: where it answered)
//    "profile": {"name": "rosrao-gamma", "source": "shipped"},
//    "requests": [{"name": ..., "description": ..., "hex": "00 01 00 00 00 06 01 03 00 00 00 0A"}],
//    "settings": {...}}                                 (the command's own: interval, count, seed...)
struct TrafficMetadataRequest {
    QString name;
    QString description;
    QByteArray bytes; // as sent on the target's framing

    friend bool operator==(const TrafficMetadataRequest &, const TrafficMetadataRequest &) = default;
};

struct TrafficMetadata {
    enum class Role : quint8 { Client, Server };

    QString mbscopeVersion;
    QString host;
    QDateTime started; // UTC
    QString command;   // "poll"
    QStringList arguments;
    Role role = Role::Client;
    QString target;
    QStringList listen;
    QString profileName;
    QString profileSource; // "shipped", a file path, "session"
    QList<TrafficMetadataRequest> requests;
    QJsonObject settings;

    [[nodiscard]] QJsonObject toJson() const;
    [[nodiscard]] QByteArray toUtf8() const; // compact JSON
    // Every key is optional; a wrong type is an error that names the key.
    [[nodiscard]] static bool fromJson(QByteArrayView utf8, TrafficMetadata *out, QString *error);
    // The lines analyze prints: "recorded      poll by mbscope 0.9.0 on bench-3, 2024-05-01 10:00:00 UTC" ...
    [[nodiscard]] QStringList summaryLines() const;
    // The host name, the start time now and this process's command, from the command line.
    [[nodiscard]] static TrafficMetadata forCommand(const QString &command, const QStringList &arguments,
                                                    const QString &mbscopeVersion);

    friend bool operator==(const TrafficMetadata &, const TrafficMetadata &) = default;
};

} // namespace mbscope
