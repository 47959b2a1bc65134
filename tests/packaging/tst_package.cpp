// The Debian package as a user gets it: cpack builds it (into this test's temporary directory,
// from the same CPackConfig.cmake `make package` uses), dpkg-deb unpacks it into a scratch root,
// and the mbscope found there runs, outside the build tree. Its control fields carry computed
// dependencies; it holds the profiles, icons, desktop entry, AppStream file, man page and
// copyright; dpkg installs and removes it from a scratch root leaving nothing; and
// `cmake --install` to another prefix installs the same files.
#include "processrun.h"

#include <QtCore/QDir>
#include <QtCore/QDirIterator>
#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
#include <QtCore/QTemporaryDir>
#include <QtCore/QtEndian>
#include <QtTest/QtTest>

using namespace mbscope::testpackaging;

namespace {

const QString kAppId = QStringLiteral(MBSCOPE_APP_ID);
const QString kSourceDir = QStringLiteral(MBSCOPE_SOURCE_DIR);
const int kIconSizes[] = {16, 22, 24, 32, 48, 64, 128, 256};

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Regular files and symlinks under root, as paths relative to it, sorted.
QStringList filesUnder(const QString &root)
{
    QStringList files;
    QDirIterator it(root, QDir::Files | QDir::System | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext())
        files.append(QDir(root).relativeFilePath(it.next()));
    files.sort();
    return files;
}

// A PNG's width and height from its IHDR chunk (PNG spec, 11.2.2), or {0, 0}.
QSize pngSize(const QByteArray &png)
{
    if (png.size() < 24 || !png.startsWith("\x89PNG\r\n\x1a\n") || png.mid(12, 4) != "IHDR")
        return {};
    const auto *bytes = reinterpret_cast<const uchar *>(png.constData());
    return {int(qFromBigEndian<quint32>(bytes + 16)), int(qFromBigEndian<quint32>(bytes + 20))};
}

} // namespace

class TestPackage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void controlFields_data();
    void controlFields();
    void dependenciesAreComputed();
    void containsFile_data();
    void containsFile();
    void shipsEveryProfile();
    void shipsExamples();
    void iconsHaveTheirSize_data();
    void iconsHaveTheirSize();
    void manPageIsTheSource();
    void changelogNamesTheVersion();
    void installedBinaryRuns_data();
    void installedBinaryRuns();
    void installedBinaryNamesNoBuildTree_data();
    void installedBinaryNamesNoBuildTree();
    void desktopFileValidates();
    void metainfoValidates();
    void dpkgInstallsAndRemovesCleanly();
    void cmakeInstallsTheSameFilesToAnyPrefix();

private:
    [[nodiscard]] QString rootPath(const QString &relative) const { return m_root + QLatin1Char('/') + relative; }
    [[nodiscard]] QString field(const QString &name) const;

    QTemporaryDir m_dir;
    QString m_deb;
    QString m_root;
    QString m_control;
    QStringList m_files; // "usr/bin/mbscope", ...
};

