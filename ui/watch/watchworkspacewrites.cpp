// WatchWorkspace's writes: a value of a watch's table, typed by the user, written to the device
// through the running watches' link; the rest of the class is in watchworkspace.cpp.
#include "watchworkspace.h"

#include "watchtablemodel.h"
#include "watchvaluewrite.h"
#include "watchwindow.h"

#include "fleet/watchrunner.h"

#include <QtGui/QAction>
#include <QtWidgets/QInputDialog>
#include <QtWidgets/QTableView>

namespace mbscope {

void WatchWorkspace::writeCurrent()
{
    const int index = currentIndex();
    WatchWindow *w = window(index);
    if (!w || !w->view()->currentIndex().isValid()) {
        Q_EMIT message(tr("Choose a value in a watch's table to write"));
        return;
    }
    requestWrite(index, w->view()->currentIndex().row());
}

void WatchWorkspace::requestWrite(int index, int row)
{
    WatchWindow *w = window(index);
    if (!w)
        return;
    const QModelIndex value = w->model()->index(row, WatchTableModel::ValueColumn);
    if (!value.data(WatchTableModel::WritableRole).toBool()) {
        Q_EMIT message(tr("Not writable: only points marked writable of a coil or holding register watch are written "
                          "(Edit watch \u2192 Points \u2192 Writable)"));
        return;
    }
    const QString name = w->model()->index(row, WatchTableModel::NameColumn).data().toString();
    const QString current = w->model()->hasValue(row) ? value.data().toString() : QString();
    const QString title = tr("Write %1").arg(name);
    const QString label = tr("New value of %1 (%2):").arg(name, w->model()->index(row, WatchTableModel::AddressColumn).data().toString());
    std::optional<QString> text;
    if (m_textPrompt) {
        text = m_textPrompt(title, label, current);
    } else {
        bool ok = false;
        const QString typed = QInputDialog::getText(this, title, label, QLineEdit::Normal, current, &ok);
        if (ok)
            text = typed;
    }
    if (!text)
        return;
    QString error;
    if (!writeValue(index, row, *text, &error))
        Q_EMIT message(error);
}

bool WatchWorkspace::writeValue(int index, int row, const QString &text, QString *error)
{
    WatchWindow *w = window(index);
    if (!w || row < 0 || row >= w->model()->rowCount()) {
        *error = tr("No such value");
        return false;
    }
    const int point = w->model()->valueAt(row).point;
    const WatchWriteWords words = WatchValueWrite::words(m_watches.watches.at(index), point, text);
    if (!words.error.isEmpty()) {
        *error = words.error;
        return false;
    }
    if (!isRunning()) {
        *error = tr("Not written: start the watches first (Start all, %1)").arg(m_startAction->shortcut().toString(QKeySequence::NativeText));
        return false;
    }
    m_runner->write(index, m_watches.watches.at(index).points.at(point).address, words.words);
    Q_EMIT message(tr("Writing %1 to %2").arg(text.trimmed(), m_watches.watches.at(index).points.at(point).name));
    return true;
}

} // namespace mbscope
