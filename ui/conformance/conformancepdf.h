#pragma once

#include "conformance/conformanceresult.h"

#include <QtCore/QString>

namespace mbscope {

// A scorecard as a PDF (`mbscope conform --pdf`, the Conformance window's Save as .pdf): the page
// of ConformanceHtml (core/conformance), the one renderer of the report, laid out by a
// QTextDocument and printed by a QPdfWriter on A4. Needs a QGuiApplication (fonts); the command
// line makes one on the offscreen platform.
class ConformancePdf
{
public:
    // Atomically (QSaveFile); false with *error naming the file.
    static bool write(const ConformanceResult &result, const QString &path, QString *error = nullptr);
};

} // namespace mbscope
