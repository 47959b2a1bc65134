#include "decodepanel.h"

#include "dissectionsummary.h"
#include "fieldtreemodel.h"
#include "fieldtreeview.h"
#include "common/hexerrormark.h"
#include "common/severitystyle.h"

#include "protocol/dissector.h"

#include <QtGui/QFontDatabase>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

// The frame editor shows about this many lines: a 255-byte frame as spaced hex fits in a few
// lines of a normal window, and the editor scrolls beyond that.
constexpr int kFrameEditorLines = 4;

QString framingTitle(Framing framing)
{
    return framingName(framing).toUpper();
}

} // namespace

DecodePanel::DecodePanel(QWidget *parent)
    : QWidget(parent)
    , m_model(new FieldTreeModel(this))
{
    buildUi();
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(kDebounceMs);
    connect(&m_debounce, &QTimer::timeout, this, &DecodePanel::decodeNow);
    connect(m_frameEdit, &QPlainTextEdit::textChanged, &m_debounce, qOverload<>(&QTimer::start));
    connect(m_requestEdit, &QLineEdit::textChanged, &m_debounce, qOverload<>(&QTimer::start));
    connect(m_framingCombo, &QComboBox::currentIndexChanged, this, &DecodePanel::decodeNow);
    connect(m_directionCombo, &QComboBox::currentIndexChanged, this, &DecodePanel::decodeNow);
    showEmpty();
}

void DecodePanel::buildUi()
{
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);

    m_frameEdit = new QPlainTextEdit(this);
    m_frameEdit->setObjectName(QStringLiteral("frameEdit"));
    m_frameEdit->setFont(mono);
    m_frameEdit->setTabChangesFocus(true);
    m_frameEdit->setPlaceholderText(tr("Type or paste a frame as hex: 01 03 00 79 00 16 15 DD"));
    const QFontMetrics fm(mono);
    const int frame = 2 * m_frameEdit->frameWidth() + int(2 * m_frameEdit->document()->documentMargin());
    m_frameEdit->setFixedHeight(fm.lineSpacing() * kFrameEditorLines + frame);

    m_framingCombo = new QComboBox(this);
    m_framingCombo->setObjectName(QStringLiteral("framingCombo"));
    m_framingCombo->addItem(tr("Auto-detect"), int(Framing::Auto));
    m_framingCombo->addItem(tr("RTU"), int(Framing::Rtu));
    m_framingCombo->addItem(tr("ASCII"), int(Framing::Ascii));
    m_framingCombo->addItem(tr("TCP (MBAP)"), int(Framing::Tcp));
    m_framingCombo->addItem(tr("UDP (MBAP)"), int(Framing::Udp));
    m_framingCombo->addItem(tr("PDU only"), int(Framing::Pdu));

    m_directionCombo = new QComboBox(this);
    m_directionCombo->setObjectName(QStringLiteral("directionCombo"));
    m_directionCombo->addItem(tr("Auto-detect"), int(Direction::Auto));
    m_directionCombo->addItem(tr("Request"), int(Direction::Request));
    m_directionCombo->addItem(tr("Response"), int(Direction::Response));

    m_requestEdit = new QLineEdit(this);
    m_requestEdit->setObjectName(QStringLiteral("requestEdit"));
    m_requestEdit->setFont(mono);
    m_requestEdit->setClearButtonEnabled(true);
    m_requestEdit->setPlaceholderText(tr("optional: the request this response answers"));
    m_requestEdit->setToolTip(tr("With the matching request, a response's byte count, echoed values and "
                                 "transaction id are checked against what was asked"));

    // Frame, Framing and Direction have no accelerator: every letter of them is the window's
    // already, in English or in Indonesian (File, Request, Answer, Timeout, Saved, Decode, Listen,
    // Connect, Tools, Host, Send; Kirim, Simak, Mulai polling...): Tab reaches them.
    auto *frameLabel = new QLabel(tr("Frame:"), this);
    frameLabel->setBuddy(m_frameEdit);
    auto *framingLabel = new QLabel(tr("Framing:"), this);
    framingLabel->setBuddy(m_framingCombo);
    auto *directionLabel = new QLabel(tr("Direction:"), this);
    directionLabel->setBuddy(m_directionCombo);
    auto *requestLabel = new QLabel(tr("Matching re&quest:"), this);
    requestLabel->setBuddy(m_requestEdit);

    // The window fits 1024 px: the combos give way rather than widen the Decode tab.
    for (QComboBox *combo : {m_framingCombo, m_directionCombo}) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(6);
    }
    auto *options = new QHBoxLayout;
    options->addWidget(m_framingCombo);
    options->addSpacing(12);
    options->addWidget(directionLabel);
    options->addWidget(m_directionCombo);
    options->addSpacing(12);
    options->addWidget(requestLabel);
    options->addWidget(m_requestEdit, 1);

    auto *inputs = new QGridLayout;
    inputs->addWidget(frameLabel, 0, 0, Qt::AlignTop | Qt::AlignLeft);
    inputs->addWidget(m_frameEdit, 0, 1);
    inputs->addWidget(framingLabel, 1, 0);
    inputs->addLayout(options, 1, 1);
    inputs->setColumnStretch(1, 1);

    m_verdictLabel = new QLabel(this);
    m_verdictLabel->setObjectName(QStringLiteral("verdictLabel"));
    QFont bold = m_verdictLabel->font();
    bold.setBold(true);
    m_verdictLabel->setFont(bold);
    m_summaryLabel = new QLabel(this);
    m_summaryLabel->setObjectName(QStringLiteral("summaryLabel"));
    m_summaryLabel->setWordWrap(true);
    m_summaryLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *summaryRow = new QHBoxLayout;
    summaryRow->addWidget(m_verdictLabel, 0, Qt::AlignTop);
    summaryRow->addWidget(m_summaryLabel, 1);

    m_errorLabel = hexerrormark::newErrorLabel(QStringLiteral("errorLabel"), this);

    m_reasonLabel = new QLabel(this);
    m_reasonLabel->setObjectName(QStringLiteral("reasonLabel"));
    m_reasonLabel->setWordWrap(true);
    m_reasonLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_reasonLabel->setForegroundRole(QPalette::PlaceholderText);

    m_tree = new FieldTreeView(this);
    m_tree->setObjectName(QStringLiteral("fieldTree"));
    m_tree->setFieldModel(m_model);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(inputs);
    layout->addLayout(summaryRow);
    layout->addWidget(m_errorLabel);
    layout->addWidget(m_reasonLabel);
    layout->addWidget(m_tree, 1);
}

