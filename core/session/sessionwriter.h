#pragma once

#include "session/sessiondocument.h"

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope {

// Writes session documents as SessionReader reads them (docs/session.schema.json): what was
// read is written back the same, and options at their defaults are left out.
class SessionWriter
{
public:
    [[nodiscard]] static QJsonObject toJson(const SessionDocument &document);
    [[nodiscard]] static QByteArray toBytes(const SessionDocument &document); // indented JSON
    // Writes atomically (QSaveFile: a temporary file beside path, written, flushed and renamed
    // over path), so that a crash or a full disk while saving leaves the previous file intact.
    // False with *error saying which file and what the OS said. When the file it replaces is a
    // session of an older version, *notice says that it was upgraded (and that older mbscope
    // versions no longer open it); else it is left empty.
    static bool save(const SessionDocument &document, const QString &path, QString *error = nullptr,
                     QString *notice = nullptr);
    // "upgraded from session version 1 to 2 ..." for a document read as version; empty when it
    // is the current version already.
    [[nodiscard]] static QString upgradeNotice(int version, int written);
};

} // namespace mbscope
