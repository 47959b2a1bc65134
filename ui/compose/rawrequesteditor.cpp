#include "rawrequesteditor.h"
#include "protocol/framingtraits.h"

#include "common/coretext.h"

#include "common/hexerrormark.h"
#include "common/severitystyle.h"

#include "protocol/adubuilder.h"
#include "protocol/functioncode.h"
#include "protocol/pdusize.h"

#include <QtCore/QEvent>
#include <QtGui/QFontDatabase>
#include <QtGui/QTextBlock>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QInputDialog>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMenu>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

QString hex2(int value)
{
    return QStringLiteral("%1").arg(value, 2, 16, QLatin1Char('0')).toUpper();
}

QString spaced(QByteArrayView bytes)
{
    return HexText::format(bytes);
}

// What the framing calls its completion, for the button and the note.
QString completionName(Framing framing)
{
    switch (framing) {
    case Framing::Tcp:
    case Framing::Udp: return RawRequestEditor::tr("Add MBAP header");
    case Framing::Rtu: return RawRequestEditor::tr("Add unit and CRC");
    case Framing::Ascii: return RawRequestEditor::tr("Add unit and LRC");
    default: return RawRequestEditor::tr("Complete");
    }
}

// RTU bytes that are exactly a unit id and a whole request PDU: what people type before the CRC
// (a frame of that length with a correct CRC would be a shorter request, which the CRC check
// tells apart).
bool isPduWithoutCrc(const QByteArray &bytes)
{
    if (bytes.size() < 2)
        return false;
    const pdusize::Expected expected = pdusize::expectedPduSize(QByteArrayView(bytes).sliced(1), Direction::Request);
    return expected.status == pdusize::Status::Complete && expected.size == bytes.size() - 1;
}

} // namespace

RawRequestEditor::RawRequestEditor(QWidget *parent)
    : QWidget(parent)
{
    buildUi();
    reloadSavedCombo();
    onTextChanged();
}

void RawRequestEditor::buildUi()
{
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_savedCombo = new QComboBox(this);
    // Long names do not widen the composer (the window fits 1024 px); the list opens wide enough.
    m_savedCombo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_savedCombo->setMinimumContentsLength(10); // the window fits 1024 px in Indonesian too
    m_savedCombo->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed); // wider when there is room
    m_savedCombo->setObjectName(QStringLiteral("savedRequestsCombo"));
    m_savedCombo->setToolTip(tr("Named requests: choose one to put its bytes in the editor"));
    auto *save = new QToolButton(this);
    save->setObjectName(QStringLiteral("saveRequestButton"));
    save->setText(tr("Save as\u2026"));
    save->setToolTip(tr("Keep the bytes in the editor under a name"));
    auto *remove = new QToolButton(this);
    remove->setObjectName(QStringLiteral("deleteRequestButton"));
    remove->setText(tr("Delete"));
    remove->setToolTip(tr("Forget the chosen named request"));
    connect(save, &QToolButton::clicked, this, &RawRequestEditor::saveCurrent);
    connect(remove, &QToolButton::clicked, this, &RawRequestEditor::deleteCurrent);
    connect(m_savedCombo, &QComboBox::activated, this, [this](int index) {
        if (index > 0)
            loadSaved(m_savedCombo->itemText(index));
    });

    m_edit = new QPlainTextEdit(this);
    m_edit->setObjectName(QStringLiteral("rawEdit"));
    m_edit->setFont(mono);
    m_edit->setTabChangesFocus(true);
    m_edit->setPlaceholderText(tr("The bytes to send, as hex: 01 03 00 79 00 16 15 DD"));
    const QFontMetrics fm(mono);
    // A 256-byte ADU as spaced hex is about 6 lines at the composer's width: room for that, and
    // the rest of the height goes to the Form and the poll settings, not to empty editor space.
    const int margins = 2 * m_edit->frameWidth() + int(2 * m_edit->document()->documentMargin());
    m_edit->setMinimumHeight(fm.lineSpacing() * 3 + margins);
    m_edit->setMaximumHeight(fm.lineSpacing() * 8 + margins);

    m_completeButton = new QToolButton(this);
    m_completeButton->setObjectName(QStringLiteral("completeButton"));
    m_completeButton->setPopupMode(QToolButton::MenuButtonPopup);
    m_completeButton->setMenu(new QMenu(m_completeButton));
    m_completeButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
    connect(m_completeButton, &QToolButton::clicked, this, &RawRequestEditor::completePdu);

    m_countLabel = new QLabel(this);
    m_countLabel->setObjectName(QStringLiteral("byteCountLabel"));
    m_infoLabel = new QLabel(this);
    m_infoLabel->setObjectName(QStringLiteral("rawInfoLabel"));
    m_infoLabel->setWordWrap(true);
    m_infoLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_noteLabel = new QLabel(this);
    m_noteLabel->setObjectName(QStringLiteral("completionNoteLabel"));
    m_noteLabel->setWordWrap(true);
    m_noteLabel->setForegroundRole(QPalette::PlaceholderText);
    m_noteLabel->hide();

    auto *savedRow = new QHBoxLayout;
    auto *savedLabel = new QLabel(tr("Sav&ed:"), this);
    savedLabel->setBuddy(m_savedCombo);
    savedRow->addWidget(savedLabel);
    savedRow->addWidget(m_savedCombo, 1);
    savedRow->addWidget(save);
    savedRow->addWidget(remove);

    auto *countRow = new QHBoxLayout;
    countRow->addWidget(m_countLabel);
    countRow->addStretch(1);
    countRow->addWidget(m_completeButton);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(savedRow);
    layout->addWidget(m_edit);
    layout->addLayout(countRow);
    layout->addWidget(m_infoLabel);
    layout->addWidget(m_noteLabel);
    layout->addStretch(1);

    connect(m_edit, &QPlainTextEdit::textChanged, this, &RawRequestEditor::onTextChanged);
    updateCompleteMenu();
}

