#include "tlsfilesfield.h"

#include "common/lastfolder.h"

#include <QtCore/QFileInfo>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QToolButton>

namespace mbscope {

TlsFilesField::TlsFilesField(QWidget *parent)
    : QWidget(parent)
{
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    m_certificate = addFile(tr("C&ertificate:"), QStringLiteral("tlsCertificateEdit"), tr("client certificate (PEM)"),
                            tr("Choose this client's certificate (PEM)"));
    m_key = addFile(tr("&Key:"), QStringLiteral("tlsKeyEdit"), tr("its private key (PEM)"),
                    tr("Choose the private key of the client certificate (PEM, no passphrase)"));
    m_ca = addFile(tr("C&A:"), QStringLiteral("tlsCaEdit"), tr("device's CA (PEM; empty: system CAs)"),
                   tr("Choose the CA certificate that signed the device's certificate (PEM)"));
    setToolTip(tr("MODBUS/TCP Security (port 802) is mutual TLS: the device asks for this client's certificate "
                  "and key, and its own certificate is checked against the CA file (or the system's CAs)."));
}

QLineEdit *TlsFilesField::addFile(const QString &label, const QString &objectName, const QString &placeholder,
                                  const QString &chooserTitle)
{
    auto *edit = new QLineEdit(this);
    edit->setObjectName(objectName);
    edit->setPlaceholderText(placeholder);
    edit->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("/etc/modbus/client.pem__")));
    auto *caption = new QLabel(label, this);
    caption->setBuddy(edit);
    auto *choose = new QToolButton(this);
    choose->setObjectName(objectName + QStringLiteral("Chooser"));
    choose->setText(QStringLiteral("\u2026"));
    choose->setToolTip(chooserTitle);
    connect(choose, &QToolButton::clicked, this, [this, edit, chooserTitle] {
        const QString start = edit->text().isEmpty() ? LastFolder::start() : QFileInfo(edit->text()).absolutePath();
        const QString path = QFileDialog::getOpenFileName(this, chooserTitle, start,
                                                          tr("PEM files (*.pem *.crt *.cer *.key);;All files (*)"));
        if (path.isEmpty())
            return;
        LastFolder::remember(path);
        edit->setText(path);
        Q_EMIT edited();
    });
    connect(edit, &QLineEdit::textEdited, this, &TlsFilesField::edited);
    auto *row = static_cast<QHBoxLayout *>(layout());
    row->addWidget(caption);
    row->addWidget(edit, 1);
    row->addWidget(choose);
    return edit;
}

TlsSettings TlsFilesField::settings() const
{
    TlsSettings tls;
    tls.certificate = m_certificate->text().trimmed();
    tls.privateKey = m_key->text().trimmed();
    tls.caCertificates = m_ca->text().trimmed();
    return tls;
}

void TlsFilesField::setSettings(const TlsSettings &tls)
{
    m_certificate->setText(tls.certificate);
    m_key->setText(tls.privateKey);
    m_ca->setText(tls.caCertificates);
}

QString TlsFilesField::checkFile(QLineEdit *edit, const QString &role)
{
    const QString path = edit->text().trimmed();
    if (path.isEmpty())
        return {};
    const QFileInfo info(path);
    QString problem;
    if (!info.exists())
        problem = tr("The %1 file '%2' does not exist: choose it with the \u2026 button beside the field.").arg(role, path);
    else if (info.isDir())
        problem = tr("The %1 file '%2' is a folder: choose the PEM file inside it.").arg(role, path);
    else if (!info.isReadable())
        problem = tr("The %1 file '%2' cannot be read (permission denied): make it readable by your user.").arg(role, path);
    if (!problem.isEmpty())
        edit->setFocus();
    return problem;
}

QString TlsFilesField::check()
{
    const TlsSettings tls = settings();
    if (tls.certificate.isEmpty() != tls.privateKey.isEmpty()) {
        QLineEdit *missing = tls.certificate.isEmpty() ? m_certificate : m_key;
        missing->setFocus();
        return tls.certificate.isEmpty()
            ? tr("A private key was given without its certificate: choose the client certificate too (mutual TLS needs both).")
            : tr("A certificate was given without its private key: choose the key file too (mutual TLS needs both).");
    }
    for (const auto &[edit, role] : {std::pair{m_certificate, tr("certificate")}, std::pair{m_key, tr("private key")},
                                     std::pair{m_ca, tr("CA certificate")}}) {
        const QString problem = checkFile(edit, role);
        if (!problem.isEmpty())
            return problem;
    }
    return {};
}

} // namespace mbscope
