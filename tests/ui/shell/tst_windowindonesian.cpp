// The window in Bahasa Indonesia: built under the Indonesian translation, its menus, actions, dock
// titles, tabs, labels, buttons, group boxes, combo boxes, placeholders, headers and tooltips show
// no English left, and each menu's &-accelerators are unique. Screenshots of the window and of
// each dock, in Indonesian and in English, are written to the test output (guitestsupport.h).
#include "guitestsupport.h"

#include "decode/fieldtreemodel.h"
#include "shell/mainwindow.h"
#include "shell/preferencesdialog.h"
#include "compose/requestcomposer.h"
#include "decode/transactionview.h"
#include "shell/translationloader.h"

#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
#include <QtCore/QSettings>
#include <QtCore/QXmlStreamReader>
#include <QtGui/QAction>
#include <QtGui/QTextDocumentFragment>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QAbstractButton>
#include <QtWidgets/QAbstractItemView>
#include <QtWidgets/QApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QMenu>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTabBar>
#include <QtWidgets/QTabWidget>

#include <algorithm>

using namespace mbscope;

namespace {

// Texts that are the same in both languages on purpose, each with its reason. A visible text that
// is an English source string of mbscope_id.ts fails unless it is here.
const QSet<QString> &keptEnglish()
{
    static const QSet<QString> kept = {
        // Protocol names and framings: what Indonesian labs and datasheets call them.
        QStringLiteral("Modbus TCP"), QStringLiteral("Modbus UDP"), QStringLiteral("Modbus TCP Security (TLS)"),
        QStringLiteral("RTU"), QStringLiteral("ASCII"), QStringLiteral("RTU (serial)"), QStringLiteral("ASCII (serial)"),
        QStringLiteral("TCP (MBAP)"), QStringLiteral("UDP (MBAP)"), QStringLiteral("CRC"), QStringLiteral("LRC"),
        // Modbus data model terms the issue keeps English (register, coil, holding register...).
        QStringLiteral("Register"), QStringLiteral("Coil"), QStringLiteral("coil"), QStringLiteral("Discrete input"),
        QStringLiteral("discrete input"), QStringLiteral("holding register"), QStringLiteral("input register"),
        QStringLiteral("ON"), QStringLiteral("OFF"), QStringLiteral("bit"), QStringLiteral("broadcast"),
        // Engineering words Indonesian engineers write in English (and spelled the same in Indonesian:
        // data, status, format, normal, valid, unit, port, link).
        QStringLiteral("Hex"), QStringLiteral("Offset"), QStringLiteral("Frame"),
        QStringLiteral("Framing"), QStringLiteral("Data"), QStringLiteral("Status"), QStringLiteral("Output"),
        QStringLiteral("Event"), QStringLiteral("Record"), QStringLiteral("Polling"),
        // Not Replay, Sweep or exception: try-out 8 (item 16) read the Analysis dock's "Exception",
        // "Sweep" and "Replay" as left untranslated; they are putar ulang, sapuan, pengecualian.
        QStringLiteral("Endpoint"), QStringLiteral("Link"), QStringLiteral("Host"),
        QStringLiteral("Port"), QStringLiteral("Baud"), QStringLiteral("Unit"), QStringLiteral("Format"),
        QStringLiteral("Valid"), QStringLiteral("(valid)"), QStringLiteral("normal"), QStringLiteral("ok"), QStringLiteral("Ok"),
        QStringLiteral("OK"), QStringLiteral("ERROR"), QStringLiteral("ms"), QStringLiteral("No"),
        QStringLiteral("big endian"), QStringLiteral("little endian"), QStringLiteral("/dev/ttyUSB0"),
        // Abbreviations: certificate authority.
        QStringLiteral("CA"),
        // Object names of Read Device Identification, as the specification spells them.
        QStringLiteral("VendorName"), QStringLiteral("ProductCode"), QStringLiteral("MajorMinorRevision"),
        QStringLiteral("VendorUrl"), QStringLiteral("ProductName"), QStringLiteral("ModelName"),
        QStringLiteral("UserApplicationName"),
    };
    return kept;
}

// Words written the same in both languages (interval, median, simulator) or kept English by the
// rules above: a source text made only of these and numbers needs no other words.
bool onlyKeptWords(const QString &text)
{
    static const QSet<QString> words = [] {
        QSet<QString> w = {QStringLiteral("interval"), QStringLiteral("median"), QStringLiteral("simulator"),
                           QStringLiteral("min"), QStringLiteral("p90"), QStringLiteral("p95"), QStringLiteral("p99"),
                           QStringLiteral("s")};
        for (const QString &kept : keptEnglish()) {
            for (const QString &word : kept.toLower().split(QRegularExpression(QStringLiteral("[^a-z0-9]+")), Qt::SkipEmptyParts))
                w.insert(word);
        }
        return w;
    }();
    const QStringList parts = text.toLower().split(QRegularExpression(QStringLiteral("[^a-z0-9]+")), Qt::SkipEmptyParts);
    return std::all_of(parts.cbegin(), parts.cend(), [](const QString &p) {
        return words.contains(p) || p.front().isDigit();
    });
}

// Words of English sentences that Indonesian never uses: a text holding one was not translated
// (it may not even be marked for translation). Lower case only: upper-case AND/OR/NOT are mask
// operators.
const QRegularExpression &englishWords()
{
    static const QRegularExpression re(QStringLiteral(
        "\\b(the|and|of|to|is|are|was|with|from|for|this|that|not|or|by|you|your|its|be|when|after|before|"
        "first|choose|press|type|send|show|none|only|then|than|into|has|have|yet|any|every|which|what|"
        "where|there|here|will|can|cannot|should|must|would|all|each|new|open|save|read|write)\\b"));
    return re;
}

// The text a user sees: no accelerator marks, no shortcut after a tab, no trailing colon or dots.
QString normalized(QString text)
{
    text = text.section(QLatin1Char('\t'), 0, 0);
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QStringLiteral("\x01"), QStringLiteral("&"));
    text = text.trimmed();
    while (text.endsWith(QLatin1Char(':')) || text.endsWith(QChar(0x2026)) || text.endsWith(QLatin1Char('.')))
        text.chop(1);
    return text.trimmed();
}

