#pragma once

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// A request kept under a name: the hex text exactly as the user typed it.
struct SavedRequest {
    QString name;
    QString hex;

    friend bool operator==(const SavedRequest &, const SavedRequest &) = default;
};

// The composer's list of named requests, kept in QSettings ("composer/savedRequests"). A first
// run starts with the requests people type most, the RosRao detector's read among them.
class SavedRequests
{
public:
    [[nodiscard]] static QList<SavedRequest> defaults();
    // What QSettings holds, or defaults() when nothing was ever saved.
    [[nodiscard]] static QList<SavedRequest> load();
    static void store(const QList<SavedRequest> &requests);
    // The RosRao detector's register read: unit 1, 22 holding registers from 0x0079, RTU.
    [[nodiscard]] static SavedRequest rosRaoRead();
};

} // namespace mbscope
