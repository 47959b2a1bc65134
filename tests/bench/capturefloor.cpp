// The floor for offline analysis: read a pcapng and pair Modbus TCP requests with their
// answers, nothing else, in plain C (compiled as C++ only to share the project's flags). See
// capturefloor.h.
#include "capturefloor.h"

#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const size_t kChunk = size_t(1) << 20;

static uint32_t le32(const unsigned char *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24; }
static uint16_t be16(const unsigned char *p) { return (uint16_t)(p[0] << 8 | p[1]); }

static void packet(const unsigned char *d, uint32_t len, long long ns, unsigned short port, long long *starts,
                   struct CaptureFloorResult *r)
{
    if (len < 14 + 20 + 20 || be16(d + 12) != 0x0800 || d[14 + 9] != 6)
        return;
    const unsigned ip = (unsigned)(d[14] & 0x0f) * 4;
    const unsigned char *tcp = d + 14 + ip;
    const unsigned th = (unsigned)(tcp[12] >> 4) * 4;
    const long total = (long)be16(d + 16) + 14;
    const unsigned char *p = tcp + th;
    const unsigned char *end = d + (total < (long)len ? total : (long)len);
    const int request = be16(tcp + 2) == port;
    if (!request && be16(tcp) != port)
        return;
    while (end - p >= 8) { /* every MBAP frame of the segment */
        const uint16_t tid = be16(p);
        const long frame = 6 + (long)be16(p + 4);
        if (request) {
            starts[tid] = ns;
            ++r->requests;
        } else if (starts[tid] >= 0) {
            r->latencyNsSum += ns - starts[tid];
            starts[tid] = -1;
            ++r->pairs;
        }
        p += frame;
    }
}

struct CaptureFloorResult captureFloorRun(const char *path, unsigned short serverPort)
{
    struct CaptureFloorResult r;
    memset(&r, 0, sizeof r);
    const int fd = open(path, O_RDONLY);
    if (fd < 0) {
        r.error = 1;
        return r;
    }
    long long *starts = static_cast<long long *>(malloc(sizeof(long long) * 65536));
    for (int i = 0; i < 65536; ++i)
        starts[i] = -1;
    unsigned char *buf = static_cast<unsigned char *>(malloc(2 * kChunk));
    size_t have = 0, at = 0;
    int eof = 0;
    unsigned long long tsPerSecond = 1000000; /* if_tsresol: microseconds unless the interface says */
    for (;;) {
        if (have - at < 8 || have - at < le32(buf + at + 4)) {
            memmove(buf, buf + at, have - at);
            have -= at;
            at = 0;
            if (eof)
                break;
            const ssize_t got = read(fd, buf + have, 2 * kChunk - have);
            if (got <= 0)
                eof = 1;
            else
                have += (size_t)got;
            continue;
        }
        const unsigned char *b = buf + at;
        const uint32_t type = le32(b);
        const uint32_t length = le32(b + 4);
        if (length < 12 || length > kChunk) {
            r.error = 3;
            break;
        }
        if (type == 0x0a0d0d0a && le32(b + 8) != 0x1a2b3c4d) {
            r.error = 2;
            break;
        }
        if (type == 1) { /* interface description: find if_tsresol (9) among the options */
            const unsigned char *o = b + 16;
            while (o + 4 <= b + length - 4 && be16(o) != 0) {
                const unsigned code = (unsigned)(o[0] | o[1] << 8), olen = (unsigned)(o[2] | o[3] << 8);
                if (code == 9 && olen == 1 && !(o[4] & 0x80)) {
                    tsPerSecond = 1;
                    for (int i = 0; i < o[4]; ++i)
                        tsPerSecond *= 10;
                }
                o += 4 + ((olen + 3) & ~3u);
            }
        } else if (type == 6) { /* enhanced packet */
            const unsigned long long ts = (unsigned long long)le32(b + 12) << 32 | le32(b + 16);
            const long long ns = (long long)(ts / tsPerSecond * 1000000000ULL + ts % tsPerSecond * 1000000000ULL / tsPerSecond);
            ++r.packets;
            packet(b + 28, le32(b + 20), ns, serverPort, starts, &r);
        }
        at += length;
    }
    free(buf);
    free(starts);
    close(fd);
    return r;
}