void RawRequestEditor::setText(const QString &text)
{
    m_edit->setPlainText(text);
}

QString RawRequestEditor::text() const
{
    return m_edit->toPlainText();
}

void RawRequestEditor::setFraming(Framing framing)
{
    m_framing = framing;
    updateCompleteMenu();
    updateInfo();
}

void RawRequestEditor::setUnitId(int unit)
{
    m_unit = quint8(qBound(0, unit, 255));
}

void RawRequestEditor::onTextChanged()
{
    if (!m_replacing) {
        m_added.clear();
        m_noteLabel->hide();
    }
    const QString text = m_edit->toPlainText();
    m_error = {};
    m_bytes.clear();
    if (!text.trimmed().isEmpty()) {
        const HexTextResult parsed = HexText::parse(text);
        if (parsed.ok)
            m_bytes = parsed.bytes;
        else
            m_error = parsed.error;
    }
    markError();
    if (m_error.message.isEmpty())
        markAdded();
    updateInfo();
    Q_EMIT bytesChanged(m_bytes, isValid());
}

void RawRequestEditor::markError()
{
    hexerrormark::mark(m_edit, m_error);
}

// Completion writes spaced hex (three characters a byte), so byte i starts at column 3 * i.
void RawRequestEditor::markAdded()
{
    QList<QTextEdit::ExtraSelection> marks;
    for (const auto &[first, count] : std::as_const(m_added)) {
        QTextCursor cursor(m_edit->document());
        cursor.setPosition(first * 3);
        cursor.setPosition(qMin(m_edit->document()->characterCount() - 1, (first + count) * 3 - 1), QTextCursor::KeepAnchor);
        QTextEdit::ExtraSelection mark;
        mark.cursor = cursor;
        mark.format.setBackground(SeverityStyle::backgroundColor(Severity::Info));
        mark.format.setFontUnderline(true);
        marks.append(mark);
    }
    m_edit->setExtraSelections(marks);
}

QString RawRequestEditor::infoText() const
{
    return m_countLabel->text() + QStringLiteral(" \u00B7 ") + m_infoLabel->text();
}

void RawRequestEditor::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    // Another theme: the line's colour is taken again from the new palette.
    if ((event->type() == QEvent::ApplicationPaletteChange || event->type() == QEvent::PaletteChange) && m_infoLabel
        && m_countLabel)
        updateInfo();
}

