#pragma once

#include "common/frameexchange.h"

#include "exchange/transaction.h"
#include "protocol/dissection.h"

#include <QtWidgets/QWidget>

class QLabel;
class QSplitter;
class QToolButton;

namespace mbscope {

class FrameInspector;

// The decode view of the workbench: a request and its matched answer, each as a field tree beside
// its bytes (FrameInspector), stacked, with the verdict and the latency on top, and Copy as text,
// JSON or hex. It shows what the traffic monitor or the engine hands it; typing frames by hand is
// DecodePanel's job.
class DecodeView : public QWidget
{
    Q_OBJECT

public:
    enum class CopyFormat : quint8 { Text, Json, Hex };
    Q_ENUM(CopyFormat)

    explicit DecodeView(QWidget *parent = nullptr);

    [[nodiscard]] const Dissection &requestDissection() const;
    [[nodiscard]] const Dissection &responseDissection() const;
    [[nodiscard]] const FrameExchange &exchange() const { return m_exchange; }
    [[nodiscard]] FrameInspector *requestInspector() const { return m_request; }
    [[nodiscard]] FrameInspector *responseInspector() const { return m_response; }

    // What Copy puts on the clipboard in a format.
    [[nodiscard]] QString copyText(CopyFormat format) const;

public Q_SLOTS:
    // Dissects both frames (the answer against its request) and shows them.
    void showExchange(const mbscope::FrameExchange &exchange);
    // The same for one transaction from the engine (TransactionEngine::transactionsFinished).
    void showTransaction(const mbscope::Transaction &transaction, mbscope::Framing framing);
    void clear();
    void copy(mbscope::DecodeView::CopyFormat format);

Q_SIGNALS:
    void shown();

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void buildUi();
    void updateHeader();
    void fitSplitter();

    FrameExchange m_exchange;
    QLabel *m_header = nullptr;
    QToolButton *m_copyButton = nullptr;
    QSplitter *m_splitter = nullptr;
    FrameInspector *m_request = nullptr;
    FrameInspector *m_response = nullptr;
    bool m_splitterMoved = false;
};

} // namespace mbscope
