#pragma once

#include <QtWidgets/QFrame>

class QLabel;

namespace mbscope {

// A tinted strip above the panels that tells the user something about the whole window (the
// built-in simulator is what answers, and how to reach a real device). It can be dismissed.
class NoticeBanner : public QFrame
{
    Q_OBJECT
public:
    explicit NoticeBanner(QWidget *parent = nullptr);

    void showNotice(const QString &richText);
    [[nodiscard]] QString text() const;

private:
    QLabel *m_label = nullptr;
};

} // namespace mbscope
