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
#include <QtWidgets/QTableWidget>
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
    void ruleUsesTheThresholdsItShows();
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

// Issue 26 item 4: "above" compared with High and ignored Low, so a rule that read "above, Low 100"
// fired on everything above High's 0. Each condition shows only the thresholds it uses (the others
// empty and not editable), a number left in one it does not use is refused, and so are thresholds
// that make no sense for the point, each naming the rule and the column.
void TestWatchDialog::ruleUsesTheThresholdsItShows()
{
    WatchDialog dialog;
    dialog.setWatch(sample());
    WatchRuleTable *table = dialog.ruleTable();
    auto *condition = qobject_cast<QComboBox *>(table->cellWidget(0, WatchRuleTable::ConditionColumn));
    QVERIFY(condition);
    QTableWidgetItem *low = table->item(0, WatchRuleTable::LowColumn);
    QTableWidgetItem *high = table->item(0, WatchRuleTable::HighColumn);
    const auto problemsNow = [&dialog] {
        QStringList problems;
        (void)dialog.watch(&problems);
        return problems.join(QLatin1Char('\n'));
    };

    // outside 10..1000 made "above": High kept, Low emptied and closed.
    condition->setCurrentIndex(condition->findData(int(WatchRule::Condition::Above)));
    QCOMPARE(low->text(), QString());
    QVERIFY(!(low->flags() & Qt::ItemIsEditable));
    QVERIFY(high->flags() & Qt::ItemIsEditable);
    QCOMPARE(high->text(), QStringLiteral("1000"));
    QStringList problems;
    WatchDefinition read = dialog.watch(&problems);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    QCOMPARE(read.rules.value(0).condition, WatchRule::Condition::Above);
    QCOMPARE(read.rules.value(0).high, 1000.0);

    // A number in the column "above" does not use is refused, never ignored.
    low->setText(QStringLiteral("100"));
    QVERIFY2(problemsNow().contains(QStringLiteral("rule 1: Low: 'above' does not use Low")), qPrintable(problemsNow()));

    // "below" uses Low alone: High's number moves to Low when Low is empty.
    low->setText(QString());
    condition->setCurrentIndex(condition->findData(int(WatchRule::Condition::Below)));
    QCOMPARE(low->text(), QStringLiteral("1000"));
    QCOMPARE(high->text(), QString());
    QVERIFY(!(high->flags() & Qt::ItemIsEditable));
    low->setText(QString());
    QVERIFY2(problemsNow().contains(QStringLiteral("rule 1: Low: 'below' needs a number here")), qPrintable(problemsNow()));

    // A range whose low is above its high.
    condition->setCurrentIndex(condition->findData(int(WatchRule::Condition::Outside)));
    QVERIFY(low->flags() & Qt::ItemIsEditable);
    QVERIFY(high->flags() & Qt::ItemIsEditable);
    low->setText(QStringLiteral("2000"));
    high->setText(QStringLiteral("1000"));
    QVERIFY2(problemsNow().contains(QStringLiteral("rule 1: Low: low 2000 is above high 1000")), qPrintable(problemsNow()));

    // A mask wider than the point (hv is one 16-bit register).
    table->item(0, WatchRuleTable::PointColumn)->setText(QStringLiteral("hv"));
    condition->setCurrentIndex(condition->findData(int(WatchRule::Condition::Bits)));
    low->setText(QStringLiteral("65536"));
    QVERIFY2(problemsNow().contains(QStringLiteral("rule 1: Low: mask 0x10000 has bits beyond the 16 bit(s) of 'hv'")),
             qPrintable(problemsNow()));
    // A point the watch does not have.
    table->item(0, WatchRuleTable::PointColumn)->setText(QStringLiteral("volts"));
    QVERIFY2(problemsNow().contains(QStringLiteral("rule 1: Point: 'volts' is neither")), qPrintable(problemsNow()));

    // A rule read from a session shows only what it uses.
    WatchDefinition watch = sample();
    watch.rules[0].condition = WatchRule::Condition::Above;
    watch.rules[0].low = 0;
    watch.rules[0].high = 80;
    dialog.setWatch(watch);
    QCOMPARE(dialog.ruleTable()->item(0, WatchRuleTable::LowColumn)->text(), QString());
    QCOMPARE(dialog.ruleTable()->item(0, WatchRuleTable::HighColumn)->text(), QStringLiteral("80"));
    problems.clear();
    QCOMPARE(dialog.watch(&problems).rules, watch.rules);
    QVERIFY(problems.isEmpty());
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
