/*
 * A libmodbus client that polls one target as fast as it can: the baseline mbscope's poll is
 * compared with (tests/bench/bench_poll.cpp does the same in-process; this one is for a quick look
 * by hand and for other peers, e.g. against pymodbus_server.py).
 *
 *   libmodbus_client tcp HOST PORT   [--count N] [--unit U] [--address A] [--quantity Q] [--check]
 *   libmodbus_client rtu DEVICE BAUD [same options]
 *
 * Sends N (default 10000) Read Holding Registers (03) requests back to back, each timed with
 * CLOCK_MONOTONIC from before modbus_read_registers() to its return, and prints one line:
 *
 *   libmodbus: N transactions, E errors, T transactions/s, latency us p50 X p90 Y p99 Z max W
 *
 * --check compares every answer with peer_datamap.h's holding registers and counts a difference as
 * an error. Exit status: 0 when every transaction succeeded, 1 otherwise, 2 on usage errors.
 */
#include "peer_datamap.h"

#include <modbus.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static long long now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000000000LL + t.tv_nsec;
}

static int compare(const void *a, const void *b)
{
    const long long x = *(const long long *)a;
    const long long y = *(const long long *)b;
    return (x > y) - (x < y);
}

/* Nearest-rank percentile of sorted samples. */
static double percentile_us(const long long *sorted, int n, double p)
{
    if (n <= 0)
        return 0.0;
    int rank = (int)((p / 100.0) * n + 0.999999);
    if (rank < 1)
        rank = 1;
    if (rank > n)
        rank = n;
    return (double)sorted[rank - 1] / 1000.0;
}

static int usage(void)
{
    fprintf(stderr, "usage: libmodbus_client tcp HOST PORT [--count N] [--unit U] [--address A] [--quantity Q] [--check]\n"
                    "       libmodbus_client rtu DEVICE BAUD [options]\n");
    return 2;
}

int main(int argc, char **argv)
{
    if (argc < 4)
        return usage();
    int count = 10000, unit = PEER_UNIT, address = 0, quantity = 10, check = 0;
    for (int i = 4; i < argc; ++i) {
        if (strcmp(argv[i], "--check") == 0) {
            check = 1;
            continue;
        }
        if (i + 1 >= argc)
            return usage();
        if (strcmp(argv[i], "--count") == 0)
            count = atoi(argv[++i]);
        else if (strcmp(argv[i], "--unit") == 0)
            unit = atoi(argv[++i]);
        else if (strcmp(argv[i], "--address") == 0)
            address = atoi(argv[++i]);
        else if (strcmp(argv[i], "--quantity") == 0)
            quantity = atoi(argv[++i]);
        else
            return usage();
    }
    if (count < 1 || quantity < 1 || quantity > MODBUS_MAX_READ_REGISTERS)
        return usage();

    modbus_t *ctx = NULL;
    if (strcmp(argv[1], "tcp") == 0)
        ctx = modbus_new_tcp(argv[2], atoi(argv[3]));
    else if (strcmp(argv[1], "rtu") == 0)
        ctx = modbus_new_rtu(argv[2], atoi(argv[3]), 'N', 8, 1);
    else
        return usage();
    if (ctx == NULL) {
        fprintf(stderr, "libmodbus_client: %s\n", modbus_strerror(errno));
        return 2;
    }
    modbus_set_slave(ctx, unit);
    modbus_set_response_timeout(ctx, 1, 0);
    if (modbus_connect(ctx) != 0) {
        fprintf(stderr, "libmodbus_client: connect to %s %s: %s\n", argv[2], argv[3], modbus_strerror(errno));
        modbus_free(ctx);
        return 2;
    }

    long long *latency = malloc(sizeof(long long) * (size_t)count);
    if (latency == NULL)
        return 2;
    uint16_t values[MODBUS_MAX_READ_REGISTERS];
    int errors = 0, done = 0;
    const long long start = now_ns();
    for (int i = 0; i < count; ++i) {
        const long long t0 = now_ns();
        const int rc = modbus_read_registers(ctx, address, quantity, values);
        const long long t1 = now_ns();
        if (rc != quantity) {
            ++errors;
            continue;
        }
        if (check) {
            for (int k = 0; k < quantity; ++k) {
                if (values[k] != peer_holding_register((unsigned)(address + k))) {
                    ++errors;
                    break;
                }
            }
        }
        latency[done++] = t1 - t0;
    }
    const double seconds = (double)(now_ns() - start) / 1e9;
    qsort(latency, (size_t)done, sizeof latency[0], compare);
    printf("libmodbus: %d transactions, %d errors, %.1f transactions/s, latency us p50 %.1f p90 %.1f p99 %.1f max %.1f\n",
           count, errors, seconds > 0 ? count / seconds : 0.0, percentile_us(latency, done, 50),
           percentile_us(latency, done, 90), percentile_us(latency, done, 99), percentile_us(latency, done, 100));
    free(latency);
    modbus_close(ctx);
    modbus_free(ctx);
    return errors == 0 ? 0 : 1;
}
