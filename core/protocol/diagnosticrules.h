#pragma once

#include "buildresult.h"
#include "framing.h"

#include <QtCore/QByteArray>

namespace mbscope {
class PduBuilder;
}

// What Diagnostics (0x08) sub-functions carry, for the request and response builders
// (V1.1b3, 6.8.1). Each check records its problems on the builder and says whether all was well.
namespace mbscope::diagnosticrules {

// "Return Query Data"; nullptr for a reserved sub-function (05-09, 13, 21-65535).
[[nodiscard]] const char *subFunctionName(int subFunction);
// The sub-function is a 16-bit value and one the specification defines.
bool checkSubFunction(PduBuilder &builder, int subFunction);
// The data field is what the sub-function prescribes in that direction.
bool checkData(PduBuilder &builder, int subFunction, const QByteArray &data, Direction direction);
// A Diagnostics PDU in that direction: sub-function and data, both checked.
[[nodiscard]] BuildResult build(int subFunction, const QByteArray &data, Direction direction);

} // namespace mbscope::diagnosticrules
