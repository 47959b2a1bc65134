#include "conformancehtml.h"

#include "conformancejudge.h"

#include <QtCore/QSaveFile>
#include <QtCore/QXmlStreamWriter>

#include <utility>

namespace mbscope {

namespace {

const char kStyle[] = R"(
body { font-family: sans-serif; margin: 2em; color: #1a1a1a; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; }
table { border-collapse: collapse; }
th, td { text-align: left; vertical-align: top; padding: 0.15em 0.8em 0.15em 0; }
.summary { margin-bottom: 1.5em; }
.verdict { font-weight: bold; font-size: 1.2em; padding: 0.4em 0.6em; border-radius: 4px; display: inline-block; }
.verdict.passed { background: #d8f0d8; color: #14501e; }
.verdict.failed { background: #f8d8d8; color: #7a1010; }
.check { border-top: 1px solid #bbb; padding: 0.5em 0; page-break-inside: avoid; break-inside: avoid; }
.check h3 { font-size: 1em; margin: 0 0 0.3em 0; }
.label { font-family: monospace; font-weight: bold; padding: 0 0.4em; border-radius: 3px; }
.PASS { background: #d8f0d8; color: #14501e; }
.INFO { background: #dde8f8; color: #1a3a6a; }
.FAIL { background: #f8d8d8; color: #7a1010; }
.WARN { background: #f8ecc8; color: #6a4a00; }
.SKIP { background: #e8e8e8; color: #444; }
.ERROR { background: #f0c8f0; color: #5a105a; }
code { font-family: monospace; word-break: break-all; }
@media print { body { margin: 0; font-size: 10pt; } a { color: inherit; text-decoration: none; } }
)";

void row(QXmlStreamWriter &w, const QString &name, const QString &value, const QString &cls = {})
{
    w.writeStartElement(QStringLiteral("tr"));
    w.writeTextElement(QStringLiteral("th"), name);
    w.writeStartElement(QStringLiteral("td"));
    if (!cls.isEmpty())
        w.writeAttribute(QStringLiteral("class"), cls);
    w.writeCharacters(value.isEmpty() ? QStringLiteral("-") : value); // never <td/>: HTML does not close it
    w.writeEndElement();
    w.writeEndElement();
}

void codeRow(QXmlStreamWriter &w, const QString &name, const QString &cls, const QString &hex, const QString &empty)
{
    w.writeStartElement(QStringLiteral("tr"));
    w.writeTextElement(QStringLiteral("th"), name);
    w.writeStartElement(QStringLiteral("td"));
    w.writeAttribute(QStringLiteral("class"), cls);
    if (hex.isEmpty()) {
        w.writeCharacters(empty);
    } else {
        w.writeTextElement(QStringLiteral("code"), hex);
    }
    w.writeEndElement();
    w.writeEndElement();
}

void writeCheck(QXmlStreamWriter &w, const CheckResult &c)
{
    const QString label = QString::fromLatin1(ConformanceResult::label(c));
    w.writeStartElement(QStringLiteral("section"));
    w.writeAttribute(QStringLiteral("class"), QStringLiteral("check"));
    w.writeAttribute(QStringLiteral("id"), c.id);
    w.writeAttribute(QStringLiteral("data-verdict"), QLatin1String(checkVerdictName(c.verdict)));
    w.writeStartElement(QStringLiteral("h3"));
    w.writeStartElement(QStringLiteral("span"));
    w.writeAttribute(QStringLiteral("class"), QStringLiteral("label ") + label);
    w.writeCharacters(label);
    w.writeEndElement();
    w.writeCharacters(QLatin1Char(' ') + c.id + QStringLiteral(": ") + c.title);
    w.writeEndElement(); // h3
    w.writeStartElement(QStringLiteral("table"));
    row(w, QStringLiteral("clause"), c.clause, QStringLiteral("clause"));
    row(w, QStringLiteral("level"), QLatin1String(checkLevelName(c.level)), QStringLiteral("level"));
    row(w, QStringLiteral("verdict"), QLatin1String(checkVerdictName(c.verdict)), QStringLiteral("verdict-name"));
    row(w, QStringLiteral("why"), c.sentence, QStringLiteral("sentence"));
    if (!c.measured.isEmpty())
        row(w, QStringLiteral("measured"), c.measured, QStringLiteral("measured"));
    codeRow(w, QStringLiteral("request"), QStringLiteral("request"), ConformanceJudge::hex(c.request), QStringLiteral("(none sent)"));
    codeRow(w, QStringLiteral("answer"), QStringLiteral("answer"), ConformanceJudge::hex(c.answer), QStringLiteral("(none)"));
    row(w, QStringLiteral("took"), QStringLiteral("%1 ms").arg(double(c.elapsedNs) / 1e6, 0, 'f', 1));
    w.writeEndElement(); // table
    w.writeEndElement(); // section
}

} // namespace

QByteArray ConformanceHtml::toHtml(const ConformanceResult &r)
{
    QByteArray out;
    QXmlStreamWriter w(&out);
    w.setAutoFormatting(true);
    w.setAutoFormattingIndent(1);
    w.writeDTD(QStringLiteral("<!DOCTYPE html>"));
    w.writeStartElement(QStringLiteral("html"));
    w.writeDefaultNamespace(QStringLiteral("http://www.w3.org/1999/xhtml"));
    w.writeAttribute(QStringLiteral("lang"), QStringLiteral("en"));
    w.writeStartElement(QStringLiteral("head"));
    w.writeEmptyElement(QStringLiteral("meta"));
    w.writeAttribute(QStringLiteral("charset"), QStringLiteral("utf-8"));
    const QString title = QStringLiteral("mbscope conform: %1, unit %2").arg(r.target).arg(r.unit);
    w.writeTextElement(QStringLiteral("title"), title);
    w.writeTextElement(QStringLiteral("style"), QString::fromLatin1(kStyle));
    w.writeEndElement(); // head

    w.writeStartElement(QStringLiteral("body"));
    w.writeTextElement(QStringLiteral("h1"), QStringLiteral("Modbus conformance scorecard"));

    w.writeStartElement(QStringLiteral("section"));
    w.writeAttribute(QStringLiteral("class"), QStringLiteral("summary"));
    w.writeAttribute(QStringLiteral("id"), QStringLiteral("summary"));
    w.writeStartElement(QStringLiteral("p"));
    w.writeAttribute(QStringLiteral("class"), QStringLiteral("verdict ") + (r.passed() ? QStringLiteral("passed") : QStringLiteral("failed")));
    w.writeCharacters(r.verdictSentence());
    w.writeEndElement();
    w.writeStartElement(QStringLiteral("table"));
    row(w, QStringLiteral("target"), r.target, QStringLiteral("target"));
    row(w, QStringLiteral("unit"), QString::number(r.unit), QStringLiteral("unit"));
    row(w, QStringLiteral("started"), r.started.toString(Qt::ISODate));
    row(w, QStringLiteral("took"), QStringLiteral("%1 s").arg(double(r.elapsedNs) / 1e9, 0, 'f', 3));
    row(w, QStringLiteral("checks"), r.countsSentence(), QStringLiteral("counts"));
    if (!r.support.isEmpty())
        row(w, QStringLiteral("functions"), r.supportSentence(), QStringLiteral("functions"));
    w.writeEndElement(); // table
    // The failures first, linked to their check below.
    QList<const CheckResult *> failures;
    for (const CheckResult &c : r.checks) {
        if (c.verdict == CheckVerdict::Failed || c.verdict == CheckVerdict::Error)
            failures.append(&c);
    }
    if (!failures.isEmpty()) {
        w.writeTextElement(QStringLiteral("h2"), QStringLiteral("Failures and deviations"));
        w.writeStartElement(QStringLiteral("ul"));
        w.writeAttribute(QStringLiteral("class"), QStringLiteral("failures"));
        for (const CheckResult *c : std::as_const(failures)) {
            w.writeStartElement(QStringLiteral("li"));
            w.writeStartElement(QStringLiteral("a"));
            w.writeAttribute(QStringLiteral("href"), QLatin1Char('#') + c->id);
            w.writeCharacters(c->id);
            w.writeEndElement();
            w.writeCharacters(QStringLiteral(" (%1): %2").arg(QLatin1String(checkLevelName(c->level)), c->sentence));
            w.writeEndElement();
        }
        w.writeEndElement(); // ul
    }
    w.writeEndElement(); // section.summary

    w.writeStartElement(QStringLiteral("section"));
    w.writeAttribute(QStringLiteral("id"), QStringLiteral("checks"));
    w.writeTextElement(QStringLiteral("h2"), QStringLiteral("Checks"));
    for (const CheckResult &c : r.checks)
        writeCheck(w, c);
    w.writeEndElement(); // section#checks
    w.writeStartElement(QStringLiteral("p"));
    w.writeAttribute(QStringLiteral("class"), QStringLiteral("footer"));
    w.writeCharacters(QStringLiteral("Written by mbscope conform. Clauses: MODBUS Application Protocol Specification V1.1b3, "
                                     "MODBUS over Serial Line V1.02, MODBUS Messaging on TCP/IP Implementation Guide V1.0b."));
    w.writeEndElement();
    w.writeEndElement(); // body
    w.writeEndElement(); // html
    w.writeEndDocument();
    return out;
}

bool ConformanceHtml::write(const ConformanceResult &result, const QString &path, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error)
            *error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    file.write(toHtml(result));
    if (!file.commit()) {
        if (error)
            *error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace mbscope
