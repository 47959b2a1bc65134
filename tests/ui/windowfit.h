#pragma once
// What tst_windowfit checks on a rendered window, each check a function of its own so that the
// test can also show each one failing on a widget made to break it (issue 31, "Fit").

#include <QtCore/QAbstractItemModel>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
#include <QtGui/QBrush>
#include <QtCore/QStringList>
#include <QtGui/QColor>
#include <QtGui/QGuiApplication>
#include <QtGui/QTextDocumentFragment>
#include <QtWidgets/QAbstractButton>
#include <QtWidgets/QAbstractItemView>
#include <QtWidgets/QAbstractScrollArea>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QRadioButton>
#include <QtWidgets/QScrollBar>
#include <QtWidgets/QStatusBar>
#include <QtWidgets/QStyle>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QWidget>

#include <algorithm>
#include <cmath>

namespace mbscope::windowfit {

// WCAG 2.x: text of normal size needs 4.5:1 against its background (level AA).
constexpr double kMinimumContrast = 4.5;

inline QString pathOf(const QObject *o, const QObject *root = nullptr)
{
    QStringList parts;
    for (; o && o != root; o = o->parent())
        parts.prepend(o->objectName().isEmpty() ? QString::fromLatin1(o->metaObject()->className()) : o->objectName());
    return parts.join(QLatin1Char('/'));
}

inline double luminance(const QColor &c)
{
    auto channel = [](double v) { return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    const QColor rgb = c.toRgb();
    return 0.2126 * channel(rgb.redF()) + 0.7152 * channel(rgb.greenF()) + 0.0722 * channel(rgb.blueF());
}

inline double contrast(const QColor &a, const QColor &b)
{
    const double la = luminance(a);
    const double lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

// The text as shown: "&&" is one '&', a single '&' marks the accelerator.
inline QString shownText(const QString &text)
{
    QString out;
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text.at(i) == QLatin1Char('&') && i + 1 < text.size()) {
            ++i;
        }
        out += text.at(i);
    }
    return out;
}

// True when text has a single '&' (not "&&", not an HTML entity of rich text).
inline bool hasMnemonicMark(const QString &text)
{
    static const QRegularExpression single(QStringLiteral("(^|[^&])&([^&\\s])"));
    return single.match(QString(text).remove(QStringLiteral("&&"))).hasMatch();
}

// Shown on the screen: visible, and not behind another dock of its tab group (Qt keeps those
// "visible" but moves them out of the window).
inline bool shown(const QWidget *w, const QWidget *root)
{
    if (!w->isVisibleTo(root) || !w->isVisible())
        return false;
    const QRect inWindow(w->mapTo(w->window(), QPoint(0, 0)), w->size());
    return inWindow.intersects(w->window()->rect());
}

// Children placed (partly) outside their parent's rectangle: cut off, unreachable. The contents of
// a scroll area's viewport are meant to be larger (they scroll), so they are left out.
inline QStringList outsideParent(QWidget *root)
{
    QStringList problems;
    for (QWidget *w : root->findChildren<QWidget *>()) {
        QWidget *parent = w->parentWidget();
        if (!parent || w->isWindow() || !shown(w, root) || w->window() != root->window())
            continue;
        if (auto *area = qobject_cast<QAbstractScrollArea *>(parent->parentWidget()); area && area->viewport() == parent)
            continue;
        if (w->geometry().isEmpty() || !shown(parent, root))
            continue;
        if (!parent->rect().contains(w->geometry()))
            problems << QStringLiteral("%1 at (%2,%3 %4x%5) lies outside its parent (%6x%7)")
                            .arg(pathOf(w, root->parent()))
                            .arg(w->x()).arg(w->y()).arg(w->width()).arg(w->height())
                            .arg(parent->width()).arg(parent->height());
    }
    return problems;
}

inline int textWidth(const QFontMetrics &fm, const QString &text)
{
    int widest = 0;
    for (const QString &line : text.split(QLatin1Char('\n')))
        widest = std::max(widest, fm.horizontalAdvance(line));
    return widest;
}

// Column headers narrower than their title (Qt elides it: "Laten…"), and buttons narrower than
// their text (cut at both ends).
inline QStringList elidedText(QWidget *root)
{
    QStringList problems;
    for (QHeaderView *header : root->findChildren<QHeaderView *>()) {
        if (!shown(header, root) || header->orientation() != Qt::Horizontal || !header->model())
            continue;
        const int margin = header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
        const int mark = header->isSortIndicatorShown()
            ? header->style()->pixelMetric(QStyle::PM_HeaderMarkSize, nullptr, header) + margin : 0;
        for (int logical = 0; logical < header->count(); ++logical) {
            if (header->isSectionHidden(logical) || header->sectionSize(logical) == 0)
                continue;
            const QString title = header->model()->headerData(logical, Qt::Horizontal).toString();
            if (title.isEmpty())
                continue;
            const int indicator = header->sortIndicatorSection() == logical ? mark : 0;
            const int needed = textWidth(header->fontMetrics(), title) + 2 * margin + indicator;
            if (header->sectionSize(logical) < needed)
                problems << QStringLiteral("%1: column \"%2\" is %3 px, its title needs %4")
                                .arg(pathOf(header, root->parent()), title)
                                .arg(header->sectionSize(logical))
                                .arg(needed);
        }
    }
    for (QAbstractButton *button : root->findChildren<QAbstractButton *>()) {
        if (!shown(button, root) || button->text().isEmpty() || button->inherits("QTabBar"))
            continue;
        int needed = 0;
        if (qobject_cast<QCheckBox *>(button) || qobject_cast<QRadioButton *>(button)
            || qobject_cast<QToolButton *>(button))
            needed = button->sizeHint().width(); // their hint is exactly indicator or icon plus text
        else // a push button draws its text inside its frame: cut when the frame leaves it less room
            needed = textWidth(button->fontMetrics(), shownText(button->text()))
                + (button->icon().isNull() ? 0 : button->iconSize().width() + 4)
                + 2 * button->style()->pixelMetric(QStyle::PM_DefaultFrameWidth, nullptr, button)
                + (qobject_cast<QPushButton *>(button) && qobject_cast<QPushButton *>(button)->menu()
                       ? button->style()->pixelMetric(QStyle::PM_MenuButtonIndicator, nullptr, button) : 0);
        if (button->width() < needed)
            problems << QStringLiteral("%1: button \"%2\" is %3 px, its text needs %4")
                            .arg(pathOf(button, root->parent()), shownText(button->text()))
                            .arg(button->width())
                            .arg(needed);
    }
    // The status bar's message in the room the permanent widgets leave it.
    for (QStatusBar *bar : root->findChildren<QStatusBar *>()) {
        if (!shown(bar, root) || bar->currentMessage().isEmpty())
            continue;
        int room = bar->width() - 12; // the size grip's and the frame's margins
        for (QWidget *permanent : bar->findChildren<QWidget *>(Qt::FindDirectChildrenOnly)) {
            if (permanent->isVisible() && !permanent->inherits("QSizeGrip"))
                room -= permanent->width() + 4;
        }
        const int needed = bar->fontMetrics().horizontalAdvance(bar->currentMessage());
        if (needed > room)
            problems << QStringLiteral("%1: status message \"%2\" needs %3 px, has %4")
                            .arg(pathOf(bar, root->parent()), bar->currentMessage())
                            .arg(needed)
                            .arg(room);
    }
    // A label on one line narrower than its text is cut (the status bar's link state, a form's label).
    for (QLabel *label : root->findChildren<QLabel *>()) {
        if (!shown(label, root) || label->wordWrap() || label->text().isEmpty() || !label->pixmap().isNull())
            continue;
        if (label->sizePolicy().horizontalPolicy() == QSizePolicy::Ignored)
            continue; // elided on purpose, the whole text in its tooltip
        if (label->width() < label->minimumSizeHint().width())
            problems << QStringLiteral("%1: label \"%2\" is %3 px, its text needs %4")
                            .arg(pathOf(label, root->parent()),
                                 Qt::mightBeRichText(label->text()) ? QTextDocumentFragment::fromHtml(label->text()).toPlainText()
                                                                     : label->text())
                            .arg(label->width())
                            .arg(label->minimumSizeHint().width());
    }
    return problems;
}

// Texts that show their '&': a plain label with no buddy shows it as is, a column title always.
inline QStringList literalAmpersands(QWidget *root)
{
    QStringList problems;
    for (QLabel *label : root->findChildren<QLabel *>()) {
        if (!shown(label, root) || label->buddy() || label->textFormat() == Qt::RichText
            || (label->textFormat() == Qt::AutoText && Qt::mightBeRichText(label->text())))
            continue;
        if (hasMnemonicMark(label->text()))
            problems << QStringLiteral("%1: label shows \"%2\" (an '&' and no buddy)").arg(pathOf(label, root->parent()), label->text());
    }
    for (QHeaderView *header : root->findChildren<QHeaderView *>()) {
        if (!shown(header, root) || !header->model())
            continue;
        for (int s = 0; s < header->count(); ++s) {
            const QString title = header->model()->headerData(s, header->orientation()).toString();
            if (hasMnemonicMark(title))
                problems << QStringLiteral("%1: column title \"%2\"").arg(pathOf(header, root->parent()), title);
        }
    }
    return problems;
}

inline QColor colourOf(const QVariant &v)
{
    if (v.canConvert<QBrush>() && v.metaType().id() == QMetaType::QBrush)
        return v.value<QBrush>().color();
    if (v.canConvert<QColor>())
        return v.value<QColor>();
    return {};
}

// Coloured text (a verdict, a state, a rule) against what it is drawn on, below 4.5:1: the cells
// of every shown view that colour their text or background, and labels coloured by palette or in
// their rich text.
inline QStringList lowContrast(QWidget *root)
{
    QStringList problems;
    QSet<QString> seen;
    auto report = [&](const QString &where, const QString &text, const QColor &fg, const QColor &bg) {
        const double ratio = contrast(fg, bg);
        if (ratio >= kMinimumContrast)
            return;
        const QString line = QStringLiteral("%1: \"%2\" %3 on %4 is %5:1")
                                 .arg(where, text.left(40), fg.name(), bg.name())
                                 .arg(ratio, 0, 'f', 2);
        if (!seen.contains(line)) {
            seen.insert(line);
            problems << line;
        }
    };
    for (QAbstractItemView *view : root->findChildren<QAbstractItemView *>()) {
        QAbstractItemModel *model = view->model();
        if (!shown(view, root) || !model || !view->isEnabled())
            continue;
        const QPalette palette = view->palette();
        // The cells the view shows (and their first children in a tree), at most 60 rows.
        QList<QModelIndex> parents{view->rootIndex()};
        for (int r = 0; r < std::min(model->rowCount(view->rootIndex()), 20); ++r)
            parents << model->index(r, 0, view->rootIndex());
        int rows = 0;
        for (const QModelIndex &parent : parents) {
            for (int r = 0; r < model->rowCount(parent) && rows < 60; ++r, ++rows) {
                for (int c = 0; c < model->columnCount(parent); ++c) {
                    const QModelIndex index = model->index(r, c, parent);
                    const QColor fg = colourOf(index.data(Qt::ForegroundRole));
                    const QColor bg = colourOf(index.data(Qt::BackgroundRole));
                    const QString text = index.data(Qt::DisplayRole).toString();
                    if ((!fg.isValid() && !bg.isValid()) || text.trimmed().isEmpty())
                        continue;
                    report(QStringLiteral("%1 column %2").arg(pathOf(view, root->parent())).arg(c), text,
                           fg.isValid() ? fg : palette.color(QPalette::Text),
                           bg.isValid() ? bg : palette.color(QPalette::Base));
                }
            }
        }
    }
    static const QRegularExpression colourStyle(QStringLiteral("color:\\s*(#[0-9a-fA-F]{6}|[a-z]+)"));
    for (QLabel *label : root->findChildren<QLabel *>()) {
        if (!shown(label, root) || label->text().isEmpty() || !label->isEnabled())
            continue; // WCAG leaves out the text of controls that cannot be used
        const QColor back = label->palette().color(label->backgroundRole());
        const QString plain = Qt::mightBeRichText(label->text()) ? QTextDocumentFragment::fromHtml(label->text()).toPlainText()
                                                                 : label->text();
        // Its text on what it is drawn on: a tinted banner's text included (after a change of
        // theme a tint made for the other one showed light text on pale blue).
        if (label->foregroundRole() == QPalette::WindowText)
            report(pathOf(label, root->parent()), plain, label->palette().color(QPalette::WindowText), back);
        auto it = colourStyle.globalMatch(label->text());
        while (it.hasNext()) {
            const QColor fg(it.next().captured(1));
            if (fg.isValid())
                report(pathOf(label, root->parent()), plain, fg, back);
        }
    }
    return problems;
}

} // namespace mbscope::windowfit
