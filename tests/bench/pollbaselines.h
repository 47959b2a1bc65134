#pragma once

#include <QtCore/QString>

#include <vector>

namespace mbscope::bench {

// What one client achieved polling the server: every transaction's latency, the wall time of the
// measured run and how many transactions failed.
struct PollFigures {
    QString client;
    QString note;
    long long transactions = 0;
    long long errors = 0;
    double seconds = 0.0;
    std::vector<long long> latencyNs; // successful transactions only

    [[nodiscard]] double perSecond() const { return seconds > 0.0 ? double(transactions) / seconds : 0.0; }
    // Adds one round of the same client (transactions, errors, time and latencies add up).
    void absorb(const PollFigures &round);
    // Nearest-rank percentile in microseconds (p in 0..100); sorts latencyNs on first use.
    [[nodiscard]] double percentileUs(double p);
};

// The same Read Holding Registers request for every client: unit 1, start address 0, quantity
// registers (peer_datamap.h: holding register a is 1000 + 3a, so answers can be checked).
struct PollPlan {
    unsigned short port = 0;
    int quantity = 10;
    long long count = 20000;
    long long warmup = 500;   // transactions first sent and not measured (connection, caches)
};

// The floor: a blocking socket loop that sends a fixed 12-byte MBAP request, reads the 7-byte
// header, then the length it announces, and checks the transaction id. No framing, no matching
// beyond that, no record: what the kernel and the server cost.
[[nodiscard]] PollFigures pollRawSocket(const PollPlan &plan);
// libmodbus's modbus_read_registers() in a loop (its own framing, checks and timeouts).
[[nodiscard]] PollFigures pollLibmodbus(const PollPlan &plan);
// The values a successful read must hold.
[[nodiscard]] bool registersMatchDataMap(const unsigned short *values, int quantity);

} // namespace mbscope::bench
