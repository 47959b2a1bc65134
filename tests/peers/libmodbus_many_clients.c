/*
 * N libmodbus clients at once against one Modbus TCP server: the load of bench_simthroughput
 * (issue 15, "Also": 50 libmodbus clients x 1000 requests). Each client is a thread with its own
 * modbus_t and connection; all connect first, then start together (a barrier), and each sends its
 * Read Holding Registers (03) requests back to back, every one timed with CLOCK_MONOTONIC from
 * before modbus_read_registers() to its return.
 *
 *   libmodbus_many_clients HOST PORT [--clients N] [--requests M] [--seconds S] [--quantity Q] [--span S]
 *                          [--timeout MS] [--check]
 *
 * Client c's request k reads Q registers at (7c + 13k) % S (default S 90, Q 10: inside a 100-register
 * table). --check compares every answer with peer_datamap.h's holding registers (1000 + 3a) and
 * counts a difference as an error. --seconds: each client sends until that long has passed since
 * the start (a soak; --requests is then ignored). --timeout: libmodbus's response timeout (default
 * 5000 ms). Prints one line:
 *
 *   clients N requests M transactions T errors E seconds S tps X p50 A p90 B p99 C max D
 *
 * (T: every request sent, M: T / N; latencies in microseconds, over every answered transaction of
 * every client; seconds from the start barrier to the last client's end). Exit status 0 when every
 * transaction succeeded, 1 otherwise, 2 on usage or connection errors.
 */
#include "peer_datamap.h"

#include <modbus.h>

#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

struct client {
    modbus_t *ctx;
    int index;
    long long *latency;
    long capacity;
    long done;
    long sent;
    int errors;
};

static const char *g_host;
static int g_port;
static int g_requests = 1000, g_quantity = 10, g_span = 90, g_check = 0, g_timeout_ms = 5000;
static double g_seconds = 0;
static long long g_start_ns;
static pthread_barrier_t g_start;

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

/* Nearest-rank percentile of sorted samples, in microseconds. */
static double percentile_us(const long long *sorted, long n, double p)
{
    if (n <= 0)
        return 0.0;
    long rank = (long)((p / 100.0) * (double)n + 0.999999);
    if (rank < 1)
        rank = 1;
    if (rank > n)
        rank = n;
    return (double)sorted[rank - 1] / 1000.0;
}

static void *run_client(void *arg)
{
    struct client *c = arg;
    uint16_t values[MODBUS_MAX_READ_REGISTERS];
    pthread_barrier_wait(&g_start);
    const long long end = g_start_ns + (long long)(g_seconds * 1e9);
    for (long k = 0; g_seconds > 0 ? now_ns() < end : k < g_requests; ++k) {
        const int address = (int)((7 * c->index + 13 * k) % g_span);
        ++c->sent;
        const long long t0 = now_ns();
        const int rc = modbus_read_registers(c->ctx, address, g_quantity, values);
        const long long t1 = now_ns();
        if (rc != g_quantity) {
            ++c->errors;
            if (c->errors == 1)
                fprintf(stderr, "libmodbus_many_clients: client %d request %ld: %s\n", c->index, k,
                        rc < 0 ? modbus_strerror(errno) : "short answer");
            continue;
        }
        if (g_check) {
            for (int i = 0; i < g_quantity; ++i) {
                if (values[i] != peer_holding_register((unsigned)(address + i))) {
                    ++c->errors;
                    break;
                }
            }
        }
        if (c->done == c->capacity) {
            c->capacity *= 2;
            long long *grown = realloc(c->latency, sizeof(long long) * (size_t)c->capacity);
            if (grown == NULL) {
                ++c->errors;
                return NULL;
            }
            c->latency = grown;
        }
        c->latency[c->done++] = t1 - t0;
    }
    return NULL;
}

static int usage(void)
{
    fprintf(stderr, "usage: libmodbus_many_clients HOST PORT [--clients N] [--requests M] [--seconds S] [--quantity Q] [--span S] "
                    "[--timeout MS] [--check]\n");
    return 2;
}

