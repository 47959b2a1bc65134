/*
 * A libmodbus server for mbscope's integration tests and benchmark.
 *
 *   libmodbus_server tcp [--port N] [--batch]            MBAP on 127.0.0.1 (port 0: the system chooses)
 *                        [--table-size N]               N items per table (default PEER_TABLE_SIZE)
 *   libmodbus_server rtu --device PATH [--baud 115200]   RTU on a serial device or pty, 8N1, unit 1
 *
 * Prints "LISTENING 127.0.0.1:PORT" (tcp) or "LISTENING PATH" (rtu) on stdout once ready, serves
 * the data map of peer_datamap.h through libmodbus's own modbus_reply (01-06, 0F, 10, 11, 16, 17;
 * other codes answer exception 01), and exits when its standard input closes (the test that started
 * it is gone) or after --lifetime seconds. On TCP it serves any number of connections at once with
 * select(), reads one request at a time per connection (libmodbus reads exactly one MBAP length),
 * so pipelined requests are answered in order, one per turn of its loop. With --batch it reads
 * everything a connection has sent and answers every whole request in it (still with modbus_reply)
 * under TCP_CORK, so the answers to pipelined requests leave together in one segment, as a
 * gateway or PLC that queues requests does: the server for pipelined throughput figures.
 * libmodbus's TCP backend answers any unit id; RTU
 * answers unit 1 and broadcasts (unit 0, no answer). After a request for another unit, libmodbus's
 * RTU backend takes the next frame on the line for that unit's answer and ignores it (right on a
 * multi-drop bus, where the other unit answers).
 */
#include "peer_datamap.h"

#include <modbus.h>

#include <errno.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

static modbus_mapping_t *make_mapping(int size)
{
    modbus_mapping_t *map = modbus_mapping_new(size, size, size, size);
    if (map == NULL)
        return NULL;
    for (unsigned a = 0; a < (unsigned)size; ++a) {
        map->tab_bits[a] = (uint8_t)peer_coil(a);
        map->tab_input_bits[a] = (uint8_t)peer_discrete_input(a);
        map->tab_registers[a] = peer_holding_register(a);
        map->tab_input_registers[a] = peer_input_register(a);
    }
    return map;
}

static int usage(void)
{
    fprintf(stderr, "usage: libmodbus_server tcp [--port N] [--batch] [--table-size N] [--lifetime S]\n"
                    "       libmodbus_server rtu --device PATH [--baud B] [--table-size N] [--lifetime S]\n");
    return 2;
}

/* True once stdin has reached its end (select said readable and read returned 0 or failed). */
static int stdin_closed(void)
{
    char buffer[256];
    const ssize_t n = read(STDIN_FILENO, buffer, sizeof buffer);
    return n <= 0;
}

/* What a --batch connection has sent that does not make a whole request yet. */
struct pending_bytes {
    size_t size;
    uint8_t data[4 * MODBUS_TCP_MAX_ADU_LENGTH];
};

/* --batch: reads what the connection has sent and answers every whole MBAP request in it. More
 * than one answer is corked (TCP_CORK) so they leave in one segment when uncorked. Returns -1 when
 * the connection is finished (closed, failed, or sent something that is not MBAP). */
static int answer_all(modbus_t *ctx, int fd, modbus_mapping_t *map, struct pending_bytes *p)
{
    const ssize_t n = recv(fd, p->data + p->size, sizeof p->data - p->size, 0);
    if (n < 0 && errno == EINTR)
        return 0;
    if (n <= 0)
        return -1;
    p->size += (size_t)n;
    size_t whole = 0;
    int requests = 0;
    while (p->size - whole >= 7) {
        const uint8_t *h = p->data + whole;
        const size_t length = (size_t)h[4] << 8 | h[5];
        /* Messaging on TCP/IP V1.0b, 3.1.3: protocol id 0, length of unit id + PDU. */
        if (h[2] != 0 || h[3] != 0 || length < 2 || length > MODBUS_TCP_MAX_ADU_LENGTH - 6)
            return -1;
        if (p->size - whole < 6 + length)
            break;
        whole += 6 + length;
        ++requests;
    }
    const int one = 1, zero = 0;
    if (requests > 1)
        setsockopt(fd, IPPROTO_TCP, TCP_CORK, &one, sizeof one);
    modbus_set_socket(ctx, fd);
    for (size_t at = 0; at < whole;) {
        const int length = 6 + (p->data[at + 4] << 8 | p->data[at + 5]);
        modbus_reply(ctx, p->data + at, length, map);
        at += (size_t)length;
    }
    if (requests > 1)
        setsockopt(fd, IPPROTO_TCP, TCP_CORK, &zero, sizeof zero);
    memmove(p->data, p->data + whole, p->size - whole);
    p->size -= whole;
    return 0;
}

