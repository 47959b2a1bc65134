#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringView>

namespace mbscope {

// One reason a PDU could not be built: the parameter at fault (the builder's own parameter
// name, "quantity", "subRequests[1].recordNumber") and a self-contained message that says the
// value, what is allowed and by which function, e.g.
// "quantity 126 is out of range: Read Holding Registers reads 1-125 registers".
struct BuildError {
    QString parameter;
    QString message;

    friend bool operator==(const BuildError &, const BuildError &) = default;
};

// What RequestBuilder and ResponseBuilder return: the PDU (function code first) when every
// parameter is within the specification's limits; otherwise no bytes and every problem found,
// so a form can mark all its bad fields at once.
struct BuildResult {
    QByteArray pdu;
    QList<BuildError> errors;

    [[nodiscard]] bool isValid() const { return errors.isEmpty(); }
    [[nodiscard]] bool hasError(QStringView parameter) const;
    // The first message about parameter, or an empty string.
    [[nodiscard]] QString message(QStringView parameter) const;
    // Every problem on one line: "quantity: quantity 0 is out of range: ...; startAddress: ..."
    [[nodiscard]] QString errorString() const;
};

} // namespace mbscope