void RawRequestEditor::updateInfo()
{
    if (!m_error.message.isEmpty()) {
        m_countLabel->setText(tr("not hex"));
        m_infoLabel->setText(m_error.message);
        SeverityStyle::setTextColour(m_infoLabel, Severity::Error);
        return;
    }
    m_countLabel->setText(m_bytes.size() == 1 ? tr("1 byte") : tr("%1 bytes").arg(m_bytes.size()));
    SeverityStyle::setTextColour(m_infoLabel, Severity::Ok);
    if (m_bytes.isEmpty()) {
        m_infoLabel->setText(tr("Type the request as hex, choose a saved one, or build it in the Form tab."));
        return;
    }
    const AduParts parts = AduBuilder::parse(m_bytes, m_framing);
    const quint8 function = parts.pdu.isEmpty() ? 0 : quint8(parts.pdu.at(0));
    const QString what = parts.pdu.isEmpty() ? QString()
                                             : tr("function %1 %2").arg(hex2(function), fieldText(functionName(function)));
    QString text;
    switch (m_framing) {
    case Framing::Rtu:
    case Framing::Ascii: {
        const QString sum = m_framing == Framing::Rtu ? tr("CRC") : tr("LRC");
        if (!parts.complete) {
            text = tr("Not a whole %1 frame (%2). Send it as it is, or use \u201C%3\u201D if it is a PDU.")
                       .arg(framingName(m_framing).toUpper(), parts.error, completionName(m_framing));
        } else if (m_framing == Framing::Rtu && !parts.checksumValid() && isPduWithoutCrc(m_bytes)) {
            text = tr("Unit %1 and a whole %2 request, but no CRC: use \u201C" "Append CRC only\u201D in the %3 menu, "
                      "or send it as it is.")
                       .arg(quint8(m_bytes.at(0)))
                       .arg(fieldText(functionName(quint8(m_bytes.at(1)))), completionName(m_framing));
        } else if (parts.checksumValid()) {
            text = tr("%1 frame: unit %2, %3, %4 correct.").arg(framingName(m_framing).toUpper()).arg(parts.unitId).arg(what, sum);
        } else {
            text = tr("%1 frame: unit %2, %3, %4 %5 is wrong (expected %6); it is sent as typed.")
                       .arg(framingName(m_framing).toUpper())
                       .arg(parts.unitId)
                       .arg(what, sum, hex2(parts.checksum & 0xFF) + QLatin1Char(' ') + hex2(parts.checksum >> 8),
                            hex2(parts.expectedChecksum & 0xFF) + QLatin1Char(' ') + hex2(parts.expectedChecksum >> 8));
            SeverityStyle::setTextColour(m_infoLabel, Severity::Warning);
        }
        break;
    }
    case Framing::Tcp:
    case Framing::Udp:
        if (!parts.complete)
            text = tr("Not a whole MBAP frame (%1). Send it as it is, or use \u201C%2\u201D if it is a PDU.")
                       .arg(parts.error, completionName(m_framing));
        else
            text = tr("MBAP frame: transaction %1, unit %2, %3, length %4%5.")
                       .arg(parts.transactionId)
                       .arg(parts.unitId)
                       .arg(what)
                       .arg(parts.length)
                       .arg(parts.lengthMatches ? tr(" (fits)") : tr(" (does not fit the bytes: sent as typed)"));
        break;
    default: text = what; break;
    }
    m_infoLabel->setText(text);
}

void RawRequestEditor::updateCompleteMenu()
{
    m_completeButton->setText(completionName(m_framing));
    m_completeButton->setToolTip(tr("Take the bytes as a PDU (function code first) and wrap them for this link, "
                                    "with the unit id of the connection bar; the added bytes are marked"));
    QMenu *menu = m_completeButton->menu();
    menu->clear();
    menu->addAction(tr("%1 (the bytes are a PDU)").arg(completionName(m_framing)), this, &RawRequestEditor::completePdu);
    if (isSerialLine(m_framing))
        menu->addAction(m_framing == Framing::Rtu ? tr("Append CRC only (the bytes are unit + PDU)")
                                                  : tr("Add LRC and delimiters only (the bytes are unit + PDU)"),
                        this, &RawRequestEditor::addChecksum);
}

