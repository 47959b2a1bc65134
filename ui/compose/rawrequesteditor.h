#pragma once

#include "protocol/framing.h"
#include "protocol/hextext.h"
#include "savedrequests.h"

#include <QtCore/QByteArray>
#include <QtWidgets/QWidget>

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QToolButton;

namespace mbscope {

// The composer's Raw tab: the exact bytes to send, typed as hex and checked as they are typed.
// A character that is not hex is marked where it is, with the reason; the byte count and what the
// bytes are on the current link's framing (a whole RTU frame with a correct or wrong CRC, an
// MBAP header whose length fits or not) are shown below. Nothing is ever added silently: the
// Complete menu wraps a PDU for the link (unit and CRC/LRC, or the MBAP header) and marks the
// bytes it added, and a frame with a wrong CRC stays sendable as typed.
class RawRequestEditor : public QWidget
{
    Q_OBJECT
public:
    explicit RawRequestEditor(QWidget *parent = nullptr);

    void setText(const QString &text);
    [[nodiscard]] QString text() const;
    // The bytes typed; empty while the text is not hex (errorText() says where).
    [[nodiscard]] QByteArray bytes() const { return m_bytes; }
    [[nodiscard]] bool isValid() const { return m_error.message.isEmpty() && !m_bytes.isEmpty(); }
    [[nodiscard]] QString errorText() const { return m_error.message; }
    [[nodiscard]] HexTextError error() const { return m_error; }
    // "8 bytes · RTU: unit 1, function 03 ..." as shown under the editor.
    [[nodiscard]] QString infoText() const;

    void setFraming(Framing framing);
    [[nodiscard]] Framing framing() const { return m_framing; }
    void setUnitId(int unit);

    // The text taken as a PDU (function code first), wrapped for the framing with the unit id.
    bool completePdu();
    // Serial framings: the text taken as unit + PDU, the CRC (RTU) or LRC and delimiters (ASCII) added.
    bool addChecksum();
    // Bytes added by the last completion, as (first byte, count) ranges; empty after an edit.
    [[nodiscard]] QList<QPair<int, int>> addedRanges() const { return m_added; }

    [[nodiscard]] QPlainTextEdit *editor() const { return m_edit; }
    [[nodiscard]] QComboBox *savedCombo() const { return m_savedCombo; }
    // Fills the editor with the saved request of that name; false when there is none.
    bool loadSaved(const QString &name);
    [[nodiscard]] QList<SavedRequest> savedRequests() const { return m_saved; }
    // Re-reads the named requests from QSettings (an opened session added some).
    void reloadSavedRequests() { reloadSavedCombo(); }

Q_SIGNALS:
    // After every edit: the bytes when the text is hex (valid), else empty bytes and false.
    void bytesChanged(const QByteArray &bytes, bool valid);

protected:
    void changeEvent(QEvent *event) override;

private:
    void buildUi();
    void onTextChanged();
    void markError();
    void markAdded();
    void updateInfo();
    void updateCompleteMenu();
    void replaceBytes(const QByteArray &bytes, const QList<QPair<int, int>> &added, const QString &note);
    void saveCurrent();
    void deleteCurrent();
    void reloadSavedCombo();

    QPlainTextEdit *m_edit = nullptr;
    QLabel *m_countLabel = nullptr;
    QLabel *m_infoLabel = nullptr;
    QLabel *m_noteLabel = nullptr;
    QToolButton *m_completeButton = nullptr;
    QComboBox *m_savedCombo = nullptr;
    QByteArray m_bytes;
    HexTextError m_error;
    Framing m_framing = Framing::Rtu;
    quint8 m_unit = 1;
    QList<QPair<int, int>> m_added;
    QList<SavedRequest> m_saved;
    bool m_replacing = false;
};

} // namespace mbscope
