#pragma once
// Helpers shared by the window's GUI tests: isolated settings and screenshots in the output dir.

#include <QtCore/QCoreApplication>
#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QSettings>
#include <QtCore/QTemporaryDir>
#include <QtCore/QStandardPaths>
#include <QtGui/QPixmap>
#include <QtWidgets/QWidget>
#include <QtGui/QAction>
#include <QtWidgets/QTabBar>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QMainWindow>
#include <QtWidgets/QLabel>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QAbstractButton>
#include <QtCore/QMultiMap>
#include <QtCore/QHash>
#include <QtCore/QRegularExpression>
#include <QtWidgets/QMenu>
#include <QtTest/QTest>

namespace mbscope::guitest {

// QSettings and files of a test never touch the user's, nor another test program's: each test
// program starts with empty settings and empty XDG folders (data, config, cache, state) in a
// folder of its own, removed when it ends. (They shared one settings file, so what one program
// left, a fault rule of the built-in simulator, reached the others, in whatever order CTest ran
// them; and the window's traffic journals piled up in ~/.qttest/share, or without this call in
// the user's ~/.local/share/mbscope/mbscope/captures.) Not QStandardPaths' test mode: it puts
// every program in the same ~/.qttest of the user running the tests.
inline void isolateSettings()
{
    static QTemporaryDir folder;
    for (const char *name : {"XDG_DATA_HOME", "XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"}) {
        const QString path = folder.filePath(QString::fromLatin1(name).toLower());
        QDir().mkpath(path);
        qputenv(name, QFile::encodeName(path));
    }
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, folder.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder.path());
    QCoreApplication::setOrganizationName(QStringLiteral("mbscope-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("mbscope-gui-tests"));
}

// Where screenshots go: $MBSCOPE_TEST_OUTPUT_DIR, else the test's working directory (CTest runs
// it in the build tree's tests/ui).
inline QString outputPath(const QString &fileName)
{
    const QString dir = qEnvironmentVariableIsSet("MBSCOPE_TEST_OUTPUT_DIR")
                            ? qEnvironmentVariable("MBSCOPE_TEST_OUTPUT_DIR")
                            : QDir::currentPath();
    return QDir(dir).filePath(fileName);
}

// Renders widget to fileName in the output dir and checks the file was written.
inline bool saveShot(QWidget *widget, const QString &fileName)
{
    QCoreApplication::sendPostedEvents();
    const QString path = outputPath(fileName);
    const bool ok = widget->grab().save(path, "PNG");
    qInfo("screenshot: %s", qPrintable(path));
    return ok;
}

// The letter after a single '&' (an accelerator), or a null QChar.
inline QChar mnemonic(const QString &text)
{
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text.at(i) != QLatin1Char('&'))
            continue;
        if (text.at(i + 1) == QLatin1Char('&')) {
            ++i;
            continue;
        }
        return text.at(i + 1).toLower();
    }
    return {};
}

// Every accelerator the shown window answers to with Alt: the menu bar's titles, and the visible
// buttons, labels with buddies, group boxes and tabs. Each maps to where it is, for the message.
inline QMultiMap<QChar, QString> visibleMnemonics(QWidget *window)
{
    QMultiMap<QChar, QString> found;
    auto add = [&found](const QString &text, const QString &where) {
        const QChar letter = mnemonic(text);
        if (!letter.isNull())
            found.insert(letter, QStringLiteral("%1 \"%2\"").arg(where, text));
    };
    if (auto *main = qobject_cast<QMainWindow *>(window)) {
        for (QAction *action : main->menuBar()->actions())
            add(action->text(), QStringLiteral("menu"));
    }
    for (QWidget *w : window->findChildren<QWidget *>()) {
        if (!w->isVisible() || w->window() != window)
            continue;
        if (auto *button = qobject_cast<QAbstractButton *>(w))
            add(button->text(), QStringLiteral("button"));
        else if (auto *label = qobject_cast<QLabel *>(w); label && label->buddy())
            add(label->text(), QStringLiteral("label"));
        else if (auto *box = qobject_cast<QGroupBox *>(w); box && box->isCheckable())
            add(box->title(), QStringLiteral("group"));
        else if (auto *tabs = qobject_cast<QTabBar *>(w)) {
            for (int i = 0; i < tabs->count(); ++i) {
                if (tabs->isTabVisible(i) && tabs->isTabEnabled(i))
                    add(tabs->tabText(i), QStringLiteral("tab"));
            }
        }
    }
    return found;
}


// The letters more than one visible control of window answers to, with who owns them.
inline QStringList mnemonicClashes(QWidget *window)
{
    const QMultiMap<QChar, QString> found = visibleMnemonics(window);
    QStringList clashes;
    for (const QChar letter : found.uniqueKeys()) {
        const QStringList owners = found.values(letter);
        if (owners.size() > 1)
            clashes << QStringLiteral("Alt+%1: %2").arg(letter.toUpper(), owners.join(QLatin1String(", ")));
    }
    return clashes;
}

// Menus whose &-accelerators repeat a letter: the second one cannot be reached with Alt.
inline QStringList repeatedAccelerators(const QString &where, const QList<QAction *> &actions)
{
    QStringList problems;
    QHash<QChar, QString> used;
    static const QRegularExpression accelerator(QStringLiteral("&([^&\\s])"));
    for (QAction *a : actions) {
        if (a->isSeparator() || !a->isVisible())
            continue;
        const QRegularExpressionMatch m = accelerator.match(QString(a->text()).remove(QStringLiteral("&&")));
        if (m.hasMatch()) {
            const QChar key = m.captured(1).at(0).toLower();
            if (used.contains(key))
                problems << QStringLiteral("%1: '%2' and '%3' share the accelerator %4")
                                .arg(where, used.value(key), a->text(), QString(key));
            else
                used.insert(key, a->text());
        }
        if (QMenu *sub = a->menu())
            problems << repeatedAccelerators(where + QStringLiteral(" > ") + QString(a->text()).remove(QLatin1Char('&')), sub->actions());
    }
    return problems;
}

} // namespace mbscope::guitest
