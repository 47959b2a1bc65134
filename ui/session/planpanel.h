#pragma once

#include "session/sessiondocument.h"

#include <QtWidgets/QWidget>

#include <functional>

class QLabel;
class QPushButton;
class QTableView;

namespace mbscope {

class PlanController;

// The Test plan dock: Run runs the session's plan (the document the window would save, so the
// plan read from the opened file), each step listed as it ends with pass or fail, what it
// expected, what came and why it failed; a summary line; the results exported as JUnit XML.
class PlanPanel : public QWidget
{
    Q_OBJECT
public:
    using DocumentSource = std::function<SessionDocument()>;
    // Asked for the JUnit file to write; empty: cancelled.
    using FileChooser = std::function<QString()>;

    PlanPanel(PlanController *controller, DocumentSource document, QWidget *parent = nullptr);

    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }

    void run();
    void exportJUnit();
    // Says what the session now open holds (its plan's name and steps, or that it has none),
    // unless a run is going on or its results are shown.
    void showDocumentHint();
    [[nodiscard]] QTableView *resultsView() const { return m_table; }
    [[nodiscard]] QString summaryText() const;

private:
    void setSummary(const QString &text, bool problem);
    void updateState();

    PlanController *m_controller;
    DocumentSource m_document;
    FileChooser m_chooser;
    QPushButton *m_runButton = nullptr;
    QPushButton *m_stopButton = nullptr;
    QPushButton *m_exportButton = nullptr;
    QLabel *m_summary = nullptr;
    QTableView *m_table = nullptr;
};

} // namespace mbscope
