#include "scanform.h"

#include <QtWidgets/QSpinBox>

namespace mbscope {

QSpinBox *ScanForm::spinBox(QWidget *parent, const char *objectName, int low, int high, int value, const QString &suffix)
{
    auto *box = new QSpinBox(parent);
    box->setObjectName(QLatin1String(objectName));
    box->setRange(low, high);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

QString ScanForm::duration(qint64 ms)
{
    return ms < 60000 ? tr("%1 s").arg(QString::number(double(ms) / 1000.0, 'f', 1))
                      : tr("%1 min %2 s").arg(ms / 60000).arg((ms / 1000) % 60);
}

} // namespace mbscope
