// Tools > Export map (ExportMapDialog) offscreen: the window's Tools menu opens it; a profile is
// written as CSV (parsed back, a row per value), and with "Verify from" set, every value is read
// once from the embedded simulator first: a value over its declared max refuses the export naming
// the row and writes nothing; the same map served within its range is verified and written.

#include "discovery/exportmapdialog.h"
#include "guitestsupport.h"
#include "shell/mainwindow.h"
#include "shell/translationloader.h"
#include "sim/embeddedsimulator.h"

#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtGui/QAction>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>

using namespace mbscope;

namespace {

// The status line as a person reads it: the words of its rich text, its lines kept.
QString shown(const QLabel *status)
{
    QString text = status->text();
    text.replace(QLatin1String("<br>"), QLatin1String("\n"));
    text.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
    return text;
}

} // namespace

class TestExportMapDialog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void toolsMenuOpensIt();
    void verifyRefusesThenWrites();
    void badInputIsSaid();
    void accessKeysAreUnique_data();
    void accessKeysAreUnique();

private:
    QTemporaryDir m_dir;
    QString profile(double voltage);
};

// A meter whose voltage declares 180-260 V, served at the value given.
QString TestExportMapDialog::profile(double voltage)
{
    const QString path = m_dir.filePath(QStringLiteral("meter-%1.json").arg(voltage));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(QStringLiteral(R"({"name": "meter", "units": [{"id": 1, "tables": {"holding": [
        {"address": 0, "name": "Voltage", "type": "f32-cdab", "unit": "V", "kind": "measurement", "min": 180, "max": 260, "value": %1},
        {"address": 2, "name": "Energy", "type": "u32", "scale": 0.1, "unit": "kWh", "kind": "counter", "value": 1234.5}]}}]})")
                .arg(voltage)
                .toUtf8());
    return path;
}

void TestExportMapDialog::toolsMenuOpensIt()
{
    MainWindow window;
    auto *action = window.findChild<QAction *>(QStringLiteral("exportMapAction"));
    QVERIFY(action);
    action->trigger();
    auto *dialog = window.findChild<ExportMapDialog *>();
    QVERIFY(dialog && dialog->isVisible());
}

void TestExportMapDialog::verifyRefusesThenWrites()
{
    const QString high = profile(275.5);
    const QString normal = profile(231.2);
    EmbeddedSimulator sim;
    EmbeddedSimulator::Started started = sim.start(high, QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));

    ExportMapDialog dialog;
    dialog.show();
    const QString out = m_dir.filePath(QStringLiteral("map.csv"));
    dialog.findChild<QLineEdit *>(QStringLiteral("exportProfile"))->setText(normal);
    auto *format = dialog.findChild<QComboBox *>(QStringLiteral("exportFormat"));
    format->setCurrentIndex(format->findText(QStringLiteral("csv")));
    dialog.findChild<QLineEdit *>(QStringLiteral("exportVerify"))->setText(started.url.toString());
    dialog.findChild<QLineEdit *>(QStringLiteral("exportOutput"))->setText(out);
    auto *status = dialog.findChild<QLabel *>(QStringLiteral("exportStatus"));
    QSignalSpy exported(&dialog, &ExportMapDialog::exported);

    // The device answers 275.5 V: refused, the row named, nothing written.
    QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("exportRun")), Qt::LeftButton);
    QVERIFY(!exported.isEmpty() || exported.wait(10000));
    QCOMPARE(exported.takeFirst().first().toBool(), false);
    QVERIFY2(shown(status).startsWith(QLatin1String("Refused: 1 of 2")), qPrintable(shown(status)));
    QVERIFY2(shown(status).contains(QLatin1String("\nunit 1 holding 0 (Voltage): 275.5 is above max 260")), qPrintable(shown(status)));
    QVERIFY(!QFile::exists(out));

    // Served inside its range: verified and written.
    started = sim.start(normal, QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    dialog.findChild<QLineEdit *>(QStringLiteral("exportVerify"))->setText(started.url.toString());
    QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("exportRun")), Qt::LeftButton);
    QVERIFY(!exported.isEmpty() || exported.wait(10000));
    QCOMPARE(exported.takeFirst().first().toBool(), true);
    QVERIFY2(shown(status).startsWith(QLatin1String("Verified: 2 values")), qPrintable(shown(status)));
    QFile csv(out);
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 3); // the header and a row per value
    QVERIFY(lines.at(0).startsWith(QLatin1String("unit,table,function,address")));
    QVERIFY2(lines.at(1).contains(QLatin1String(",Voltage,")) && lines.at(1).contains(QLatin1String("f32")), qPrintable(lines.at(1)));
    QVERIFY2(lines.at(2).contains(QLatin1String(",Energy,")) && lines.at(2).contains(QLatin1String("0.1")), qPrintable(lines.at(2)));
}

void TestExportMapDialog::badInputIsSaid()
{
    ExportMapDialog dialog;
    auto *status = dialog.findChild<QLabel *>(QStringLiteral("exportStatus"));
    QVERIFY(!dialog.exportMap());
    QVERIFY(shown(status).startsWith(QLatin1String("Which profile?")));
    dialog.findChild<QLineEdit *>(QStringLiteral("exportProfile"))->setText(QStringLiteral("no-such-profile"));
    QVERIFY(!dialog.exportMap());
    QVERIFY2(shown(status).contains(QLatin1String("no-such-profile")), qPrintable(shown(status)));
    dialog.findChild<QLineEdit *>(QStringLiteral("exportProfile"))->setText(profile(230));
    dialog.findChild<QLineEdit *>(QStringLiteral("exportEndpoint"))->setText(QStringLiteral("tpc://x"));
    dialog.findChild<QLineEdit *>(QStringLiteral("exportOutput"))->setText(m_dir.filePath(QStringLiteral("x.csv")));
    QVERIFY(!dialog.exportMap());
    QVERIFY2(shown(status).startsWith(QLatin1String("Endpoint:")), qPrintable(shown(status)));
}

void TestExportMapDialog::accessKeysAreUnique_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("English") << QStringLiteral("en");
    QTest::newRow("Indonesian") << QStringLiteral("id");
}

void TestExportMapDialog::accessKeysAreUnique()
{
    QFETCH(QString, language);
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(*TranslationLoader::parse(language)));
    {
        ExportMapDialog dialog;
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        const QStringList clashes = guitest::mnemonicClashes(&dialog);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
    }
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
}

QTEST_MAIN(TestExportMapDialog)
#include "tst_exportmapdialog.moc"