// The English source strings of mbscope_id.ts, normalised.
QSet<QString> englishSources(QString *error)
{
    QSet<QString> sources;
    QFile file(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/translations/mbscope_id.ts"));
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.fileName() + QStringLiteral(": ") + file.errorString();
        return sources;
    }
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() == QXmlStreamReader::StartElement && xml.name() == QLatin1String("source"))
            sources.insert(normalized(xml.readElementText()));
    }
    return sources;
}

struct VisibleText {
    QString where; // "QLabel 'connectionBar/...' text"
    QString text;
};

QString pathOf(const QObject *o)
{
    QStringList parts;
    for (; o; o = o->parent())
        parts.prepend(o->objectName().isEmpty() ? QString::fromLatin1(o->metaObject()->className()) : o->objectName());
    return parts.join(QLatin1Char('/'));
}

void addText(QList<VisibleText> &out, const QString &where, const QString &text)
{
    const QString plain = Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText() : text;
    if (!plain.trimmed().isEmpty())
        out.append({where, plain});
}

void collectActions(QList<VisibleText> &out, const QString &where, const QList<QAction *> &actions)
{
    for (QAction *a : actions) {
        if (a->isSeparator())
            continue;
        addText(out, where + QStringLiteral(" action"), a->text());
        if (a->toolTip() != QString(a->text()).remove(QLatin1Char('&')))
            addText(out, where + QStringLiteral(" action '") + a->text() + QStringLiteral("' tooltip"), a->toolTip());
        addText(out, where + QStringLiteral(" action '") + a->text() + QStringLiteral("' status tip"), a->statusTip());
        if (QMenu *sub = a->menu()) {
            addText(out, where + QStringLiteral(" menu"), sub->title());
            collectActions(out, where + QStringLiteral(" > ") + normalized(a->text()), sub->actions());
        }
    }
}

void collectModelHeaders(QList<VisibleText> &out, const QString &where, const QAbstractItemModel *model)
{
    for (int c = 0; c < model->columnCount(); ++c) {
        addText(out, where + QStringLiteral(" header %1").arg(c), model->headerData(c, Qt::Horizontal).toString());
        addText(out, where + QStringLiteral(" header %1 tooltip").arg(c),
                model->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString());
    }
}

