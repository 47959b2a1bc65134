// WatchDialog: a watch typed in full, read back as it was set, and every problem named where it is.
#include "watch/watchdialog.h"
#include "watch/watchpointtable.h"
#include "watch/watchruletable.h"

#include "compose/addressfield.h"

#include "guitestsupport.h"
#include "shell/translationloader.h"

#include <QtWidgets/QApplication>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

WatchDefinition sample()
{
    WatchDefinition watch;
    watch.name = QStringLiteral("detector");
    watch.target = QStringLiteral("rtu-tcp://127.0.0.1:4001");
    watch.unit = 1;
    watch.function = 3;
    watch.address = 0x79;
    watch.quantity = 22;
    watch.intervalMs = 500;
    WatchPoint counts;
    counts.address = 0x79;
    counts.name = QStringLiteral("counts");
    counts.format = RegisterFormat::parse(u"u32-abcd").format;
    counts.unit = QStringLiteral("cps");
    counts.scale = 0.5;
    counts.writable = true;
    WatchPoint voltage;
    voltage.address = 0x7d;
    voltage.name = QStringLiteral("hv");
    voltage.unit = QStringLiteral("V");
    voltage.offset = -10;
    watch.points = {counts, voltage};
    WatchRule rule;
    rule.point = QStringLiteral("counts");
    rule.condition = WatchRule::Condition::Outside;
    rule.low = 10;
    rule.high = 1000;
    rule.forPolls = 3;
    rule.severity = WatchSeverity::Alarm;
    rule.colour = QStringLiteral("#ff00ff");
    rule.message = QStringLiteral("counts out of range");
    watch.rules = {rule};
    return watch;
}

} // namespace

class TestWatchDialog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void readsBackWhatWasSet();
    void namesEveryProblem();
    void okIsRefusedWhileSomethingIsWrong();
    void enronHalvesTheQuantityLimit();
    void accessKeysAreUnique_data();
    void accessKeysAreUnique();
};

void TestWatchDialog::readsBackWhatWasSet()
{
    WatchDialog dialog;
    dialog.setWatch(sample());
    QStringList problems;
    const WatchDefinition read = dialog.watch(&problems);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    QCOMPARE(read, sample());
}

void TestWatchDialog::namesEveryProblem()
{
    WatchDialog dialog;
    dialog.setWatch(sample());
    dialog.setTakenNames({QStringLiteral("detector")});
    dialog.targetEdit()->setText(QStringLiteral("ftp://nowhere"));
    dialog.pointTable()->item(1, WatchPointTable::FormatColumn)->setText(QStringLiteral("f33"));
    dialog.pointTable()->addPoint(500);
    dialog.ruleTable()->item(0, WatchRuleTable::ColourColumn)->setText(QStringLiteral("purple"));
    QStringList problems;
    (void)dialog.watch(&problems);
    const QString all = problems.join(QLatin1Char('\n'));
    QVERIFY2(all.contains(QStringLiteral("another watch is called 'detector'")), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("Target:")), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("point 2:")) && all.contains(QStringLiteral("f33")), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("address 500 lies outside")), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("rule 1: colour 'purple'")), qPrintable(all));
}

void TestWatchDialog::okIsRefusedWhileSomethingIsWrong()
{
    WatchDialog dialog;
    dialog.setWatch(sample());
    dialog.nameEdit()->clear();
    dialog.show();
    dialog.accept();
    QVERIFY(dialog.isVisible());
    QVERIFY(dialog.findChild<QLabel *>(QStringLiteral("watchProblems"))->isVisible());
    dialog.nameEdit()->setText(QStringLiteral("ok now"));
    dialog.accept();
    QVERIFY(!dialog.isVisible());
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
}

void TestWatchDialog::enronHalvesTheQuantityLimit()
{
    WatchDialog dialog;
    dialog.functionBox()->setCurrentIndex(dialog.functionBox()->findData(3));
    QCOMPARE(dialog.quantitySpin()->maximum(), 125);
    dialog.enronBox()->setChecked(true);
    dialog.functionBox()->setCurrentIndex(dialog.functionBox()->findData(4));
    QCOMPARE(dialog.quantitySpin()->maximum(), 62);
    dialog.functionBox()->setCurrentIndex(dialog.functionBox()->findData(1));
    QVERIFY(!dialog.enronBox()->isEnabled());
    QCOMPARE(dialog.quantitySpin()->maximum(), 2000);
}

void TestWatchDialog::accessKeysAreUnique_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("English") << QStringLiteral("en");
    QTest::newRow("Indonesian") << QStringLiteral("id");
}

// Each Alt+letter of the dialog reaches one control, in both languages, on both tabs ("&Target"
// and "Poin&ts" both took T; in Indonesian T, U and N were each taken twice or three times).
void TestWatchDialog::accessKeysAreUnique()
{
    QFETCH(QString, language);
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(*TranslationLoader::parse(language)));
    {
        WatchDialog dialog;
        dialog.setWatch(sample());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto *tabs = dialog.findChild<QTabWidget *>();
        QVERIFY(tabs);
        for (int i = 0; i < tabs->count(); ++i) {
            tabs->setCurrentIndex(i);
            const QStringList clashes = guitest::mnemonicClashes(&dialog);
            QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
        }
    }
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
}

QTEST_MAIN(TestWatchDialog)
#include "tst_watchdialog.moc"