void TestPackage::initTestCase()
{
    if (findProgram(QStringLiteral("dpkg-deb")).isEmpty())
        QSKIP("dpkg-deb is not installed: the package test needs Debian's dpkg");
    if (findProgram(QStringLiteral("dpkg-shlibdeps")).isEmpty())
        QSKIP("dpkg-shlibdeps is not installed (Debian: dpkg-dev, from scripts/install-deps.sh)");
    QVERIFY(m_dir.isValid());

    const QString out = m_dir.filePath(QStringLiteral("out"));
    const ProcessRun cpack = runProcess(QStringLiteral(MBSCOPE_CPACK),
                                        {QStringLiteral("--config"), QStringLiteral(MBSCOPE_BUILD_DIR "/CPackConfig.cmake"),
                                         QStringLiteral("-B"), out},
                                        m_dir.path(), 240000);
    QVERIFY2(cpack.succeeded(), cpack.describe().constData());
    m_deb = out + QLatin1Char('/') + QStringLiteral(MBSCOPE_DEB_NAME);
    QVERIFY2(QFile::exists(m_deb), qPrintable(QStringLiteral("cpack made no %1:\n%2").arg(m_deb, cpack.outText())));

    const ProcessRun info = runProcess(QStringLiteral("dpkg-deb"), {QStringLiteral("--field"), m_deb});
    QVERIFY2(info.succeeded(), info.describe().constData());
    m_control = info.outText();

    m_root = m_dir.filePath(QStringLiteral("root"));
    const ProcessRun extract = runProcess(QStringLiteral("dpkg-deb"), {QStringLiteral("-x"), m_deb, m_root});
    QVERIFY2(extract.succeeded(), extract.describe().constData());
    m_files = filesUnder(m_root);
    QVERIFY2(m_files.contains(QStringLiteral("usr/bin/mbscope")), qPrintable(m_files.join(QLatin1Char('\n'))));
}

QString TestPackage::field(const QString &name) const
{
    const QRegularExpression line(QStringLiteral("^%1: (.*)$").arg(name), QRegularExpression::MultilineOption);
    return line.match(m_control).captured(1).trimmed();
}

void TestPackage::controlFields_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("expected");
    const ProcessRun arch = runProcess(QStringLiteral("dpkg"), {QStringLiteral("--print-architecture")});
    QTest::newRow("Package") << QStringLiteral("Package") << QStringLiteral("mbscope");
    QTest::newRow("Version") << QStringLiteral("Version") << QStringLiteral(MBSCOPE_VERSION);
    QTest::newRow("Architecture") << QStringLiteral("Architecture") << arch.outText().trimmed();
    QTest::newRow("Section") << QStringLiteral("Section") << QStringLiteral("electronics");
}

void TestPackage::controlFields()
{
    QFETCH(QString, name);
    QFETCH(QString, expected);
    QCOMPARE(field(name), expected);
}

// dpkg-shlibdeps found the libraries the binary links (their package names are Debian's), so
// the package installs what it needs on a machine that never built mbscope.
void TestPackage::dependenciesAreComputed()
{
    const QString depends = field(QStringLiteral("Depends"));
    QList<const char *> packages{"libc6", "libqt6core6", "libqt6network6", "libqt6serialbus6", "libqt6serialport6"};
#ifdef MBSCOPE_HAVE_UI
    packages += {"libqt6widgets6", "libqcustomplot"};
#endif
    for (const char *package : std::as_const(packages)) {
        QVERIFY2(depends.contains(QLatin1String(package)),
                 qPrintable(QStringLiteral("Depends lacks %1: %2").arg(QLatin1String(package), depends)));
    }
    QVERIFY2(depends.contains(QRegularExpression(QStringLiteral(R"(libqt6core6 \(>= [0-9.]+\))"))), qPrintable(depends));
}

void TestPackage::containsFile_data()
{
    QTest::addColumn<QString>("path");
    const QStringList paths{
        QStringLiteral("usr/bin/mbscope"),
        QStringLiteral("usr/bin/mbscope-full"), // the window and the heavy commands, which mbscope execs
        QStringLiteral("usr/share/applications/%1.desktop").arg(kAppId),
        QStringLiteral("usr/share/metainfo/%1.metainfo.xml").arg(kAppId),
        QStringLiteral("usr/share/icons/hicolor/scalable/apps/mbscope.svg"),
        QStringLiteral("usr/share/man/man1/mbscope.1.gz"),
        QStringLiteral("usr/share/bash-completion/completions/mbscope"),
        QStringLiteral("usr/share/zsh/vendor-completions/_mbscope"),
        QStringLiteral("usr/share/doc/mbscope/copyright"),
        QStringLiteral("usr/share/doc/mbscope/changelog.gz"),
        QStringLiteral("usr/share/mbscope/profiles/rosrao-gamma.json"),
        QStringLiteral("usr/lib/systemd/system/mbscope-watch@.service"),
    };
    for (const QString &path : paths)
        QTest::newRow(qPrintable(path)) << path;
    for (const int size : kIconSizes) {
        const QString path = QStringLiteral("usr/share/icons/hicolor/%1x%1/apps/mbscope.png").arg(size);
        QTest::newRow(qPrintable(path)) << path;
    }
}

