#include "analysisdock.h"

#include <QtWidgets/QTabWidget>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

AnalysisDock::AnalysisDock(QWidget *parent)
    : QWidget(parent)
    , m_tabs(new QTabWidget(this))
{
    m_tabs->setObjectName(QStringLiteral("analysisTabs"));
    m_tabs->setDocumentMode(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs);
}

void AnalysisDock::addPanel(QWidget *panel, const QString &title)
{
    m_tabs->addTab(panel, title);
}

void AnalysisDock::showPanel(QWidget *panel)
{
    if (m_tabs->indexOf(panel) >= 0)
        m_tabs->setCurrentWidget(panel);
}

} // namespace mbscope
