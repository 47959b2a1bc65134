// libFuzzer target over session documents: any bytes given to SessionReader::parse load as a
// whole document or are refused with problems that each say what is wrong; never a crash, a hang
// or a sanitizer report. A document that loads survives the writer: what SessionWriter makes of
// it loads again, and writing that gives the same bytes (nothing is lost or changed on a save).
//
// Input layout: the bytes are the file. Seeds: the example and test sessions (corpus/session).
#include "session/sessionreader.h"
#include "session/sessionwriter.h"

#include <QtCore/QByteArray>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

using namespace mbscope;

namespace {

void check(bool condition)
{
    if (!condition)
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const QString source = QStringLiteral("fuzz.mbscope.json");
    const SessionLoadResult result = SessionReader::parse(bytes, source);
    check(result.ok() == result.problems.isEmpty());
    for (const ProfileProblem &problem : result.problems) {
        check(!problem.message.isEmpty());
        check(problem.line >= 0 && problem.column >= 0);
        check(problem.toString().contains(problem.message));
    }
    if (!result.ok())
        return 0;

    const QByteArray written = SessionWriter::toBytes(*result.document);
    const SessionLoadResult again = SessionReader::parse(written, source);
    check(again.ok());
    check(SessionWriter::toBytes(*again.document) == written);
    return 0;
}