void TestPackage::containsFile()
{
    QFETCH(QString, path);
    QVERIFY2(m_files.contains(path), qPrintable(QStringLiteral("%1 is not in the package; it has:\n%2")
                                                   .arg(path, m_files.join(QLatin1Char('\n')))));
    QVERIFY2(QFileInfo(rootPath(path)).size() > 0, qPrintable(path + QStringLiteral(" is empty")));
}

void TestPackage::shipsEveryProfile()
{
    const QDir profiles(kSourceDir + QStringLiteral("/resources/profiles"));
    const QStringList names = profiles.entryList({QStringLiteral("*.json")}, QDir::Files);
    QVERIFY(!names.isEmpty());
    for (const QString &name : names) {
        const QString shipped = rootPath(QStringLiteral("usr/share/mbscope/profiles/") + name);
        QVERIFY2(QFile::exists(shipped), qPrintable(shipped));
        QVERIFY2(readAll(shipped) == readAll(profiles.filePath(name)), qPrintable(name + QStringLiteral(" differs")));
    }
}

void TestPackage::shipsExamples()
{
    const QString examples = kSourceDir + QStringLiteral("/docs/examples");
    if (!QFileInfo(examples).isDir())
        QSKIP("docs/examples/ does not exist (yet): no example sessions to ship");
    const QStringList sources = filesUnder(examples);
    for (const QString &file : sources) {
        const QString shipped = QStringLiteral("usr/share/mbscope/examples/") + file;
        QVERIFY2(m_files.contains(shipped), qPrintable(shipped + QStringLiteral(" is not in the package")));
    }
}

void TestPackage::iconsHaveTheirSize_data()
{
    QTest::addColumn<int>("size");
    for (const int size : kIconSizes)
        QTest::addRow("%dx%d", size, size) << size;
}

void TestPackage::iconsHaveTheirSize()
{
    QFETCH(int, size);
    const QString png = rootPath(QStringLiteral("usr/share/icons/hicolor/%1x%1/apps/mbscope.png").arg(size));
    QCOMPARE(pngSize(readAll(png)), QSize(size, size));
}

void TestPackage::manPageIsTheSource()
{
    const ProcessRun gunzip = runProcess(QStringLiteral("gzip"), {QStringLiteral("-dc"), rootPath(QStringLiteral("usr/share/man/man1/mbscope.1.gz"))});
    QVERIFY2(gunzip.succeeded(), gunzip.describe().constData());
    QVERIFY(gunzip.out == readAll(kSourceDir + QStringLiteral("/docs/mbscope.1")));
}

// Debian reads the package's version history from the changelog's first line.
void TestPackage::changelogNamesTheVersion()
{
    const ProcessRun gunzip = runProcess(QStringLiteral("gzip"), {QStringLiteral("-dc"), rootPath(QStringLiteral("usr/share/doc/mbscope/changelog.gz"))});
    QVERIFY2(gunzip.succeeded(), gunzip.describe().constData());
    const QString first = gunzip.outText().section(QLatin1Char('\n'), 0, 0);
    QVERIFY2(first.startsWith(QStringLiteral("mbscope (" MBSCOPE_VERSION ") ")),
             qPrintable(QStringLiteral("packaging/changelog starts '%1', not with version " MBSCOPE_VERSION).arg(first)));
}

