#pragma once

#include "transport/linkurl.h"

#include <QtWidgets/QWidget>

class QLineEdit;

namespace mbscope {

// The three PEM files of a tls:// target (MODBUS/TCP Security: mutual TLS): this client's
// certificate and private key, and the CA that signed the device's certificate, each a path with
// a "…" button that opens a file chooser. check() says what is wrong with them before a link
// tries: a file that does not exist or cannot be read, named with its role and path, or a
// certificate without its key.
class TlsFilesField : public QWidget
{
    Q_OBJECT
public:
    explicit TlsFilesField(QWidget *parent = nullptr);

    [[nodiscard]] TlsSettings settings() const;
    void setSettings(const TlsSettings &tls);
    // Empty when the files can be used; otherwise the message, and the field at fault has focus.
    [[nodiscard]] QString check();

    [[nodiscard]] QLineEdit *certificateEdit() const { return m_certificate; }
    [[nodiscard]] QLineEdit *keyEdit() const { return m_key; }
    [[nodiscard]] QLineEdit *caEdit() const { return m_ca; }

Q_SIGNALS:
    // The user typed or chose a file.
    void edited();

private:
    QLineEdit *addFile(const QString &label, const QString &objectName, const QString &placeholder,
                       const QString &chooserTitle);
    [[nodiscard]] QString checkFile(QLineEdit *edit, const QString &role);

    QLineEdit *m_certificate = nullptr;
    QLineEdit *m_key = nullptr;
    QLineEdit *m_ca = nullptr;
};

} // namespace mbscope
