// Theme: light and dark applied to the whole application, System back to the desktop's look;
// the choice kept in QSettings and offered in Preferences; rule colours readable in both.
#include "common/theme.h"
#include "shell/preferencesdialog.h"
#include "watch/rulepalette.h"

#include "guitestsupport.h"

#include <QtCore/QSettings>
#include <QtWidgets/QApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QStyle>
#include <QtWidgets/QTableWidget>
#include <QtTest/QtTest>

using namespace mbscope;

class TestTheme : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanup();
    void parsesNames();
    void darkAndLightChangeTheWholeApplication();
    void systemPutsBackThePlatformLook();
    void ruleColoursAreReadableInBothThemes_data();
    void ruleColoursAreReadableInBothThemes();
    void preferencesStoresAndAppliesTheChoice();

private:
    QPalette m_platformPalette;
    QString m_platformStyle;
};

void TestTheme::initTestCase()
{
    guitest::isolateSettings();
    QSettings().remove(QLatin1String(Theme::kSettingsKey));
    m_platformPalette = QApplication::palette();
    m_platformStyle = QApplication::style()->name();
}

void TestTheme::cleanup()
{
    Theme::apply(Theme::Choice::System);
    QSettings().remove(QLatin1String(Theme::kSettingsKey));
}

void TestTheme::parsesNames()
{
    QCOMPARE(Theme::parse(QStringLiteral("Dark")), Theme::Choice::Dark);
    QCOMPARE(Theme::parse(QStringLiteral(" light ")), Theme::Choice::Light);
    QCOMPARE(Theme::parse(QStringLiteral("system")), Theme::Choice::System);
    QVERIFY(!Theme::parse(QStringLiteral("blue")));
    for (Theme::Choice choice : {Theme::Choice::System, Theme::Choice::Light, Theme::Choice::Dark})
        QCOMPARE(Theme::parse(Theme::key(choice)), choice);
    QCOMPARE(Theme::storedChoice(), Theme::Choice::System); // nothing stored: the desktop's
}

void TestTheme::darkAndLightChangeTheWholeApplication()
{
    QTableWidget table(2, 2);
    table.show();
    QVERIFY(QTest::qWaitForWindowExposed(&table));
    Theme::apply(Theme::Choice::Dark);
    QCoreApplication::processEvents();
    QCOMPARE(Theme::current(), Theme::Choice::Dark);
    QVERIFY(Theme::isDark());
    QVERIFY(QApplication::palette().color(QPalette::Base).lightness() < 60);
    QVERIFY(QApplication::palette().color(QPalette::Text).lightness() > 200);
    // Widgets already shown take the new palette.
    QVERIFY(table.palette().color(QPalette::Base).lightness() < 60);
    QCOMPARE(QApplication::style()->name().toLower(), QStringLiteral("fusion"));
    QVERIFY(RulePalette::contrast(QApplication::palette().color(QPalette::Text), QApplication::palette().color(QPalette::Base)) >= 7);
    QVERIFY(guitest::saveShot(&table, QStringLiteral("theme-dark-table.png")));

    Theme::apply(Theme::Choice::Light);
    QCoreApplication::processEvents();
    QVERIFY(!Theme::isDark());
    QVERIFY(table.palette().color(QPalette::Base).lightness() > 200);
    QVERIFY(RulePalette::contrast(QApplication::palette().color(QPalette::Text), QApplication::palette().color(QPalette::Base)) >= 7);
}

void TestTheme::systemPutsBackThePlatformLook()
{
    Theme::apply(Theme::Choice::Dark);
    Theme::apply(Theme::Choice::System);
    QCOMPARE(QApplication::style()->name(), m_platformStyle);
    QCOMPARE(QApplication::palette().color(QPalette::Base), m_platformPalette.color(QPalette::Base));
    QCOMPARE(QApplication::palette().color(QPalette::Text), m_platformPalette.color(QPalette::Text));
}

void TestTheme::ruleColoursAreReadableInBothThemes_data()
{
    QTest::addColumn<int>("theme");
    QTest::addColumn<int>("severity");
    QTest::addColumn<QString>("colour");
    for (Theme::Choice theme : {Theme::Choice::Light, Theme::Choice::Dark}) {
        for (WatchSeverity severity : {WatchSeverity::Info, WatchSeverity::Warning, WatchSeverity::Alarm}) {
            for (const char *colour : {"", "#ff0000", "#ffff00", "#00ff00", "#0000ff", "#000000", "#ffffff"}) {
                QTest::addRow("%s %s %s", qPrintable(Theme::key(theme)), qPrintable(RulePalette::severityName(severity)),
                              colour[0] ? colour : "default")
                    << int(theme) << int(severity) << QString::fromLatin1(colour);
            }
        }
    }
}

void TestTheme::ruleColoursAreReadableInBothThemes()
{
    QFETCH(int, theme);
    QFETCH(int, severity);
    QFETCH(QString, colour);
    Theme::apply(Theme::Choice(theme));
    const QColor back = RulePalette::background(WatchSeverity(severity), colour);
    const QColor text = RulePalette::foreground(WatchSeverity(severity), colour);
    const double ratio = RulePalette::contrast(text, back);
    QVERIFY2(ratio >= RulePalette::kMinimumContrast, qPrintable(QStringLiteral("%1 on %2: %3:1").arg(text.name(), back.name()).arg(ratio)));
    // The tint is visible: a rule's cell differs from an ordinary one.
    QVERIFY(RulePalette::contrast(back, QApplication::palette().color(QPalette::Base)) >= 1.1);
}

void TestTheme::preferencesStoresAndAppliesTheChoice()
{
    PreferencesDialog dialog;
    QComboBox *box = dialog.themeBox();
    QCOMPARE(dialog.themeChoice(), Theme::Choice::System);
    box->setCurrentIndex(box->findData(int(Theme::Choice::Dark)));
    dialog.apply();
    QCOMPARE(Theme::storedChoice(), Theme::Choice::Dark);
    QVERIFY(Theme::isDark());
    PreferencesDialog again;
    QCOMPARE(again.themeChoice(), Theme::Choice::Dark);
    again.themeBox()->setCurrentIndex(again.themeBox()->findData(int(Theme::Choice::Light)));
    again.apply();
    QCOMPARE(Theme::storedChoice(), Theme::Choice::Light);
    QVERIFY(!Theme::isDark());
}

QTEST_MAIN(TestTheme)
#include "tst_theme.moc"