void TestPackage::installedBinaryRuns_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("expected"); // each must appear in standard output
    QTest::newRow("--version") << QStringList{QStringLiteral("--version")}
                               << QStringList{QStringLiteral("mbscope " MBSCOPE_VERSION "\n")};
    QTest::newRow("decode RosRao request")
        << QStringList{QStringLiteral("decode"), QStringLiteral("01"), QStringLiteral("03"), QStringLiteral("00"),
                       QStringLiteral("79"), QStringLiteral("00"), QStringLiteral("16"), QStringLiteral("15"),
                       QStringLiteral("DD")}
        << QStringList{QStringLiteral("Read Holding Registers"), QStringLiteral("15 DD")};
    // simulate runs in mbscope-full, which the installed mbscope finds beside itself.
    QTest::newRow("simulate --list-profiles (compiled in)")
        << QStringList{QStringLiteral("simulate"), QStringLiteral("--list-profiles")}
        << QStringList{QStringLiteral("rosrao-gamma")};
}

// From the unpacked root, run in the temporary directory: the system's libraries, nothing of the
// build tree.
void TestPackage::installedBinaryRuns()
{
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, expected);
    const ProcessRun run = runProcess(rootPath(QStringLiteral("usr/bin/mbscope")), arguments, m_dir.path(), 60000);
    QVERIFY2(run.succeeded(), run.describe().constData());
    for (const QString &text : expected)
        QVERIFY2(run.outText().contains(text), qPrintable(QStringLiteral("'%1' not in:\n%2").arg(text, run.outText())));
}

void TestPackage::installedBinaryNamesNoBuildTree_data()
{
    QTest::addColumn<QString>("binary");
    QTest::newRow("mbscope") << QStringLiteral("usr/bin/mbscope");
    QTest::newRow("mbscope-full") << QStringLiteral("usr/bin/mbscope-full");
}

void TestPackage::installedBinaryNamesNoBuildTree()
{
    QFETCH(QString, binary);
    const QByteArray bytes = readAll(rootPath(binary));
    QVERIFY(!bytes.isEmpty());
    QVERIFY2(!bytes.contains(QByteArrayLiteral(MBSCOPE_BUILD_DIR)), "the installed binary names the build directory");
    const QString readelf = findProgram(QStringLiteral("readelf"));
    if (readelf.isEmpty())
        QSKIP("readelf is not installed (Debian: binutils): RPATH not checked");
    const ProcessRun dynamic = runProcess(readelf, {QStringLiteral("-d"), rootPath(binary)});
    QVERIFY2(dynamic.succeeded(), dynamic.describe().constData());
    QVERIFY2(!dynamic.outText().contains(QLatin1String("RPATH")) && !dynamic.outText().contains(QLatin1String("RUNPATH")),
             dynamic.out.constData());
}

void TestPackage::desktopFileValidates()
{
    const QString validator = findProgram(QStringLiteral("desktop-file-validate"));
    if (validator.isEmpty())
        QSKIP("desktop-file-validate is not installed (scripts/install-deps.sh --tests installs desktop-file-utils)");
    const ProcessRun run = runProcess(validator, {rootPath(QStringLiteral("usr/share/applications/%1.desktop").arg(kAppId))});
    QVERIFY2(run.succeeded(), run.describe().constData());
    QVERIFY2(run.out.trimmed().isEmpty() && run.err.trimmed().isEmpty(), run.describe().constData());
}

void TestPackage::metainfoValidates()
{
    const QString appstream = findProgram(QStringLiteral("appstreamcli"));
    if (appstream.isEmpty())
        QSKIP("appstreamcli is not installed (scripts/install-deps.sh --tests installs appstream)");
    const ProcessRun file = runProcess(appstream, {QStringLiteral("validate"), QStringLiteral("--no-net"), QStringLiteral("--pedantic"),
                                                   rootPath(QStringLiteral("usr/share/metainfo/%1.metainfo.xml").arg(kAppId))});
    QVERIFY2(file.succeeded(), file.describe().constData());
    // The installed tree as a software centre reads it: the metainfo's launchable names the
    // desktop file that is there, and the icon it names is installed.
    const ProcessRun tree = runProcess(appstream, {QStringLiteral("validate-tree"), QStringLiteral("--no-net"), m_root});
    QVERIFY2(tree.succeeded(), tree.describe().constData());
}

