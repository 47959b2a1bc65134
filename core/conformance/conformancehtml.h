#pragma once

#include "conformanceresult.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// A scorecard as one self-contained HTML page (`mbscope conform --html`, the Conformance
// window's Save): the verdict and the counts first, then every check with its id, title, clause,
// level, verdict, sentence, the request sent (the evidence) and the device's answer as hex.
// Written with QXmlStreamWriter, so the page is well-formed XML as well as HTML (a test reads it
// back); its style is inline, with a print layout; no script, image or external file.
class ConformanceHtml
{
public:
    [[nodiscard]] static QByteArray toHtml(const ConformanceResult &result);
    // Atomically (QSaveFile); false with *error naming the file.
    static bool write(const ConformanceResult &result, const QString &path, QString *error = nullptr);
};

} // namespace mbscope
