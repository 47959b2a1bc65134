#include "includerules.h"

#include <QtCore/QDir>
#include <QtCore/QDirIterator>
#include <QtCore/QRegularExpression>

#include <utility>

namespace mbscope::testdocs {

namespace {

// Where a file stands: "core", "ui", "app", "tests/core" or "tests" (the rest of tests/).
QString partOf(const QString &path)
{
    if (path.startsWith(QLatin1String("tests/core/")))
        return QStringLiteral("tests/core");
    return path.section(QLatin1Char('/'), 0, 0);
}

// The folder inside core/ or ui/ ("protocol", "common"); empty elsewhere.
QString folderOf(const QString &path)
{
    const QString part = partOf(path);
    if (part != QLatin1String("core") && part != QLatin1String("ui"))
        return {};
    return path.count(QLatin1Char('/')) >= 2 ? path.section(QLatin1Char('/'), 1, 1) : QString();
}

// The include roots of each part, in the order its target hands them to the compiler.
QStringList rootsOf(const QString &part)
{
    if (part == QLatin1String("app"))
        return {QStringLiteral("app"), QStringLiteral("ui"), QStringLiteral("core")};
    if (part == QLatin1String("ui"))
        return {QStringLiteral("ui"), QStringLiteral("core")};
    return {QStringLiteral("core")};
}

// Qt modules core may use, and where. Anything else (QtGui, QtWidgets, QtSvg, QCustomPlot) none.
const QMap<QString, QStringList> &coreModules()
{
    static const QMap<QString, QStringList> modules{
        {QStringLiteral("QtCore"), {}}, // everywhere
        {QStringLiteral("QtNetwork"),
         {QStringLiteral("transport"), QStringLiteral("sim"), QStringLiteral("capture")}},
        {QStringLiteral("QtSerialPort"), {QStringLiteral("transport"), QStringLiteral("sim")}},
        {QStringLiteral("QtSerialBus"), {QStringLiteral("sim")}},
        {QStringLiteral("QtQml"), {QStringLiteral("script")}},
    };
    return modules;
}

const QStringList &windowModules()
{
    static const QStringList modules{QStringLiteral("QtGui"), QStringLiteral("QtWidgets"),
                                     QStringLiteral("QtSvg"), QStringLiteral("QCustomPlot")};
    return modules;
}

const QStringList &uiCommonCore()
{
    static const QStringList folders{QStringLiteral("protocol"), QStringLiteral("exchange"),
                                     QStringLiteral("time"), QStringLiteral("json")};
    return folders;
}

} // namespace

QString IncludeViolation::toString() const
{
    return QStringLiteral("%1:%2: #include %3: %4").arg(file).arg(line).arg(include, reason);
}

IncludeRules::IncludeRules(QSet<QString> knownFiles)
    : m_known(std::move(knownFiles))
{
}

QMap<QString, int> IncludeRules::coreLayers()
{
    return {
        {QStringLiteral("protocol"), 0}, {QStringLiteral("time"), 0},    {QStringLiteral("json"), 0},
        {QStringLiteral("metrics"), 0}, {QStringLiteral("job"), 0},
        {QStringLiteral("transport"), 1}, {QStringLiteral("exchange"), 2}, {QStringLiteral("traffic"), 3},
        {QStringLiteral("script"), 3},
        {QStringLiteral("engine"), 4},   {QStringLiteral("capture"), 4}, {QStringLiteral("profile"), 4},
        {QStringLiteral("watch"), 4},    {QStringLiteral("fleet"), 5},    {QStringLiteral("discovery"), 5},
        {QStringLiteral("sim"), 5},      {QStringLiteral("session"), 5}, {QStringLiteral("monitor"), 5},
        {QStringLiteral("mapexport"), 5},
        {QStringLiteral("replay"), 6},   {QStringLiteral("service"), 6}, {QStringLiteral("conformance"), 6},
        {QStringLiteral("inference"), 6},
        {QStringLiteral("tap"), 7},
    };
}

QMap<QString, int> IncludeRules::uiTiers()
{
    return {
        {QStringLiteral("common"), 0},
        {QStringLiteral("link"), 1},     {QStringLiteral("compose"), 1},   {QStringLiteral("decode"), 1},
        {QStringLiteral("traffic"), 1},  {QStringLiteral("registers"), 1}, {QStringLiteral("sim"), 1},
        {QStringLiteral("discovery"), 1},
        {QStringLiteral("analysis"), 2}, {QStringLiteral("session"), 2}, {QStringLiteral("watch"), 2},
        {QStringLiteral("conformance"), 2},
        {QStringLiteral("shell"), 3},
    };
}

QStringList IncludeRules::coreExceptions()
{
    return {
        QStringLiteral("core/profile/delayspec.cpp -> core/sim/simrandom.h"),
        QStringLiteral("core/profile/profileunitreader.cpp -> core/sim/simunit.h"),
    };
}

IncludeRules::Resolution IncludeRules::resolve(const QString &file, const QString &name) const
{
    const QString part = partOf(file);
    const QString dir = file.section(QLatin1Char('/'), 0, -2);
    QStringList ordered{QDir::cleanPath(dir + QLatin1Char('/') + name)};
    for (const QString &root : rootsOf(part))
        ordered.append(QDir::cleanPath(root + QLatin1Char('/') + name));
    // Roots the part cannot see still tell where a name leads (core including a ui header).
    for (const QString &root : {QStringLiteral("ui"), QStringLiteral("core"), QStringLiteral("app")})
        ordered.append(QDir::cleanPath(root + QLatin1Char('/') + name));

    Resolution result;
    for (const QString &candidate : std::as_const(ordered)) {
        if (!m_known.contains(candidate))
            continue;
        if (result.target.isEmpty())
            result.target = candidate;
        else if (candidate != result.target && !result.others.contains(candidate))
            result.others.append(candidate);
    }
    return result;
}

QStringList IncludeRules::includedFiles(const QString &file, const QString &text) const
{
    static const QRegularExpression quoted(QStringLiteral(R"re(^\s*#\s*include\s*"([^"]+)")re"),
                                           QRegularExpression::MultilineOption);
    QStringList out;
    for (auto it = quoted.globalMatch(text); it.hasNext();) {
        const QString target = resolve(file, it.next().captured(1)).target;
        if (!target.isEmpty() && !out.contains(target))
            out.append(target);
    }
    return out;
}

void IncludeRules::checkQuoted(const QString &file, int line, const QString &name, bool uiGuarded,
                               QList<IncludeViolation> &out) const
{
    const QString part = partOf(file);
    const QString written = QLatin1Char('"') + name + QLatin1Char('"');
    const auto fail = [&](const QString &reason) { out.append(IncludeViolation{file, line, written, reason}); };

    // AUTOMOC's meta-object code of the file's own header (moc_X.cpp for X.h beside it), included
    // at the end of X.cpp so that it is linked only with the class.
    if (name.startsWith(QLatin1String("moc_")) && name.endsWith(QLatin1String(".cpp")) && !name.contains(QLatin1Char('/'))) {
        const QString header = file.section(QLatin1Char('/'), 0, -2) + QLatin1Char('/') + name.mid(4).chopped(4)
                               + QLatin1String(".h");
        if (!m_known.contains(header))
            fail(QStringLiteral("includes the meta-object code of %1, which does not exist").arg(header));
        return;
    }
    const Resolution found = resolve(file, name);
    if (found.target.isEmpty()) {
        // Tests include generated .moc files and helpers of their own folders.
        if (!part.startsWith(QLatin1String("tests")))
            fail(QStringLiteral("names no file under core/, ui/ or app/"));
        return;
    }
    if (!found.others.isEmpty() && !part.startsWith(QLatin1String("tests")))
        fail(QStringLiteral("reaches both %1 and %2: which one is taken depends on the include order")
                 .arg(found.target, found.others.join(QLatin1String(", "))));

    const QString own = folderOf(file);
    const QString targetPart = partOf(found.target);
    const QString target = folderOf(found.target);
    const QString where = QStringLiteral(" (%1)").arg(found.target);

    if (part == QLatin1String("core")) {
        if (targetPart != QLatin1String("core")) {
            fail(QStringLiteral("core includes nothing from %1/").arg(targetPart) + where);
            return;
        }
        if (target == own
            || coreExceptions().contains(file + QLatin1String(" -> ") + found.target))
            return;
        const QMap<QString, int> layers = coreLayers();
        if (!layers.contains(own) || !layers.contains(target)) {
            fail(QStringLiteral("core/%1 has no layer: give it one in docs/architecture.md (Layers) "
                                "and IncludeRules::coreLayers")
                     .arg(layers.contains(own) ? target : own));
            return;
        }
        if (layers.value(target) >= layers.value(own))
            fail(QStringLiteral("core/%1 (layer %2) includes only lower layers, and core/%3 is layer %4")
                     .arg(own)
                     .arg(layers.value(own))
                     .arg(target)
                     .arg(layers.value(target))
                 + where);
    } else if (part == QLatin1String("ui")) {
        if (targetPart == QLatin1String("core")) {
            if (own == QLatin1String("common") && !uiCommonCore().contains(target))
                fail(QStringLiteral("ui/common includes of core only the values (core/%1), not core/%2")
                         .arg(uiCommonCore().join(QLatin1String(", core/")), target)
                     + where);
            return;
        }
        if (targetPart != QLatin1String("ui")) {
            fail(QStringLiteral("ui includes nothing from %1/").arg(targetPart) + where);
            return;
        }
        if (target == own)
            return;
        const QMap<QString, int> tiers = uiTiers();
        if (!tiers.contains(own) || !tiers.contains(target)) {
            fail(QStringLiteral("ui/%1 has no tier: give it one in docs/architecture.md (Layers) "
                                "and IncludeRules::uiTiers")
                     .arg(tiers.contains(own) ? target : own));
            return;
        }
        if (tiers.value(target) >= tiers.value(own))
            fail(QStringLiteral("ui/%1 (tier %2) includes only wings of a lower tier, and ui/%3 is tier %4")
                     .arg(own)
                     .arg(tiers.value(own))
                     .arg(target)
                     .arg(tiers.value(target))
                 + where);
    } else if (part == QLatin1String("app")) {
        if (targetPart == QLatin1String("ui") && !uiGuarded && file != QLatin1String("app/gui.cpp"))
            fail(QStringLiteral("app includes ui/ only in gui.cpp or under #ifdef MBSCOPE_HAVE_UI "
                                "(the command line builds without the window)")
                 + where);
        else if (targetPart.startsWith(QLatin1String("tests")))
            fail(QStringLiteral("app includes nothing from tests/") + where);
    } else if (part == QLatin1String("tests/core")) {
        if (targetPart == QLatin1String("ui") || targetPart == QLatin1String("app"))
            fail(QStringLiteral("tests of core include core only") + where);
    }
}

void IncludeRules::checkAngled(const QString &file, int line, const QString &name, bool uiGuarded,
                               QList<IncludeViolation> &out) const
{
    const QString part = partOf(file);
    const QString written = QLatin1Char('<') + name + QLatin1Char('>');
    const auto fail = [&](const QString &reason) { out.append(IncludeViolation{file, line, written, reason}); };

    QString module;
    if (name == QLatin1String("qcustomplot.h"))
        module = QStringLiteral("QCustomPlot");
    else if (name.startsWith(QLatin1String("Qt")))
        module = name.section(QLatin1Char('/'), 0, 0);
    else if (name.size() > 1 && name.at(0) == QLatin1Char('Q') && name.at(1).isUpper()) {
        if (!part.startsWith(QLatin1String("tests")))
            fail(QStringLiteral("Qt headers are named with their module (<QtCore/QTimer>), so that the "
                                "modules each part uses can be checked"));
        return;
    } else {
        return; // the standard library and POSIX
    }

    if (part == QLatin1String("core")) {
        const QString own = folderOf(file);
        if (!coreModules().contains(module))
            fail(QStringLiteral("core uses QtCore, QtNetwork, QtSerialPort, QtSerialBus and QtQml only, not %1")
                     .arg(module));
        else if (const QStringList allowed = coreModules().value(module);
                 !allowed.isEmpty() && !allowed.contains(own))
            fail(QStringLiteral("%1 is used in core only by core/%2, not core/%3")
                     .arg(module, allowed.join(QLatin1String(", core/")), own));
    } else if (part == QLatin1String("app")) {
        if (windowModules().contains(module) && !uiGuarded && file != QLatin1String("app/gui.cpp"))
            fail(QStringLiteral("app uses %1 only in gui.cpp or under #ifdef MBSCOPE_HAVE_UI "
                                "(the command line builds without the window)")
                     .arg(module));
    } else if (part == QLatin1String("tests/core")) {
        if (!coreModules().contains(module) && module != QLatin1String("QtTest"))
            fail(QStringLiteral("tests of core use core's Qt modules and QtTest only, not %1").arg(module));
    }
}

QList<IncludeViolation> IncludeRules::check(const QString &file, const QString &text) const
{
    static const QRegularExpression include(
        QStringLiteral(R"(^\s*#\s*include\s*([<"])([^">]+)[">])"));
    static const QRegularExpression conditional(
        QStringLiteral(R"(^\s*#\s*(ifdef|ifndef|if|elif|else|endif)\b(.*)$)"));
    const QLatin1String uiMacro("MBSCOPE_HAVE_UI");

    QList<IncludeViolation> out;
    // One entry per open #if: whether its branch holds only when the window is built.
    QList<bool> guards;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString &lineText = lines.at(i);
        if (const QRegularExpressionMatch m = conditional.match(lineText); m.hasMatch()) {
            const QString directive = m.captured(1);
            const QString condition = m.captured(2).trimmed();
            if (directive == QLatin1String("endif")) {
                if (!guards.isEmpty())
                    guards.removeLast();
            } else if (directive == QLatin1String("else") || directive == QLatin1String("elif")) {
                if (!guards.isEmpty())
                    guards.last() = false;
            } else {
                const bool positive = directive == QLatin1String("ifdef")
                    || (directive == QLatin1String("if") && !condition.contains(QLatin1Char('!')));
                guards.append(positive && condition.contains(uiMacro));
            }
            continue;
        }
        const QRegularExpressionMatch m = include.match(lineText);
        if (!m.hasMatch())
            continue;
        const bool uiGuarded = guards.contains(true);
        const int line = int(i + 1);
        if (m.captured(1) == QLatin1String("\""))
            checkQuoted(file, line, m.captured(2), uiGuarded, out);
        else
            checkAngled(file, line, m.captured(2), uiGuarded, out);
    }
    return out;
}

QStringList IncludeRules::sourceFiles(const QString &sourceDir)
{
    const QDir root(sourceDir);
    QStringList files;
    for (const QString &top : {QStringLiteral("core"), QStringLiteral("ui"), QStringLiteral("app"),
                               QStringLiteral("tests/core")}) {
        QDirIterator it(root.filePath(top), {QStringLiteral("*.h"), QStringLiteral("*.cpp")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext())
            files.append(root.relativeFilePath(it.next()));
    }
    files.sort();
    return files;
}

QSet<QString> IncludeRules::knownFiles(const QString &sourceDir)
{
    const QDir root(sourceDir);
    QSet<QString> files;
    for (const QString &top : {QStringLiteral("core"), QStringLiteral("ui"), QStringLiteral("app"),
                               QStringLiteral("tests")}) {
        QDirIterator it(root.filePath(top), {QStringLiteral("*.h"), QStringLiteral("*.cpp")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext())
            files.insert(root.relativeFilePath(it.next()));
    }
    return files;
}

} // namespace mbscope::testdocs