bool RawRequestEditor::completePdu()
{
    if (!isValid())
        return false;
    AduOptions options;
    options.framing = m_framing;
    options.unitId = m_unit;
    options.transactionId = 1;
    const QByteArray adu = AduBuilder::complete(m_bytes, options);
    QList<QPair<int, int>> added;
    QString note;
    switch (m_framing) {
    case Framing::Tcp:
    case Framing::Udp:
        added = {{0, 7}};
        note = tr("Added the MBAP header (transaction 1, protocol 0, length %1, unit %2) in front of the PDU.")
                   .arg(m_bytes.size() + 1)
                   .arg(m_unit);
        break;
    case Framing::Rtu:
        added = {{0, 1}, {int(adu.size()) - 2, 2}};
        note = tr("Added unit %1 in front and the CRC %2 at the end.").arg(m_unit).arg(spaced(adu.right(2)));
        break;
    case Framing::Ascii:
        added = {{0, 3}, {int(adu.size()) - 4, 4}};
        note = tr("Added ':' and unit %1 in front, and the LRC and CR LF at the end (as ASCII characters).").arg(m_unit);
        break;
    default: return false;
    }
    replaceBytes(adu, added, note);
    return true;
}

bool RawRequestEditor::addChecksum()
{
    if (!isValid() || m_bytes.size() < 2 || (m_framing != Framing::Rtu && m_framing != Framing::Ascii))
        return false;
    const quint8 unit = quint8(m_bytes.at(0));
    const QByteArray pdu = m_bytes.mid(1);
    if (m_framing == Framing::Rtu) {
        const QByteArray adu = AduBuilder::rtu(pdu, unit);
        replaceBytes(adu, {{int(adu.size()) - 2, 2}}, tr("Appended the CRC %1.").arg(spaced(adu.right(2))));
    } else {
        const QByteArray adu = AduBuilder::ascii(pdu, unit);
        replaceBytes(adu, {{0, 1}, {int(adu.size()) - 4, 4}},
                     tr("Added ':' in front, and the LRC and CR LF at the end (as ASCII characters)."));
    }
    return true;
}

void RawRequestEditor::replaceBytes(const QByteArray &bytes, const QList<QPair<int, int>> &added, const QString &note)
{
    m_replacing = true;
    m_added = added;
    m_edit->setPlainText(spaced(bytes));
    m_replacing = false;
    m_noteLabel->setText(note);
    m_noteLabel->show();
}

bool RawRequestEditor::loadSaved(const QString &name)
{
    for (const SavedRequest &request : std::as_const(m_saved)) {
        if (request.name == name) {
            setText(request.hex);
            m_savedCombo->setCurrentIndex(m_savedCombo->findText(name));
            return true;
        }
    }
    return false;
}

void RawRequestEditor::reloadSavedCombo()
{
    m_saved = SavedRequests::load();
    m_savedCombo->clear();
    m_savedCombo->addItem(tr("(choose a named request)"));
    for (const SavedRequest &request : std::as_const(m_saved)) {
        m_savedCombo->addItem(request.name);
        m_savedCombo->setItemData(m_savedCombo->count() - 1, request.hex, Qt::ToolTipRole);
    }
}

void RawRequestEditor::saveCurrent()
{
    if (!isValid())
        return;
    const QString current = m_savedCombo->currentIndex() > 0 ? m_savedCombo->currentText() : QString();
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Save request"), tr("Name of the request:"),
                                               QLineEdit::Normal, current, &ok).trimmed();
    if (!ok || name.isEmpty())
        return;
    QList<SavedRequest> list = m_saved;
    list.removeIf([&name](const SavedRequest &r) { return r.name == name; });
    list.append({name, spaced(m_bytes)});
    SavedRequests::store(list);
    reloadSavedCombo();
    m_savedCombo->setCurrentIndex(m_savedCombo->findText(name));
}

void RawRequestEditor::deleteCurrent()
{
    if (m_savedCombo->currentIndex() <= 0)
        return;
    const QString name = m_savedCombo->currentText();
    QList<SavedRequest> list = m_saved;
    list.removeIf([&name](const SavedRequest &r) { return r.name == name; });
    SavedRequests::store(list);
    reloadSavedCombo();
}

} // namespace mbscope
