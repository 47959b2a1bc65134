#pragma once

#include "protocol/dissection.h"
#include "protocol/hextext.h"

#include <QtCore/QTimer>
#include <QtWidgets/QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace mbscope {

class FieldTreeModel;
class FieldTreeView;

// Type a frame as hex, see every field. The frame is re-dissected while the user types (after a
// short pause, so a long paste is read once). Text that is not hex never clears what is shown:
// the error names the line and column, the editor marks the character, and the tree keeps the
// last frame that could be read, so a half-typed byte does not make the tree flicker away.
class DecodePanel : public QWidget
{
    Q_OBJECT

public:
    // Pause after the last keystroke before dissecting: long enough to skip the frames a user
    // is still typing, short enough to feel immediate.
    static constexpr int kDebounceMs = 150;

    explicit DecodePanel(QWidget *parent = nullptr);

    void setFrameText(const QString &text);
    [[nodiscard]] QString frameText() const;
    void setRequestText(const QString &text);
    [[nodiscard]] QString requestText() const;
    void setFraming(Framing framing);
    [[nodiscard]] Framing framing() const;
    void setDirection(Direction direction);
    [[nodiscard]] Direction direction() const;

    // The dissection shown in the tree: the last input that could be read.
    [[nodiscard]] const Dissection &dissection() const;
    // True while the frame or request text is not hex; inputError() says where and why.
    [[nodiscard]] bool hasInputError() const { return !m_inputError.isEmpty(); }
    [[nodiscard]] QString inputError() const { return m_inputError; }
    [[nodiscard]] FieldTreeModel *model() const { return m_model; }
    [[nodiscard]] FieldTreeView *treeView() const { return m_tree; }

public Q_SLOTS:
    // Dissects now instead of waiting for the pause (a combo change, a programmatic fill).
    void decodeNow();

Q_SIGNALS:
    // The input was read again: either the tree shows a new dissection or an input error is shown.
    void decoded();

private:
    void buildUi();
    void showDissection(const Dissection &dissection);
    void showEmpty();
    void showInputError(const QString &what, const HexTextError &error, bool inFrame);
    void setVerdict(const QString &text, Severity severity);

    QPlainTextEdit *m_frameEdit = nullptr;
    QComboBox *m_framingCombo = nullptr;
    QComboBox *m_directionCombo = nullptr;
    QLineEdit *m_requestEdit = nullptr;
    QLabel *m_verdictLabel = nullptr;
    QLabel *m_summaryLabel = nullptr;
    QLabel *m_errorLabel = nullptr;
    QLabel *m_reasonLabel = nullptr;
    FieldTreeView *m_tree = nullptr;
    FieldTreeModel *m_model = nullptr;
    QTimer m_debounce;
    QString m_inputError;
};

} // namespace mbscope