// Every text the widget and its children show, or show on hovering.
QList<VisibleText> visibleTexts(QWidget *root)
{
    QList<VisibleText> out;
    QList<QWidget *> widgets = root->findChildren<QWidget *>();
    widgets.prepend(root);
    for (QWidget *w : std::as_const(widgets)) {
        const QString where = pathOf(w);
        addText(out, where + QStringLiteral(" tooltip"), w->toolTip());
        addText(out, where + QStringLiteral(" status tip"), w->statusTip());
        if (w->isWindow())
            addText(out, where + QStringLiteral(" window title"), w->windowTitle());
        collectActions(out, where, w->actions());
        if (auto *label = qobject_cast<QLabel *>(w))
            addText(out, where + QStringLiteral(" text"), label->text());
        else if (auto *button = qobject_cast<QAbstractButton *>(w))
            addText(out, where + QStringLiteral(" text"), button->text());
        else if (auto *box = qobject_cast<QGroupBox *>(w))
            addText(out, where + QStringLiteral(" title"), box->title());
        else if (auto *dock = qobject_cast<QDockWidget *>(w))
            addText(out, where + QStringLiteral(" title"), dock->windowTitle());
        else if (auto *edit = qobject_cast<QLineEdit *>(w))
            addText(out, where + QStringLiteral(" placeholder"), edit->placeholderText());
        else if (auto *plain = qobject_cast<QPlainTextEdit *>(w))
            addText(out, where + QStringLiteral(" placeholder"), plain->placeholderText());
        else if (auto *spin = qobject_cast<QSpinBox *>(w)) {
            addText(out, where + QStringLiteral(" suffix"), spin->suffix());
            addText(out, where + QStringLiteral(" special value"), spin->specialValueText());
        } else if (auto *combo = qobject_cast<QComboBox *>(w)) {
            for (int i = 0; i < combo->count(); ++i)
                addText(out, where + QStringLiteral(" item %1").arg(i), combo->itemText(i));
        } else if (auto *bar = qobject_cast<QTabBar *>(w)) {
            for (int i = 0; i < bar->count(); ++i) {
                addText(out, where + QStringLiteral(" tab %1").arg(i), bar->tabText(i));
                addText(out, where + QStringLiteral(" tab %1 tooltip").arg(i), bar->tabToolTip(i));
            }
        } else if (auto *view = qobject_cast<QAbstractItemView *>(w)) {
            if (QAbstractItemModel *model = view->model())
                collectModelHeaders(out, where, model);
        } else if (auto *menuBar = qobject_cast<QMenuBar *>(w)) {
            collectActions(out, QStringLiteral("menu bar"), menuBar->actions());
        }
    }
    return out;
}

// The field names and meanings the answer's trees show (translated from the core's English).
QList<VisibleText> fieldTreeTexts(QWidget *root)
{
    QList<VisibleText> out;
    for (QAbstractItemView *view : root->findChildren<QAbstractItemView *>()) {
        auto *model = qobject_cast<FieldTreeModel *>(view->model());
        if (!model)
            continue;
        QList<QModelIndex> pending{QModelIndex()};
        while (!pending.isEmpty()) {
            const QModelIndex parent = pending.takeFirst();
            for (int r = 0; r < model->rowCount(parent); ++r) {
                const QModelIndex name = model->index(r, FieldTreeModel::FieldColumn, parent);
                addText(out, pathOf(view) + QStringLiteral(" field"), name.data().toString().remove(QRegularExpression(QStringLiteral(" \\d+$"))));
                QString value = model->index(r, FieldTreeModel::ValueColumn, parent).data().toString();
                // The meaning after the number: "0x03 Baca Holding Register" -> "Baca Holding Register".
                addText(out, pathOf(view) + QStringLiteral(" meaning"),
                        value.remove(QRegularExpression(QStringLiteral("^[0-9A-Fa-fx ()/]+(?= |$)"))));
                pending.append(name);
            }
        }
    }
    return out;
}

// What in texts is still English: a source string of the translation, or English sentence words.
QStringList englishLeft(const QList<VisibleText> &texts, const QSet<QString> &sources)
{
    QStringList problems;
    QSet<QString> reported;
    static const QRegularExpression letters(QStringLiteral("[A-Za-z]{2}"));
    for (const VisibleText &t : texts) {
        const QString n = normalized(t.text);
        if (!n.contains(letters))
            continue; // "#", "…", numbers: no language
        QString why;
        if (sources.contains(n) && !keptEnglish().contains(n) && !onlyKeptWords(n)) {
            why = QStringLiteral("is the English source text");
        } else {
            // URLs, paths and command lines are not language.
            QString words = n;
            words.remove(QRegularExpression(QStringLiteral("\\S*(://|/|--)\\S*")));
            const QRegularExpressionMatch m = englishWords().match(words);
            if (m.hasMatch())
                why = QStringLiteral("has the English word '%1'").arg(m.captured(1));
        }
        if (!why.isEmpty() && !reported.contains(t.where + n)) {
            reported.insert(t.where + n);
            problems << QStringLiteral("%1: \"%2\" %3").arg(t.where, t.text, why);
        }
    }
    return problems;
}

} // namespace

class TestWindowIndonesian : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void checkerFindsEnglish_data();
    void checkerFindsEnglish();
    void windowHasNoEnglishLeft();
    void menuAcceleratorsAreUnique();
    void preferencesHasNoEnglishLeft();
    void screenshots_data();
    void screenshots();

private:
    void showFirstRun(MainWindow &window);
    QSet<QString> m_sources;
};

