#include "pollbaselines.h"

#include "peer_datamap.h"

#include <modbus.h>

#include <algorithm>
#include <arpa/inet.h>
#include <cerrno>
#include <cmath>
#include <ctime>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace mbscope::bench {

namespace {

long long nowNs()
{
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000000000LL + t.tv_nsec;
}

bool sendAll(int fd, const unsigned char *data, size_t size)
{
    while (size > 0) {
        const ssize_t n = ::send(fd, data, size, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        data += n;
        size -= size_t(n);
    }
    return true;
}

bool receiveAll(int fd, unsigned char *data, size_t size)
{
    while (size > 0) {
        const ssize_t n = ::recv(fd, data, size, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        data += n;
        size -= size_t(n);
    }
    return true;
}

} // namespace

double PollFigures::percentileUs(double p)
{
    if (latencyNs.empty())
        return 0.0;
    if (!std::is_sorted(latencyNs.begin(), latencyNs.end()))
        std::sort(latencyNs.begin(), latencyNs.end());
    const auto n = (long long)latencyNs.size();
    long long rank = (long long)std::ceil(p / 100.0 * double(n));
    rank = std::clamp(rank, 1LL, n);
    return double(latencyNs[size_t(rank - 1)]) / 1000.0;
}

void PollFigures::absorb(const PollFigures &round)
{
    if (client.isEmpty())
        client = round.client;
    if (note.isEmpty())
        note = round.note;
    transactions += round.transactions;
    errors += round.errors;
    seconds += round.seconds;
    latencyNs.insert(latencyNs.end(), round.latencyNs.begin(), round.latencyNs.end());
}

bool registersMatchDataMap(const unsigned short *values, int quantity)
{
    for (int a = 0; a < quantity; ++a) {
        if (values[a] != peer_holding_register(unsigned(a)))
            return false;
    }
    return true;
}

PollFigures pollRawSocket(const PollPlan &plan)
{
    PollFigures f;
    f.client = QStringLiteral("raw socket loop");
    f.note = QStringLiteral("blocking send/recv, TCP_NODELAY");
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) {
        f.errors = plan.count;
        return f;
    }
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(plan.port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) != 0) {
        ::close(fd);
        f.errors = plan.count;
        return f;
    }
    // MBAP header (Messaging on TCP/IP V1.0b, 3.1.3) + 03 request (V1.1b3, 6.3).
    unsigned char request[12] = {0, 0, 0, 0, 0, 6, PEER_UNIT, 0x03, 0, 0, 0, (unsigned char)plan.quantity};
    unsigned char response[260];
    f.latencyNs.reserve(size_t(plan.count));
    long long start = 0;
    for (long long i = -plan.warmup; i < plan.count; ++i) {
        if (i == 0)
            start = nowNs();
        const unsigned short tid = (unsigned short)(i & 0xFFFF);
        request[0] = (unsigned char)(tid >> 8);
        request[1] = (unsigned char)(tid & 0xFF);
        const long long t0 = nowNs();
        bool ok = sendAll(fd, request, sizeof request) && receiveAll(fd, response, 7);
        const size_t length = ok ? (size_t(response[4]) << 8 | response[5]) : 0;
        ok = ok && length >= 2 && length <= 254 && receiveAll(fd, response + 7, length - 1);
        const long long t1 = nowNs();
        ok = ok && response[0] == request[0] && response[1] == request[1] && response[7] == 0x03
             && response[8] == 2 * plan.quantity;
        if (i < 0)
            continue;
        if (!ok) {
            ++f.errors;
            if (length == 0)
                break; // the connection is gone
            continue;
        }
        f.latencyNs.push_back(t1 - t0);
    }
    f.seconds = double(nowNs() - start) / 1e9;
    f.transactions = plan.count;
    ::close(fd);
    return f;
}

PollFigures pollLibmodbus(const PollPlan &plan)
{
    PollFigures f;
    f.client = QStringLiteral("libmodbus client");
    f.note = QString::fromLatin1(LIBMODBUS_VERSION_STRING) + QStringLiteral(", modbus_read_registers");
    modbus_t *ctx = modbus_new_tcp("127.0.0.1", plan.port);
    if (ctx == nullptr) {
        f.errors = plan.count;
        return f;
    }
    modbus_set_slave(ctx, PEER_UNIT);
    modbus_set_response_timeout(ctx, 1, 0);
    if (modbus_connect(ctx) != 0) {
        modbus_free(ctx);
        f.errors = plan.count;
        return f;
    }
    unsigned short values[MODBUS_MAX_READ_REGISTERS];
    f.latencyNs.reserve(size_t(plan.count));
    long long start = 0;
    for (long long i = -plan.warmup; i < plan.count; ++i) {
        if (i == 0)
            start = nowNs();
        const long long t0 = nowNs();
        const int rc = modbus_read_registers(ctx, 0, plan.quantity, values);
        const long long t1 = nowNs();
        if (i < 0)
            continue;
        if (rc != plan.quantity || !registersMatchDataMap(values, plan.quantity)) {
            ++f.errors;
            continue;
        }
        f.latencyNs.push_back(t1 - t0);
    }
    f.seconds = double(nowNs() - start) / 1e9;
    f.transactions = plan.count;
    modbus_close(ctx);
    modbus_free(ctx);
    return f;
}

} // namespace mbscope::bench
