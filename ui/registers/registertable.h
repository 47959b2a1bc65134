#pragma once

#include "exchange/transaction.h"
#include "protocol/framing.h"
#include "profile/deviceprofile.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtWidgets/QWidget>

class QComboBox;
class QLabel;
class QTableView;
class QToolBar;
class QAction;

namespace mbscope {

class RegisterTableModel;

// The register table panel: a RegisterTableModel in a table view, under a toolbar that sets the
// format and order of the current value column, adds and removes value columns, chooses the
// write function (06 / 10 / by width; 05 / 0F for coils) and shows the profile the names come
// from. Right-clicking a value column's header offers the same formats. A value wider than one
// register is drawn as one cell spanning its registers' rows. Edits become writeRequested; the
// window sends them. Refused answers and edits are shown in a message line above the table.
class RegisterTable : public QWidget
{
    Q_OBJECT

public:
    explicit RegisterTable(QWidget *parent = nullptr);

    [[nodiscard]] RegisterTableModel *model() const { return m_model; }
    [[nodiscard]] QTableView *view() const { return m_view; }

    // Shows a read's answer; false (and the reason in the message line) when it cannot.
    bool showTransaction(const Transaction &transaction, Framing framing);
    bool showAnswer(const QByteArray &requestPdu, const QByteArray &responsePdu);

    void setProfile(const UnitProfile &unit, const QString &profileName);
    // The value columns (formats and byte orders) as the user left them, in the application's
    // settings (registers/formats): stored when the window closes, put back at the next start.
    void storeFormats() const;
    void restoreFormats();
    void clearProfile();

    // The value column the toolbar's format and order act on (0-based among value columns).
    [[nodiscard]] int currentValueIndex() const { return m_currentValue; }
    void setCurrentValueIndex(int valueIndex);
    // The message line's text: the latest refused answer or edit, empty when all went well.
    [[nodiscard]] QString message() const;

Q_SIGNALS:
    void writeRequested(const QByteArray &pdu, const QString &description);

private:
    void buildToolBar();
    void refreshToolBar();
    void refreshWriteChoices();
    void applySpans();
    void applyTypeAndOrder();
    void showMessage(const QString &text);
    void showHeaderMenu(const QPoint &position);

    RegisterTableModel *m_model = nullptr;
    QTableView *m_view = nullptr;
    QToolBar *m_toolBar = nullptr;
    QComboBox *m_typeBox = nullptr;
    QComboBox *m_orderBox = nullptr;
    QComboBox *m_writeBox = nullptr;
    QAction *m_addColumn = nullptr;
    QAction *m_removeColumn = nullptr;
    QLabel *m_columnLabel = nullptr;
    QLabel *m_profileLabel = nullptr;
    QLabel *m_message = nullptr;
    int m_currentValue = 0;
    bool m_refreshing = false;
    bool m_showingProblem = false; // the message line shows a refused answer or edit
};

} // namespace mbscope
