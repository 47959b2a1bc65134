#pragma once

#include "exchange/requestitem.h"
#include "protocol/registerformat.h"

#include <QtCore/QCommandLineOption>
#include <QtCore/QList>
#include <QtCore/QString>

class QCommandLineParser;
class QTextStream;

namespace mbscope::app {

struct TargetSettings;

// One request the options describe, in the target's framing, with what the output needs to show
// its values.
struct PlannedRequest {
    RequestItem item;
    QString description;     // "Read Holding Registers, unit 1, 22 registers at 121 (0x0079), 40122-40143"
    quint8 functionCode = 0; // of a built request; 0 for --hex
    quint8 unit = 1;         // of a built request
    int address = 0;         // first register or coil
    int quantity = 0;        // registers or bits read or written
    QList<quint16> registers; // the values a register write sends
    QList<bool> coils;        // the values a coil write sends
    bool oneBased = false;    // the user counts registers from 1 (--one-based): outputs say so
};

struct RequestPlan {
    QList<PlannedRequest> requests;
    QList<RegisterFormat> formats; // --format: how register values are shown (read) or typed (write)
    bool built = false;            // requests built from parameters (read/write options), not --hex
    QString summary;               // built requests: what they read or write, all together
    bool oneBased = false;         // --one-based: addresses typed and shown counted from 1
};

// The options that say what to send, in three groups a subcommand picks from:
//   Hex:   --hex HEX [--complete]  (exact bytes, or a PDU completed for the target's framing)
//   Read:  --function 1|2|3|4 --address A --quantity N [--format F,...]
//          or mbpoll's -t 0|1|3|4[:hex|:int|:float] [-B] instead of --function (TableType)
//   Write: --coils 1,0,... | --registers V,... --address A [--single] [--format F]
// plus --unit for built and completed requests, and --one-based (-0/--zero-based, the default,
// says the contrary) for the addresses of Read and Write. Short forms as mbpoll's where they
// mean the same: -a unit, -r address (reference), -c quantity, -t table, -B, -0. A subcommand with several groups (poll, sweep)
// takes one of them per run. Requests are built with RequestBuilder; its errors are reported with
// the option at fault ("--quantity: quantity 126 is out of range: ...").
class RequestOptions
{
public:
    enum Group { Hex = 1, Read = 2, Write = 4 };

    // repeatHex: --hex may be given several times, one request each (a poll's items, in order).
    explicit RequestOptions(int groups, bool repeatHex = false);

    void addTo(QCommandLineParser &parser) const;
    // Reads the options and builds the requests for the target; on error writes
    // "mbscope COMMAND: ..." to err and returns false.
    [[nodiscard]] bool read(const QCommandLineParser &parser, const QString &command, const TargetSettings &target,
                            RequestPlan &out, QTextStream &err) const;

private:
    bool readHex(const QCommandLineParser &parser, const TargetSettings &target, RequestPlan &out,
                 QString &error) const;
    bool readRead(const QCommandLineParser &parser, const TargetSettings &target, RequestPlan &out,
                  QString &error) const;
    bool readWrite(const QCommandLineParser &parser, const TargetSettings &target, RequestPlan &out,
                   QString &error) const;
    bool readUnit(const QCommandLineParser &parser, int &unit, QString &error) const;
    // The PDU address --address gives (one less with --one-based).
    bool readAddress(const QCommandLineParser &parser, bool oneBased, int &address, QString &error) const;

    int m_groups;
    bool m_repeatHex;
    QCommandLineOption m_hex;
    QCommandLineOption m_complete;
    QCommandLineOption m_unit;
    QCommandLineOption m_function;
    QCommandLineOption m_address;
    QCommandLineOption m_quantity;
    QCommandLineOption m_format;
    QCommandLineOption m_coils;
    QCommandLineOption m_registers;
    QCommandLineOption m_single;
    QCommandLineOption m_table;
    QCommandLineOption m_bigEndian;
    QCommandLineOption m_oneBased;
    QCommandLineOption m_zeroBased;
};

// The bytes of a frame typed for a target: hex ("01 03 00 79 00 16 15 DD"), or on an ASCII link
// the frame's characters (":010300790016..."; CR LF added when missing).
struct FrameTextResult {
    QByteArray bytes;
    QString error; // with line and column, and a caret line under the culprit
    bool ok = false;
};
[[nodiscard]] FrameTextResult parseFrameText(const QString &text, bool asciiCharacters);

// A built request to an address of 10001 or more answered with exception 02 (Illegal Data
// Address): "40122 looks like a Modicon reference; its PDU address is 121 (0x0079): give
// --address 121"; and to an address that looks counted from 1 (1, 11, 101, 1001...: a block of a
// manual that numbers registers from 1 starts there) without --one-based: "... give --address 0,
// or --one-based ...". Empty for every other request and answer.
[[nodiscard]] QString addressHintFor(const PlannedRequest &request, quint8 exceptionCode, bool exception);

} // namespace mbscope::app
