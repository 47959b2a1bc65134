#pragma once

#include "session/fieldexpectation.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// What the answer to a send step must be. Any combination of bytes, fields and exception may be
// given (all must hold); noAnswer stands alone.
struct StepExpectation {
    std::optional<QString> bytes;  // hex text: the answer's exact bytes (as typed, compared as bytes)
    QList<FieldExpectation> fields;
    std::optional<int> exception;  // the exception code of an exception response
    bool noAnswer = false;         // the device stays silent (the request times out)

    [[nodiscard]] bool isEmpty() const { return !bytes && fields.isEmpty() && !exception && !noAnswer; }

    friend bool operator==(const StepExpectation &, const StepExpectation &) = default;
};

} // namespace mbscope
