#pragma once

// Throwaway TLS certificates for the tests (MODBUS/TCP Security: mutual TLS), made with the
// openssl command in one folder: NAME.pem and NAME.key for every CA and leaf, EC P-256, valid
// for two days. Shared by tst_tlslink, tst_simulator_tls and the `mbscope simulate` tests.

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope::testing {

class TestCertificates
{
public:
    // Certificates are written into dir, which must exist.
    explicit TestCertificates(QString dir);

    // False when openssl is not installed; error() then says what to install.
    [[nodiscard]] bool isAvailable() const { return !m_openssl.isEmpty(); }
    // What the last failing call could not do (the openssl command and its output).
    [[nodiscard]] QString error() const { return m_error; }
    [[nodiscard]] QString path(const QString &fileName) const;

    // A self-signed CA: NAME.pem, NAME.key; subject "/CN=NAME" unless given.
    bool makeCa(const QString &name, const QString &subject = QString());
    // A key and a certificate signed by the CA named ca, with the given x509v3 extensions
    // ("subjectAltName=IP:127.0.0.1\nextendedKeyUsage=serverAuth\n"); subject "/CN=NAME" unless given.
    bool issue(const QString &name, const QByteArray &extensions, const QString &ca, const QString &subject = QString());

private:
    bool openssl(const QStringList &arguments);

    QString m_dir;
    QString m_openssl;
    QString m_error;
};

} // namespace mbscope::testing
