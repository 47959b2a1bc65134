#include "common/printoptions.h"

#include "common/framelog.h"
#include "common/outputpath.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QTextStream>

namespace mbscope::app {

PrintOptions::PrintOptions(bool values)
    : m_values(values)
    , m_print(QStringLiteral("print"),
              values ? QStringLiteral("Print as they come: values (one line per answer: time, request, status, latency and "
                                      "the values in the --format(s) given), before the statistics; frames (every frame "
                                      "sent and received: time, direction, verdict and hex, on standard error). Both: "
                                      "--print values,frames.")
                     : QStringLiteral("Print as they come: frames (every frame sent and received: time, direction, verdict "
                                      "and hex, on standard error)."),
              QStringLiteral("what"))
    , m_frameLog(QStringLiteral("frame-log"),
                 QStringLiteral("Write the frames as they come (as --print frames shows them) to FILE instead of "
                                "standard error."),
                 QStringLiteral("FILE"))
{
}

void PrintOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOptions({m_print, m_frameLog});
}

bool PrintOptions::frameLogSet(const QCommandLineParser &parser) const
{
    return parser.isSet(m_frameLog);
}

bool PrintOptions::read(const QCommandLineParser &parser, const QString &command, bool force, PrintSettings &out,
                        QTextStream &err) const
{
    const QString prefix = QStringLiteral("mbscope %1: ").arg(command);
    for (const QString &value : parser.values(m_print)) {
        for (const QString &word : value.split(QLatin1Char(','))) {
            const QString w = word.trimmed();
            if (w == QLatin1String("frames")) {
                out.frames = true;
            } else if (m_values && w == QLatin1String("values")) {
                out.values = true;
            } else {
                err << prefix << "--print '" << w << "': expected "
                    << (m_values ? "values (each answer's values as it comes) or frames (each frame as it goes and comes)"
                                 : "frames (each frame as it goes and comes)")
                    << '\n';
                return false;
            }
        }
    }
    if (parser.isSet(m_frameLog)) {
        const QString path = parser.value(m_frameLog);
        const QString problem = OutputPath::problem(QStringLiteral("--frame-log"), path, QStringLiteral("--frame-log frames.log"),
                                                    force);
        if (!problem.isEmpty()) {
            err << prefix << problem << '\n';
            return false;
        }
        out.frames = true;
        out.framePath = path;
    }
    return true;
}

bool openFrameLog(FrameLog &log, const PrintSettings &settings, const QString &command, QTextStream &err)
{
    if (!settings.frames)
        return true;
    QString error;
    if (log.open(settings.framePath, &error))
        return true;
    err << "mbscope " << command << ": --frame-log: " << error << '\n';
    return false;
}

} // namespace mbscope::app