// dpkg itself, into an empty scratch root: the package installs (its libraries are the host's
// business, hence --force-depends), lists its files, and purging it leaves no file behind.
void TestPackage::dpkgInstallsAndRemovesCleanly()
{
    if (findProgram(QStringLiteral("dpkg")).isEmpty())
        QSKIP("dpkg is not installed");
    const QString root = m_dir.filePath(QStringLiteral("dpkgroot"));
    for (const char *dir : {"var/lib/dpkg/info", "var/lib/dpkg/updates", "var/lib/dpkg/triggers", "var/log"})
        QVERIFY(QDir().mkpath(root + QLatin1Char('/') + QLatin1String(dir)));
    QFile status(root + QStringLiteral("/var/lib/dpkg/status"));
    QVERIFY(status.open(QIODevice::WriteOnly));
    status.close();

    const QStringList dpkg{QStringLiteral("--root=") + root, QStringLiteral("--log=/dev/null"),
                           QStringLiteral("--force-depends"), QStringLiteral("--force-not-root")};
    const ProcessRun install = runProcess(QStringLiteral("dpkg"), dpkg + QStringList{QStringLiteral("--install"), m_deb});
    QVERIFY2(install.succeeded(), install.describe().constData());
    const ProcessRun listed = runProcess(QStringLiteral("dpkg"), dpkg + QStringList{QStringLiteral("--listfiles"), QStringLiteral("mbscope")});
    QVERIFY2(listed.succeeded() && listed.outText().contains(QLatin1String("/usr/bin/mbscope")), listed.describe().constData());
    const ProcessRun version = runProcess(root + QStringLiteral("/usr/bin/mbscope"), {QStringLiteral("--version")}, m_dir.path());
    QVERIFY2(version.succeeded(), version.describe().constData());

    const ProcessRun purge = runProcess(QStringLiteral("dpkg"), dpkg + QStringList{QStringLiteral("--purge"), QStringLiteral("mbscope")});
    QVERIFY2(purge.succeeded(), purge.describe().constData());
    QStringList left;
    for (const QString &file : filesUnder(root)) {
        if (!file.startsWith(QLatin1String("var/lib/dpkg/")))
            left.append(file);
    }
    QVERIFY2(left.isEmpty(), qPrintable(QStringLiteral("left after purge:\n") + left.join(QLatin1Char('\n'))));
    QVERIFY2(!QFileInfo::exists(root + QStringLiteral("/usr/share/mbscope")), "usr/share/mbscope is still there");
}

// `cmake --install` to an unusual prefix installs exactly the package's files (under the prefix
// instead of /usr), and the mbscope there runs.
void TestPackage::cmakeInstallsTheSameFilesToAnyPrefix()
{
    const QString prefix = m_dir.filePath(QStringLiteral("prefix with space/opt"));
    const ProcessRun install = runProcess(QStringLiteral(MBSCOPE_CMAKE),
                                          {QStringLiteral("--install"), QStringLiteral(MBSCOPE_BUILD_DIR),
                                           QStringLiteral("--prefix"), prefix},
                                          m_dir.path(), 120000);
    QVERIFY2(install.succeeded(), install.describe().constData());
    QStringList packaged;
    for (const QString &file : std::as_const(m_files)) {
        QVERIFY2(file.startsWith(QLatin1String("usr/")), qPrintable(file));
        packaged.append(file.mid(4));
    }
    QCOMPARE(filesUnder(prefix), packaged);
    const ProcessRun version = runProcess(prefix + QStringLiteral("/bin/mbscope"), {QStringLiteral("--version")}, m_dir.path());
    QVERIFY2(version.succeeded(), version.describe().constData());
}

QTEST_GUILESS_MAIN(TestPackage)
#include "tst_package.moc"