void DecodePanel::setFrameText(const QString &text)
{
    m_frameEdit->setPlainText(text);
}

QString DecodePanel::frameText() const
{
    return m_frameEdit->toPlainText();
}

void DecodePanel::setRequestText(const QString &text)
{
    m_requestEdit->setText(text);
}

QString DecodePanel::requestText() const
{
    return m_requestEdit->text();
}

void DecodePanel::setFraming(Framing framing)
{
    m_framingCombo->setCurrentIndex(m_framingCombo->findData(int(framing)));
}

Framing DecodePanel::framing() const
{
    return Framing(m_framingCombo->currentData().toInt());
}

void DecodePanel::setDirection(Direction direction)
{
    m_directionCombo->setCurrentIndex(m_directionCombo->findData(int(direction)));
}

Direction DecodePanel::direction() const
{
    return Direction(m_directionCombo->currentData().toInt());
}

const Dissection &DecodePanel::dissection() const
{
    return m_model->dissection();
}

void DecodePanel::decodeNow()
{
    m_debounce.stop();
    m_frameEdit->setExtraSelections({});
    const QString text = m_frameEdit->toPlainText();
    if (text.trimmed().isEmpty()) {
        showEmpty();
        return;
    }
    const HexTextResult frame = HexText::parse(text);
    if (!frame.ok) {
        showInputError(tr("Frame"), frame.error, true);
        return;
    }
    if (frame.bytes.isEmpty()) {
        showEmpty();
        return;
    }
    DissectOptions options;
    options.framing = framing();
    options.direction = direction();
    const QString requestHex = m_requestEdit->text();
    if (!requestHex.trimmed().isEmpty()) {
        const HexTextResult request = HexText::parse(requestHex);
        if (!request.ok) {
            showInputError(tr("Matching request"), request.error, false);
            return;
        }
        options.request = request.bytes;
    }
    showDissection(Dissector::dissect(frame.bytes, options));
}

void DecodePanel::showDissection(const Dissection &dissection)
{
    m_inputError.clear();
    m_errorLabel->hide();
    m_model->setDissection(dissection);
    m_tree->showAllFields();

    // summary() already counts errors and warnings; the verdict only says whether the frame
    // keeps to the spec, coloured by the worst problem found.
    const Severity worst = dissection.fields.worstSeverity();
    setVerdict(dissection.isValid() ? tr("Valid:") : tr("Invalid:"),
               worst >= Severity::Warning ? worst : Severity::Ok);
    m_summaryLabel->setText(DissectionSummary::text(dissection));

    const QString framingReason = dissection.framingReason.isEmpty() ? tr("as chosen") : dissection.framingReason.toString();
    const QString directionReason = dissection.directionReason.isEmpty() ? tr("as chosen") : dissection.directionReason.toString();
    m_reasonLabel->setText(tr("Framing %1: %2. Direction %3: %4.")
                               .arg(framingTitle(dissection.framing), framingReason,
                                    directionName(dissection.direction), directionReason));
    Q_EMIT decoded();
}

void DecodePanel::showEmpty()
{
    m_inputError.clear();
    m_errorLabel->hide();
    m_model->clear();
    setVerdict({}, Severity::Ok);
    m_summaryLabel->setText(tr("Type or paste a frame as hex; the fields appear as you type."));
    m_reasonLabel->clear();
    Q_EMIT decoded();
}

void DecodePanel::showInputError(const QString &what, const HexTextError &error, bool inFrame)
{
    m_inputError = what + QStringLiteral(": ") + error.message;
    QString text = m_inputError;
    if (!m_model->dissection().fields.isEmpty())
        text += QLatin1Char(' ') + tr("(the tree shows the last input that could be read)");
    m_errorLabel->setText(text);
    m_errorLabel->show();
    if (inFrame)
        hexerrormark::mark(m_frameEdit, error);
    Q_EMIT decoded();
}

void DecodePanel::setVerdict(const QString &text, Severity severity)
{
    SeverityStyle::setTextColour(m_verdictLabel, severity);
    m_verdictLabel->setText(text);
    m_verdictLabel->setVisible(!text.isEmpty());
}

} // namespace mbscope
