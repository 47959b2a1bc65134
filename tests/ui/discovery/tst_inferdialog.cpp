// Map unit > Infer types (InferDialog) offscreen against the embedded simulator serving the
// em340-meter profile (32-bit integers low word first at x0.1 and x0.001): the map scan's blocks
// sampled and inferred through the buttons, the draft shown a row per value with every reading
// side by side under its live value, a row corrected by choosing another reading with the
// keyboard, a name typed, a row confirmed, Read again, and the profile saved as the person left it
// (loaded back, served by a second simulator).

#include "discovery/inferdialog.h"
#include "discovery/inferdraftmodel.h"
#include "discovery/mapscandialog.h"
#include "guitestsupport.h"
#include "profile/profileloader.h"
#include "shell/translationloader.h"
#include "sim/embeddedsimulator.h"

#include <QtCore/QTemporaryDir>
#include <QtTest/QAbstractItemModelTester>
#include <QtCore/QThread>
#include <QtCore/QTimer>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>

using namespace mbscope;

class TestInferDialog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void inferConfirmAndSave();
    void accessKeysAreUnique_data();
    void accessKeysAreUnique();

private:
    EmbeddedSimulator m_sim;
    LinkUrl m_url;
};

void TestInferDialog::initTestCase()
{
    const EmbeddedSimulator::Started started = m_sim.start(QStringLiteral("em340-meter"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    m_url = started.url;
}

static int rowAt(const InferDraftModel *model, int address)
{
    for (int r = 0; r < model->rowCount(); ++r) {
        if (model->index(r, InferDraftModel::AddressColumn).data().toString().section(QLatin1Char('-'), 0, 0).toInt() == address)
            return r;
    }
    return -1;
}

// The reading column whose label (the cell's first line) is label; -1 when none.
static int readingColumn(const InferDraftModel *model, int row, const QString &label)
{
    for (int c = InferDraftModel::FirstReadingColumn; c < InferDraftModel::kColumns; ++c) {
        if (model->index(row, c).data().toString().section(QLatin1Char('\n'), 0, 0) == label)
            return c;
    }
    return -1;
}

static QString valueUnder(const InferDraftModel *model, int row, int column)
{
    return model->index(row, column).data().toString().section(QLatin1Char('\n'), 1);
}

void TestInferDialog::inferConfirmAndSave()
{
    MapScanDialog map;
    map.setTarget(m_url, 1);
    map.findChild<QSpinBox *>(QStringLiteral("mapFirstAddress"))->setValue(0);
    map.findChild<QSpinBox *>(QStringLiteral("mapLastAddress"))->setValue(99);
    for (const int table : {1, 2, 4})
        map.findChild<QCheckBox *>(QStringLiteral("mapTable%1").arg(table))->setChecked(false);
    map.findChild<QCheckBox *>(QStringLiteral("mapOptional"))->setChecked(false);
    map.show();
    auto *inferButton = map.findChild<QPushButton *>(QStringLiteral("mapInfer"));
    QVERIFY(!inferButton->isEnabled()); // no map yet
    QSignalSpy scanned(&map, &MapScanDialog::scanFinished);
    QTest::mouseClick(map.findChild<QPushButton *>(QStringLiteral("mapStart")), Qt::LeftButton);
    QVERIFY(!scanned.isEmpty() || scanned.wait(30000));
    QVERIFY(inferButton->isEnabled());

    QTest::mouseClick(inferButton, Qt::LeftButton);
    auto *dialog = map.findChild<InferDialog *>();
    QVERIFY(dialog && dialog->isVisible());
    auto *model = dialog->model();
    QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(!dialog->findChild<QPushButton *>(QStringLiteral("inferSave"))->isEnabled());
    dialog->findChild<QSpinBox *>(QStringLiteral("inferSamples"))->setValue(16);
    dialog->findChild<QSpinBox *>(QStringLiteral("inferInterval"))->setValue(300);
    QSignalSpy inferred(dialog, &InferDialog::inferred);
    // The sampling runs in the job's thread: the window's own loop is never nested meanwhile (a
    // 2 ms timer on it sees loop level 1 throughout; sampling on it made that 2).
    int deepest = 0;
    QTimer probe;
    connect(&probe, &QTimer::timeout, this, [&deepest] { deepest = qMax(deepest, QThread::currentThread()->loopLevel()); });
    probe.start(2);
    // Clicked from inside the test's event loop, as a user clicks inside the window's.
    QTimer::singleShot(0, dialog, [dialog] { QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("inferStart")), Qt::LeftButton); });
    QVERIFY(inferred.wait(60000));
    probe.stop();
    QCOMPARE(deepest, 1);
    // The profile's 31 values, one row each (an energy counter that did not move while sampled
    // may be two still 16-bit registers).
    QVERIFY2(model->rowCount() >= 31 && model->rowCount() <= 33, qPrintable(QString::number(model->rowCount())));
    QVERIFY(dialog->findChild<QPushButton *>(QStringLiteral("inferSave"))->isEnabled());

    // V L1-N: 32 bits low word first, x0.1, volts; the readings side by side, each with its value.
    const int voltage = rowAt(model, 0);
    QVERIFY(voltage >= 0);
    QCOMPARE(model->index(voltage, InferDraftModel::UnitColumn).data().toString(), QStringLiteral("V"));
    const QString guess = model->index(voltage, InferDraftModel::FirstReadingColumn).data().toString();
    QVERIFY2(guess.startsWith(QLatin1String("u32-cdab x0.1")) || guess.startsWith(QLatin1String("i32-cdab x0.1")), qPrintable(guess));
    const double volts = valueUnder(model, voltage, InferDraftModel::FirstReadingColumn).toDouble();
    QVERIFY2(volts >= 226 && volts <= 235, qPrintable(guess));
    const int asFloat = readingColumn(model, voltage, QStringLiteral("f32-cdab"));
    const int bigEndian = readingColumn(model, voltage, QStringLiteral("u32-abcd x0.1"));
    QVERIFY(asFloat > 0 && bigEndian > 0);
    // Read ABCD the words give a number a person does not recognise as a voltage.
    QVERIFY(valueUnder(model, voltage, bigEndian).toDouble() > 1e5);
    // The current, by the relation S = V x A: x0.001, amperes.
    const int current = rowAt(model, 12);
    QCOMPARE(model->index(current, InferDraftModel::UnitColumn).data().toString(), QStringLiteral("A"));
    QVERIFY(model->index(current, InferDraftModel::FirstReadingColumn).data().toString().contains(QLatin1String("x0.001")));
    QVERIFY(model->index(current, InferDraftModel::NameColumn).data(Qt::ToolTipRole).toString().contains(QLatin1String("V(")));

    // Phase sequence (50), still at 0: the person chooses the other 16-bit integer than the guess
    // with the keyboard (Space on the cell).
    auto *table = dialog->findChild<QTableView *>(QStringLiteral("inferTable"));
    const int sequence = rowAt(model, 50);
    QVERIFY(sequence >= 0);
    const bool guessedSigned = model->index(sequence, InferDraftModel::FirstReadingColumn).data().toString().startsWith(QLatin1String("i16"));
    const QString other = guessedSigned ? QStringLiteral("u16") : QStringLiteral("i16");
    const int asOther = readingColumn(model, sequence, other);
    QVERIFY(asOther > InferDraftModel::FirstReadingColumn);
    table->setCurrentIndex(model->index(sequence, asOther));
    QTest::keyClick(table, Qt::Key_Space);
    QCOMPARE(model->chosenReading(sequence), asOther - InferDraftModel::FirstReadingColumn);
    QCOMPARE(model->confirmedCount(), 1);
    // A name typed for the voltage, and its guess confirmed as it is.
    table->setCurrentIndex(model->index(voltage, InferDraftModel::NameColumn));
    table->edit(table->currentIndex());
    auto *editor = table->findChild<QLineEdit *>();
    QVERIFY(editor);
    QTest::keyClicks(editor, QStringLiteral("V L1-N"));
    QTest::keyClick(editor, Qt::Key_Return);
    // The delegate commits the editor's text after the key (a queued call).
    QTRY_COMPARE(model->index(voltage, InferDraftModel::NameColumn).data().toString(), QStringLiteral("V L1-N"));
    table->setCurrentIndex(model->index(voltage, InferDraftModel::ConfirmedColumn));
    QTest::keyClick(table, Qt::Key_Space);
    QCOMPARE(model->confirmedCount(), 2);
    QVERIFY(dialog->findChild<QLabel *>(QStringLiteral("inferStatus"))->text().startsWith(QStringLiteral("2 of %1").arg(model->rowCount())));

    // Read again: the values under the readings come from a new read.
    QSignalSpy read(dialog, &InferDialog::readDone);
    QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("inferReadAgain")), Qt::LeftButton);
    QVERIFY(!read.isEmpty() || read.wait(10000));
    const double again = valueUnder(model, voltage, InferDraftModel::FirstReadingColumn).toDouble();
    QVERIFY(again >= 226 && again <= 235);

    if (const QString shot = qEnvironmentVariable("MBSCOPE_INFER_SCREENSHOT"); !shot.isEmpty())
        dialog->grab().save(shot);

    // Saved as the person left it: a profile the simulator serves.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("em340-confirmed.json"));
    QVERIFY(dialog->saveProfile(path));
    const ProfileLoadResult loaded = ProfileLoader::loadFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
    const QList<TableEntry> &entries = loaded.profile.units.constFirst().entries;
    bool sawVoltage = false;
    bool sawSequence = false;
    bool sawGuess = false;
    for (const TableEntry &e : entries) {
        if (e.address == 0) {
            sawVoltage = true;
            QCOMPARE(e.name, QStringLiteral("V L1-N"));
            QVERIFY(e.description.startsWith(QLatin1String("confirmed")));
            QCOMPARE(e.scale, 0.1);
        } else if (e.address == 50) {
            sawSequence = true;
            QCOMPARE(e.format.name(), other);
            QVERIFY(e.description.startsWith(QLatin1String("confirmed")));
        } else {
            sawGuess = sawGuess || e.description.startsWith(QLatin1String("guess"));
        }
    }
    QVERIFY(sawVoltage && sawSequence && sawGuess);
    EmbeddedSimulator clone;
    const EmbeddedSimulator::Started started = clone.start(path, QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
}

void TestInferDialog::accessKeysAreUnique_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("English") << QStringLiteral("en");
    QTest::newRow("Indonesian") << QStringLiteral("id");
}

// Each Alt+letter of the dialog reaches one control, in both languages.
void TestInferDialog::accessKeysAreUnique()
{
    QFETCH(QString, language);
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(*TranslationLoader::parse(language)));
    {
        InferDialog dialog;
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        const QStringList clashes = guitest::mnemonicClashes(&dialog);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
    }
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
}

QTEST_MAIN(TestInferDialog)
#include "tst_inferdialog.moc"