void TestWindowIndonesian::initTestCase()
{
    guitest::isolateSettings();
    // Settings of our own, emptied: names other tests saved (requests, targets) are user data in
    // any language, not the window's text.
    QCoreApplication::setApplicationName(QStringLiteral("mbscope-gui-tests-indonesian"));
    QSettings().clear();
    QString error;
    m_sources = englishSources(&error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(m_sources.size() > 300);
    QVERIFY2(TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::Indonesian)),
             "no Indonesian translation at :/translations/mbscope_id.qm");
    QCOMPARE(QCoreApplication::translate("mbscope::MainWindow", "&File"), QStringLiteral("&Berkas"));
    QCOMPARE(QCoreApplication::translate("mbscope::Field", "Read Holding Registers"), QStringLiteral("Baca Holding Register"));
}

void TestWindowIndonesian::cleanupTestCase()
{
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
}

// The window as a first run shows it: connected to the built-in simulator, its answer shown.
void TestWindowIndonesian::showFirstRun(MainWindow &window)
{
    window.resize(1400, 900);
    QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:0")));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy shown(window.answerView(), &TransactionView::transactionShown);
    window.composer()->send();
    QVERIFY2(shown.wait(5000), "the simulator's answer was not shown");
    QCoreApplication::sendPostedEvents();
}

// The checks themselves catch English, and leave Indonesian and kept terms alone.
void TestWindowIndonesian::checkerFindsEnglish_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("english");
    QTest::newRow("source string") << QStringLiteral("&Quit") << true;
    QTest::newRow("unmarked sentence") << QStringLiteral("Choose the port first") << true;
    QTest::newRow("translated") << QStringLiteral("&Keluar") << false;
    QTest::newRow("kept term") << QStringLiteral("CRC") << false;
    QTest::newRow("url") << QStringLiteral("Menjawab di rtu-tcp://127.0.0.1:4001") << false;
    QTest::newRow("mask operators") << QStringLiteral("hasil = (isi AND and_mask) OR (or_mask AND NOT and_mask)") << false;
}

void TestWindowIndonesian::checkerFindsEnglish()
{
    QFETCH(QString, text);
    QFETCH(bool, english);
    QCOMPARE(!englishLeft({{QStringLiteral("test"), text}}, m_sources).isEmpty(), english);
}

void TestWindowIndonesian::windowHasNoEnglishLeft()
{
    MainWindow window;
    showFirstRun(window);
    QList<VisibleText> texts = visibleTexts(&window);
    texts += fieldTreeTexts(&window);
    QVERIFY(texts.size() > 100);
    const QStringList problems = englishLeft(texts, m_sources);
    for (const QString &p : problems)
        qWarning("%s", qPrintable(p));
    QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("%1 English text(s) left in the Indonesian window, listed above; "
                                                           "the first: %2")
                                                .arg(problems.size())
                                                .arg(problems.value(0))));
}

void TestWindowIndonesian::menuAcceleratorsAreUnique()
{
    MainWindow window;
    const QStringList problems = guitest::repeatedAccelerators(QStringLiteral("menu bar"), window.menuBar()->actions());
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestWindowIndonesian::preferencesHasNoEnglishLeft()
{
    PreferencesDialog dialog;
    QList<VisibleText> texts = visibleTexts(&dialog);
    // Each language is named in its own words in the language box: "English" stays.
    texts.removeIf([](const VisibleText &t) { return t.text == QLatin1String("English"); });
    const QStringList problems = englishLeft(texts, m_sources);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    QVERIFY(guitest::saveShot(&dialog, QStringLiteral("preferences-id.png")));
}

// The window and each of its docks, in both languages.
void TestWindowIndonesian::screenshots_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("id") << QStringLiteral("id");
    QTest::newRow("en") << QStringLiteral("en");
}

void TestWindowIndonesian::screenshots()
{
    QFETCH(QString, language);
    const std::optional<TranslationLoader::Choice> choice = TranslationLoader::parse(language);
    QVERIFY(choice);
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(*choice));
    MainWindow window;
    showFirstRun(window);
    QVERIFY(guitest::saveShot(&window, QStringLiteral("window-%1.png").arg(language)));
    const QList<QDockWidget *> docks = window.findChildren<QDockWidget *>();
    QVERIFY(!docks.isEmpty());
    for (QDockWidget *dock : docks) {
        dock->show();
        dock->raise();
        QTest::qWait(100); // a raised tab lays out and paints its panel (plots) on the next turns
        QVERIFY(guitest::saveShot(dock, QStringLiteral("window-%1-dock-%2.png").arg(language, dock->objectName())));
    }
    // Back to Indonesian for any test that runs after.
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::Indonesian));
}

QTEST_MAIN(TestWindowIndonesian)
#include "tst_windowindonesian.moc"
