#pragma once

#include <QtWidgets/QFrame>

class QLabel;

namespace mbscope {

// A tinted strip above the panels that tells the user something about the whole window (the
// built-in simulator is what answers, and how to reach a real device). It can be dismissed. Links
// in the notice are actions its owner handles (linkActivated), never opened in a browser.
class NoticeBanner : public QFrame
{
    Q_OBJECT
public:
    explicit NoticeBanner(QWidget *parent = nullptr);

    void showNotice(const QString &richText);
    [[nodiscard]] QString text() const;

Q_SIGNALS:
    // A link in the notice was clicked (<a href="open">): its href.
    void linkActivated(const QString &href);
    void dismissed();

protected:
    void changeEvent(QEvent *event) override;

private:
    void applyTint();

    QLabel *m_label = nullptr;
};

} // namespace mbscope