int main(int argc, char **argv)
{
    if (argc < 3)
        return usage();
    g_host = argv[1];
    g_port = atoi(argv[2]);
    int clients = 50;
    for (int i = 3; i < argc; ++i) {
        if (strcmp(argv[i], "--check") == 0) {
            g_check = 1;
            continue;
        }
        if (i + 1 >= argc)
            return usage();
        if (strcmp(argv[i], "--clients") == 0)
            clients = atoi(argv[++i]);
        else if (strcmp(argv[i], "--requests") == 0)
            g_requests = atoi(argv[++i]);
        else if (strcmp(argv[i], "--quantity") == 0)
            g_quantity = atoi(argv[++i]);
        else if (strcmp(argv[i], "--span") == 0)
            g_span = atoi(argv[++i]);
        else if (strcmp(argv[i], "--seconds") == 0)
            g_seconds = atof(argv[++i]);
        else if (strcmp(argv[i], "--timeout") == 0)
            g_timeout_ms = atoi(argv[++i]);
        else
            return usage();
    }
    if (g_port <= 0 || clients < 1 || g_requests < 1 || g_quantity < 1 || g_quantity > MODBUS_MAX_READ_REGISTERS || g_span < 1
        || g_seconds < 0 || g_timeout_ms < 1)
        return usage();

    struct client *all = calloc((size_t)clients, sizeof *all);
    pthread_t *threads = calloc((size_t)clients, sizeof *threads);
    if (all == NULL || threads == NULL)
        return 2;
    for (int c = 0; c < clients; ++c) {
        all[c].index = c;
        all[c].capacity = g_seconds > 0 ? 4096 : g_requests;
        all[c].latency = malloc(sizeof(long long) * (size_t)all[c].capacity);
        all[c].ctx = modbus_new_tcp(g_host, g_port);
        if (all[c].latency == NULL || all[c].ctx == NULL)
            return 2;
        modbus_set_slave(all[c].ctx, PEER_UNIT);
        modbus_set_response_timeout(all[c].ctx, (uint32_t)(g_timeout_ms / 1000), (uint32_t)(g_timeout_ms % 1000) * 1000);
        if (modbus_connect(all[c].ctx) != 0) {
            fprintf(stderr, "libmodbus_many_clients: client %d: connect to %s:%d: %s\n", c, g_host, g_port, modbus_strerror(errno));
            return 2;
        }
    }
    pthread_barrier_init(&g_start, NULL, (unsigned)clients + 1);
    for (int c = 0; c < clients; ++c) {
        if (pthread_create(&threads[c], NULL, run_client, &all[c]) != 0) {
            fprintf(stderr, "libmodbus_many_clients: cannot start thread %d\n", c);
            return 2;
        }
    }
    g_start_ns = now_ns(); /* before the barrier: the clients read it once it opens */
    pthread_barrier_wait(&g_start);
    const long long start = g_start_ns;
    for (int c = 0; c < clients; ++c)
        pthread_join(threads[c], NULL);
    const double seconds = (double)(now_ns() - start) / 1e9;

    long total = 0;
    long transactions = 0;
    int errors = 0;
    for (int c = 0; c < clients; ++c) {
        total += all[c].done;
        transactions += all[c].sent;
        errors += all[c].errors;
    }
    long long *latency = malloc(sizeof(long long) * (size_t)(total > 0 ? total : 1));
    if (latency == NULL)
        return 2;
    long at = 0;
    for (int c = 0; c < clients; ++c) {
        memcpy(latency + at, all[c].latency, sizeof(long long) * (size_t)all[c].done);
        at += all[c].done;
        modbus_close(all[c].ctx);
        modbus_free(all[c].ctx);
        free(all[c].latency);
    }
    qsort(latency, (size_t)total, sizeof latency[0], compare);
    printf("clients %d requests %ld transactions %ld errors %d seconds %.3f tps %.1f p50 %.1f p90 %.1f p99 %.1f max %.1f\n",
           clients, transactions / clients, transactions, errors, seconds, seconds > 0 ? (double)transactions / seconds : 0.0,
           percentile_us(latency, total, 50), percentile_us(latency, total, 90), percentile_us(latency, total, 99),
           percentile_us(latency, total, 100));
    free(latency);
    free(all);
    free(threads);
    pthread_barrier_destroy(&g_start);
    return errors == 0 ? 0 : 1;
}
