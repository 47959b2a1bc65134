// libFuzzer target over the script-facing request object (issue 15): any bytes as a request PDU,
// taken apart by ScriptRequest::fromPdu, handed to a device script's onRequest through a real
// ScriptHost (QJSEngine), and its answer read back by the host. The script returns what it saw
// (function, address, quantity, count of values, PDU length), which must be what fromPdu read;
// a PDU starting 7E is read by the script as JSON text and returned as it is, so that every kind
// of value (objects with any keys, arrays, numbers, strings, null) goes through the answer
// reader. Nothing may crash, hang or answer other than the script said.
#include "script/scripthost.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>

using namespace mbscope;

namespace {

void check(bool condition)
{
    if (!condition)
        std::abort();
}

const char kScript[] =
    "function onRequest(r) {\n"
    "  if (r.function === 0x7E) {\n"
    "    try { return JSON.parse(String.fromCharCode.apply(null, r.pdu.slice(1))); } catch (e) { return undefined; }\n"
    "  }\n"
    "  var n = function (v) { return v === undefined ? 65535 : v; };\n"
    "  return [n(r.function), n(r.address), n(r.quantity), r.values.length, r.pdu.length, n(r.writeAddress)];\n"
    "}\n";

ScriptHost &host()
{
    // QJSEngine needs an application object; libFuzzer's main and fuzz_replay's make none.
    static int argc = 1;
    static char name[] = "fuzz_script";
    static char *argv[] = {name, nullptr};
    static std::unique_ptr<QCoreApplication> app(QCoreApplication::instance() ? nullptr : new QCoreApplication(argc, argv));
    static QTemporaryDir dir;
    static std::unique_ptr<ScriptHost> h;
    if (!h) {
        QFile file(dir.filePath(QStringLiteral("fuzz.js")));
        check(file.open(QIODevice::WriteOnly));
        file.write(kScript);
        file.close();
        ScriptSettings settings;
        settings.path = file.fileName();
        settings.name = QStringLiteral("fuzz.js");
        settings.timeoutMs = 2000;
        h = std::make_unique<ScriptHost>(settings, nullptr);
        check(h->load());
    }
    return *h;
}

quint16 orMax(int v)
{
    return v < 0 ? 65535 : quint16(v);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size > 300) // a PDU is at most 253 bytes; a little more tests the reader's bounds
        return 0;
    const QByteArray pdu(reinterpret_cast<const char *>(data), qsizetype(size));
    ScriptRequest request = ScriptRequest::fromPdu(pdu);
    check(request.pdu == pdu);
    check(request.function == (pdu.isEmpty() ? -1 : int(quint8(pdu.at(0)))));
    check(request.address >= -1 && request.address <= 65535);
    check(request.quantity >= -1 && request.quantity <= 65535);
    check(request.values.size() <= pdu.size() * 8);
    request.unit = 1;
    request.transactionId = 7;
    const ScriptAnswer answer = host().request(request);
    if (request.function == 0x7E) {
        // Any kind; a failure says where it came from.
        check(answer.kind != ScriptAnswer::Kind::Failed || answer.note.startsWith(QLatin1String("fuzz.js")));
        check(answer.kind != ScriptAnswer::Kind::Exception || (answer.exceptionCode >= 1 && answer.exceptionCode <= 255));
        check((answer.kind != ScriptAnswer::Kind::Pdu && answer.kind != ScriptAnswer::Kind::Adu) || !answer.bytes.isEmpty());
        check(answer.delayNs >= -1);
        return 0;
    }
    if (request.function < 0) {
        check(answer.kind == ScriptAnswer::Kind::Values);
        check(answer.values.at(0) == 65535);
        return 0;
    }
    check(answer.kind == ScriptAnswer::Kind::Values);
    const QList<quint16> expected{orMax(request.function), orMax(request.address), orMax(request.quantity),
                                  quint16(request.values.size()), quint16(pdu.size()), orMax(request.writeAddress)};
    check(answer.values == expected);
    return 0;
}
