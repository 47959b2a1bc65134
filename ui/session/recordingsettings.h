#pragma once

#include "traffic/capturedirectory.h"
#include "traffic/rollingcapture.h"

#include <QtCore/QString>

namespace mbscope {

// The window's recording choices, kept in QSettings (recording/...): on by default, into
// "captures" in the user's data folder (QStandardPaths::AppDataLocation), journals in parts of
// 64 MiB and the folder kept under 2 GiB, so that a week-long poll cannot fill the disk.
struct RecordingSettings {
    bool enabled = true;
    QString folder;         // empty: defaultFolder()
    int rotateMiB = 64;     // 1 .. 4096
    int keepMiB = 2048;     // 16 .. 1,048,576

    [[nodiscard]] static RecordingSettings load();
    void store() const;
    [[nodiscard]] static QString defaultFolder();
    [[nodiscard]] QString effectiveFolder() const { return folder.isEmpty() ? defaultFolder() : folder; }
    [[nodiscard]] CaptureDirectory directory() const { return CaptureDirectory(effectiveFolder()); }
    [[nodiscard]] RollingCapture::Policy policy() const;

    friend bool operator==(const RecordingSettings &, const RecordingSettings &) = default;
};

} // namespace mbscope
