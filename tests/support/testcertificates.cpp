#include "testcertificates.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>

#include <utility>

namespace mbscope::testing {

namespace {

// A new EC P-256 key, unencrypted: fast to make, and what Qt's TLS backends all accept.
QStringList newEcKey()
{
    return {QStringLiteral("-newkey"), QStringLiteral("ec"), QStringLiteral("-pkeyopt"),
            QStringLiteral("ec_paramgen_curve:prime256v1"), QStringLiteral("-nodes")};
}

QString subjectOr(const QString &subject, const QString &name)
{
    return subject.isEmpty() ? QStringLiteral("/CN=") + name : subject;
}

} // namespace

TestCertificates::TestCertificates(QString dir)
    : m_dir(std::move(dir))
    , m_openssl(QStandardPaths::findExecutable(QStringLiteral("openssl")))
{
    if (m_openssl.isEmpty())
        m_error = QStringLiteral("openssl is not installed (Debian: openssl): no certificates to test TLS with");
}

QString TestCertificates::path(const QString &fileName) const
{
    return QDir(m_dir).filePath(fileName);
}

bool TestCertificates::openssl(const QStringList &arguments)
{
    if (!isAvailable())
        return false;
    QProcess process;
    process.setWorkingDirectory(m_dir);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(m_openssl, arguments);
    if (!process.waitForFinished(60000) || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        m_error = QStringLiteral("openssl %1 failed: %2").arg(arguments.join(QLatin1Char(' ')), QString::fromLocal8Bit(process.readAll()));
        return false;
    }
    return true;
}

bool TestCertificates::makeCa(const QString &name, const QString &subject)
{
    return openssl(QStringList{QStringLiteral("req"), QStringLiteral("-x509")} + newEcKey()
                   + QStringList{QStringLiteral("-keyout"), name + QStringLiteral(".key"), QStringLiteral("-out"),
                                 name + QStringLiteral(".pem"), QStringLiteral("-days"), QStringLiteral("2"),
                                 QStringLiteral("-subj"), subjectOr(subject, name)});
}

bool TestCertificates::issue(const QString &name, const QByteArray &extensions, const QString &ca, const QString &subject)
{
    QFile ext(path(name + QStringLiteral(".ext")));
    if (!ext.open(QIODevice::WriteOnly) || ext.write(extensions) != extensions.size()) {
        m_error = QStringLiteral("cannot write %1: %2").arg(ext.fileName(), ext.errorString());
        return false;
    }
    ext.close();
    return openssl(QStringList{QStringLiteral("req")} + newEcKey()
                   + QStringList{QStringLiteral("-keyout"), name + QStringLiteral(".key"), QStringLiteral("-out"),
                                 name + QStringLiteral(".csr"), QStringLiteral("-subj"), subjectOr(subject, name)})
        && openssl({QStringLiteral("x509"), QStringLiteral("-req"), QStringLiteral("-in"), name + QStringLiteral(".csr"),
                    QStringLiteral("-CA"), ca + QStringLiteral(".pem"), QStringLiteral("-CAkey"), ca + QStringLiteral(".key"),
                    QStringLiteral("-CAcreateserial"), QStringLiteral("-days"), QStringLiteral("2"), QStringLiteral("-extfile"),
                    name + QStringLiteral(".ext"), QStringLiteral("-out"), name + QStringLiteral(".pem")});
}

} // namespace mbscope::testing
