#include "noticebanner.h"

#include "severitystyle.h"

#include <QtCore/QEvent>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QToolButton>

namespace mbscope {

// The information tint of the palette in use: made again when the theme changes, or the light
// theme's pale blue would stay under the dark theme's light text (issue 31, tst_windowfit).
void NoticeBanner::applyTint()
{
    QPalette tint; // the window colour only: the text and the rest come from the window's palette
    tint.setColor(QPalette::Window, SeverityStyle::backgroundColor(Severity::Info));
    setPalette(tint);
}

void NoticeBanner::changeEvent(QEvent *event)
{
    QFrame::changeEvent(event);
    // (Its own setPalette sends a PaletteChange too: the tint is set only when it differs.)
    if ((event->type() == QEvent::ApplicationPaletteChange || event->type() == QEvent::PaletteChange)
        && palette().color(QPalette::Window) != SeverityStyle::backgroundColor(Severity::Info))
        applyTint();
}

NoticeBanner::NoticeBanner(QWidget *parent)
    : QFrame(parent)
    , m_label(new QLabel(this))
{
    setObjectName(QStringLiteral("noticeBanner"));
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    applyTint();
    m_label->setObjectName(QStringLiteral("noticeText"));
    m_label->setWordWrap(true);
    m_label->setTextFormat(Qt::RichText);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::LinksAccessibleByMouse | Qt::LinksAccessibleByKeyboard);
    m_label->setOpenExternalLinks(false);
    connect(m_label, &QLabel::linkActivated, this, &NoticeBanner::linkActivated);
    auto *close = new QToolButton(this);
    close->setObjectName(QStringLiteral("noticeCloseButton"));
    close->setText(tr("Dismiss"));
    close->setAutoRaise(true);
    connect(close, &QToolButton::clicked, this, [this] {
        hide();
        Q_EMIT dismissed();
    });
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 6, 6);
    layout->addWidget(m_label, 1);
    layout->addWidget(close, 0, Qt::AlignTop);
    hide();
}

void NoticeBanner::showNotice(const QString &richText)
{
    m_label->setText(richText);
    show();
}

QString NoticeBanner::text() const
{
    return m_label->text();
}

} // namespace mbscope
