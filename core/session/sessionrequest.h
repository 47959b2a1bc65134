#pragma once

#include "exchange/requestitem.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

class LinkUrl;

// One request of a session, as the user gave it: exact bytes typed as hex, or parameters of a
// form (function, unit, address, quantity or values) that RequestBuilder turns into a PDU. The
// bytes on the wire depend on the link (MBAP header, RTU CRC, ASCII LRC), so they are made when
// the link is known: toItem().
struct SessionRequest {
    enum class Kind : quint8 { Hex, Form };

    QString name;   // unique in the document: steps and polls refer to requests by name
    QString notes;
    Kind kind = Kind::Hex;
    // Hex: the text as typed ("01 03 00 79 00 16 15 DD"), sent exactly, unless complete says it
    // is a PDU to be completed for the link (then unit is its unit id).
    QString hex;
    bool complete = false;
    // Form: function 1, 2, 3, 4 (address, quantity), 5 (address, coils: one), 6 (address,
    // values: one), 15 (address, coils), 16 (address, values).
    int function = 3;
    int unit = 1;
    int address = 0;
    int quantity = 0;
    QList<quint16> values;
    QList<bool> coils;

    // The PDU of a form request, or the bytes of hex text; error says what is wrong ("quantity:
    // quantity 126 is out of range: ..."), with the parameter first.
    struct Bytes {
        QByteArray bytes;
        QString parameter; // the form parameter at fault ("quantity"), or "hex"
        QString error;
        [[nodiscard]] bool ok() const { return error.isEmpty(); }
    };
    [[nodiscard]] Bytes pdu() const;           // Form only
    [[nodiscard]] Bytes hexBytes() const;      // Hex only
    // What goes on the wire on this link, with its keys and the URL's timeout. transactionId is
    // the MBAP transaction id of a completed or built request.
    [[nodiscard]] Bytes wireBytes(const LinkUrl &url, quint16 transactionId) const;
    [[nodiscard]] static bool formSupports(int function);

    friend bool operator==(const SessionRequest &, const SessionRequest &) = default;
};

} // namespace mbscope
