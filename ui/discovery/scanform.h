#pragma once

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

class QSpinBox;
class QWidget;

namespace mbscope {

// What the scan dialogs share: their number fields and how they say a duration.
class ScanForm
{
    Q_DECLARE_TR_FUNCTIONS(ScanForm)
public:
    [[nodiscard]] static QSpinBox *spinBox(QWidget *parent, const char *objectName, int low, int high, int value,
                                           const QString &suffix = {});
    // "4.2 s" under a minute, "3 min 20 s" from one.
    [[nodiscard]] static QString duration(qint64 ms);
};

} // namespace mbscope
