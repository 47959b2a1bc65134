#pragma once

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

namespace mbscope {

// Text the core hands out as static strings (field names and meanings, function and exception
// names, register types, why bytes were skipped), marked there with
// QT_TRANSLATE_NOOP("mbscope::Field", ...), shown in the window's language. The core itself
// always speaks English, so the command line, JSON and the golden tests do not change.
inline QString fieldText(const char *text)
{
    return text ? QCoreApplication::translate("mbscope::Field", text) : QString();
}

} // namespace mbscope