static int serve_tcp(int port, int batch, time_t deadline, modbus_mapping_t *map)
{
    modbus_t *ctx = modbus_new_tcp("127.0.0.1", port);
    if (ctx == NULL) {
        fprintf(stderr, "libmodbus_server: modbus_new_tcp: %s\n", modbus_strerror(errno));
        return 1;
    }
    const int listener = modbus_tcp_listen(ctx, 16);
    if (listener < 0) {
        fprintf(stderr, "libmodbus_server: listen on port %d: %s\n", port, modbus_strerror(errno));
        modbus_free(ctx);
        return 1;
    }
    struct sockaddr_in bound;
    socklen_t length = sizeof bound;
    if (getsockname(listener, (struct sockaddr *)&bound, &length) != 0) {
        perror("libmodbus_server: getsockname");
        return 1;
    }
    printf("LISTENING 127.0.0.1:%u\n", (unsigned)ntohs(bound.sin_port));
    fflush(stdout);

    fd_set all;
    FD_ZERO(&all);
    FD_SET(listener, &all);
    FD_SET(STDIN_FILENO, &all);
    int maxfd = listener > STDIN_FILENO ? listener : STDIN_FILENO;
    uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
    static struct pending_bytes *pending[FD_SETSIZE];

    while (time(NULL) < deadline) {
        fd_set ready = all;
        struct timeval tick = {1, 0};
        const int n = select(maxfd + 1, &ready, NULL, NULL, &tick);
        if (n < 0 && errno != EINTR) {
            perror("libmodbus_server: select");
            break;
        }
        if (n <= 0)
            continue;
        if (FD_ISSET(STDIN_FILENO, &ready) && stdin_closed())
            break;
        for (int fd = 0; fd <= maxfd; ++fd) {
            if (!FD_ISSET(fd, &ready) || fd == STDIN_FILENO)
                continue;
            if (fd == listener) {
                const int client = accept(listener, NULL, NULL);
                if (client >= 0 && client < FD_SETSIZE) {
                    /* Answers to pipelined requests go out at once, not held by Nagle's algorithm
                     * until the client's delayed ACK (up to 40 ms on Linux). */
                    const int one = 1;
                    setsockopt(client, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
                    FD_SET(client, &all);
                    if (batch)
                        pending[client] = calloc(1, sizeof(struct pending_bytes));
                    if (client > maxfd)
                        maxfd = client;
                } else if (client >= 0) {
                    close(client);
                }
                continue;
            }
            if (batch) {
                if (pending[fd] == NULL || answer_all(ctx, fd, map, pending[fd]) < 0) {
                    free(pending[fd]);
                    pending[fd] = NULL;
                    close(fd);
                    FD_CLR(fd, &all);
                }
                continue;
            }
            modbus_set_socket(ctx, fd);
            const int rc = modbus_receive(ctx, query);
            if (rc > 0) {
                modbus_reply(ctx, query, rc, map);
            } else if (rc < 0) {
                close(fd);
                FD_CLR(fd, &all);
            }
        }
    }
    close(listener);
    modbus_free(ctx);
    return 0;
}

static int serve_rtu(const char *device, int baud, time_t deadline, modbus_mapping_t *map)
{
    modbus_t *ctx = modbus_new_rtu(device, baud, 'N', 8, 1);
    if (ctx == NULL) {
        fprintf(stderr, "libmodbus_server: modbus_new_rtu %s: %s\n", device, modbus_strerror(errno));
        return 1;
    }
    modbus_set_slave(ctx, PEER_UNIT);
    if (modbus_connect(ctx) != 0) {
        fprintf(stderr, "libmodbus_server: open %s: %s\n", device, modbus_strerror(errno));
        modbus_free(ctx);
        return 1;
    }
    printf("LISTENING %s\n", device);
    fflush(stdout);

    const int serial = modbus_get_socket(ctx);
    uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
    while (time(NULL) < deadline) {
        fd_set ready;
        FD_ZERO(&ready);
        FD_SET(serial, &ready);
        FD_SET(STDIN_FILENO, &ready);
        struct timeval tick = {1, 0};
        const int n = select((serial > STDIN_FILENO ? serial : STDIN_FILENO) + 1, &ready, NULL, NULL, &tick);
        if (n < 0 && errno != EINTR)
            break;
        if (n <= 0)
            continue;
        if (FD_ISSET(STDIN_FILENO, &ready) && stdin_closed())
            break;
        if (FD_ISSET(serial, &ready)) {
            const int rc = modbus_receive(ctx, query);
            if (rc > 0) {
                modbus_reply(ctx, query, rc, map);
            } else {
                /* A frame libmodbus could not use (bad CRC, a function code it cannot size, another
                 * unit's request, or the frame it then reads as that unit's answer) may leave bytes
                 * behind. A serial device resynchronises on the line's t3.5 silence (Serial Line
                 * V1.02, 2.5.1.1); libmodbus does not, so drop what is left of the frame. */
                modbus_flush(ctx);
            }
        }
    }
    modbus_close(ctx);
    modbus_free(ctx);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return usage();
    const char *mode = argv[1];
    const char *device = NULL;
    int port = 0;
    int baud = 115200;
    double lifetime = 900.0;
    int batch = 0;
    int size = PEER_TABLE_SIZE;
    for (int i = 2; i < argc; ++i) {
        if (strcmp(argv[i], "--batch") == 0) {
            batch = 1;
            continue;
        }
        if (i + 1 >= argc)
            return usage();
        if (strcmp(argv[i], "--port") == 0)
            port = atoi(argv[++i]);
        else if (strcmp(argv[i], "--device") == 0)
            device = argv[++i];
        else if (strcmp(argv[i], "--baud") == 0)
            baud = atoi(argv[++i]);
        else if (strcmp(argv[i], "--table-size") == 0)
            size = atoi(argv[++i]);
        else if (strcmp(argv[i], "--lifetime") == 0)
            lifetime = atof(argv[++i]);
        else
            return usage();
    }
    if (size < 1 || size > 65536)
        return usage();
    modbus_mapping_t *map = make_mapping(size);
    if (map == NULL) {
        fprintf(stderr, "libmodbus_server: modbus_mapping_new: %s\n", modbus_strerror(errno));
        return 1;
    }
    const time_t deadline = time(NULL) + (time_t)lifetime;
    int rc;
    if (strcmp(mode, "tcp") == 0)
        rc = serve_tcp(port, batch, deadline, map);
    else if (strcmp(mode, "rtu") == 0 && device != NULL)
        rc = serve_rtu(device, baud, deadline, map);
    else
        rc = usage();
    modbus_mapping_free(map);
    return rc;
}
