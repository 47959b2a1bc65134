/*
 * A libmodbus client that calls every function code libmodbus has against
 * `mbscope simulate --profile conformance` and checks each answer against the profile
 * (resources/profiles/conformance.json): 01, 02, 03, 04, 05, 06, 0F, 10, 11, 16 and 17, writes
 * read back, and the exceptions the profile's map implies.
 *
 *   libmodbus_conformance tcp HOST PORT
 *   libmodbus_conformance rtu DEVICE BAUD      (8N1)
 *
 * Prints one "ok ..." line per check and "done" at the end; the first failed check prints
 * "FAIL what: got ..., expected ..." and exits 1. Usage or connection errors exit 2.
 */
#include <modbus.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static modbus_t *ctx;

static void fail(const char *what, const char *got, const char *expected)
{
    printf("FAIL %s: got %s, expected %s\n", what, got, expected);
    fflush(stdout);
    modbus_close(ctx);
    modbus_free(ctx);
    exit(1);
}

static void ok(const char *what)
{
    printf("ok %s\n", what);
    fflush(stdout);
}

/* A call that must succeed and return rc (a count of items, or 1 for single writes). */
static void expect_rc(const char *what, int rc, int expected)
{
    if (rc == expected)
        return;
    char got[160];
    char want[32];
    if (rc < 0)
        snprintf(got, sizeof got, "error '%s'", modbus_strerror(errno));
    else
        snprintf(got, sizeof got, "%d", rc);
    snprintf(want, sizeof want, "%d", expected);
    fail(what, got, want);
}

/* A call the server must refuse with the given exception (libmodbus: EMBXILFUN, EMBXILADD...). */
static void expect_exception(const char *what, int rc, int code)
{
    if (rc == -1 && errno == code) {
        ok(what);
        return;
    }
    char got[160];
    if (rc == -1)
        snprintf(got, sizeof got, "error '%s'", modbus_strerror(errno));
    else
        snprintf(got, sizeof got, "success (%d)", rc);
    fail(what, got, modbus_strerror(code));
}

static void expect_registers(const char *what, const uint16_t *got, const uint16_t *expected, int count)
{
    for (int i = 0; i < count; ++i) {
        if (got[i] != expected[i]) {
            char g[48], e[48];
            snprintf(g, sizeof g, "%u at index %d", got[i], i);
            snprintf(e, sizeof e, "%u", expected[i]);
            fail(what, g, e);
        }
    }
    ok(what);
}

static void expect_bits(const char *what, const uint8_t *got, const uint8_t *expected, int count)
{
    for (int i = 0; i < count; ++i) {
        if ((got[i] != 0) != (expected[i] != 0)) {
            char g[48], e[48];
            snprintf(g, sizeof g, "%u at index %d", got[i], i);
            snprintf(e, sizeof e, "%u", expected[i]);
            fail(what, g, e);
        }
    }
    ok(what);
}

/* The profile's unit 1 (conformance.json): holding 0-99 = 1000 + 3a, input 0-99 = 40000 + 2a,
 * coil a ON when a % 3 == 0, discrete input a ON when a is odd. */
static uint16_t holding(int a) { return (uint16_t)(1000 + 3 * a); }
static uint16_t input(int a) { return (uint16_t)(40000 + 2 * a); }
static uint8_t coil(int a) { return a % 3 == 0; }
static uint8_t discrete(int a) { return a % 2 == 1; }

static void reads(void)
{
    uint8_t bits[100], want_bits[100];
    uint16_t regs[125], want[125];

    expect_rc("01 read coils 0-99", modbus_read_bits(ctx, 0, 100, bits), 100);
    for (int a = 0; a < 100; ++a)
        want_bits[a] = coil(a);
    expect_bits("01 coils 0-99 ON where a % 3 == 0", bits, want_bits, 100);

    expect_rc("02 read discrete inputs 5-41", modbus_read_input_bits(ctx, 5, 37, bits), 37);
    for (int a = 5; a < 42; ++a)
        want_bits[a - 5] = discrete(a);
    expect_bits("02 discrete inputs 5-41 ON where a is odd", bits, want_bits, 37);

    expect_rc("03 read holding registers 0-99", modbus_read_registers(ctx, 0, 100, regs), 100);
    for (int a = 0; a < 100; ++a)
        want[a] = holding(a);
    expect_registers("03 holding registers 0-99 = 1000 + 3a", regs, want, 100);

    /* The typed block: f32 123.456 ABCD and CDAB, u32 0x12345678, i32 -2, i16 -12.5 / 0.1,
     * u16 (1013.25 - 900) / 0.01, f64 pi, "MBSCOPE ". */
    const uint16_t typed[18] = {0x42F6, 0xE979, 0xE979, 0x42F6, 0x1234, 0x5678, 0xFFFF, 0xFFFE, 0xFF83, 11325,
                                0x4009, 0x21FB, 0x5444, 0x2D18, 0x4D42, 0x5343, 0x4F50, 0x4520};
    expect_rc("03 read typed registers 200-217", modbus_read_registers(ctx, 200, 18, regs), 18);
    expect_registers("03 typed registers 200-217 as the profile encodes them", regs, typed, 18);

    expect_rc("04 read input registers 10-29", modbus_read_input_registers(ctx, 10, 20, regs), 20);
    for (int a = 10; a < 30; ++a)
        want[a - 10] = input(a);
    expect_registers("04 input registers 10-29 = 40000 + 2a", regs, want, 20);

    expect_rc("03 read-only block 300-309", modbus_read_registers(ctx, 300, 10, regs), 10);
    for (int i = 0; i < 10; ++i)
        want[i] = 7;
    expect_registers("03 read-only block 300-309 = 7", regs, want, 10);
}

static void writes(void)
{
    uint8_t bits[16];
    uint16_t regs[16];

    expect_rc("05 write coil 1 ON", modbus_write_bit(ctx, 1, 1), 1);
    expect_rc("05 write coil 3 OFF", modbus_write_bit(ctx, 3, 0), 1);
    expect_rc("01 read back coils 0-4", modbus_read_bits(ctx, 0, 5, bits), 5);
    expect_bits("05 coils 0-4 read back", bits, (const uint8_t[]){1, 1, 0, 0, 0}, 5);

    expect_rc("06 write register 7", modbus_write_register(ctx, 7, 4242), 1);
    expect_rc("03 read back register 6-8", modbus_read_registers(ctx, 6, 3, regs), 3);
    expect_registers("06 register 7 read back, neighbours untouched", regs,
                     (const uint16_t[]){holding(6), 4242, holding(8)}, 3);

    const uint8_t pattern[11] = {1, 0, 1, 1, 0, 0, 1, 0, 1, 1, 1};
    expect_rc("0F write coils 10-20", modbus_write_bits(ctx, 10, 11, pattern), 11);
    expect_rc("01 read back coils 9-21", modbus_read_bits(ctx, 9, 13, bits), 13);
    expect_bits("0F coils 10-20 read back, 9 and 21 untouched", bits,
                (const uint8_t[]){coil(9), 1, 0, 1, 1, 0, 0, 1, 0, 1, 1, 1, coil(21)}, 13);

    const uint16_t values[5] = {1, 2, 3, 0xFFFF, 0x8000};
    expect_rc("10 write registers 20-24", modbus_write_registers(ctx, 20, 5, values), 5);
    expect_rc("03 read back registers 19-25", modbus_read_registers(ctx, 19, 7, regs), 7);
    expect_registers("10 registers 20-24 read back, 19 and 25 untouched", regs,
                     (const uint16_t[]){holding(19), 1, 2, 3, 0xFFFF, 0x8000, holding(25)}, 7);

    /* V1.1b3 6.16's example: current 0x0012, AND 0x00F2, OR 0x0025 gives 0x0017. */
    expect_rc("06 set register 4 to 0x0012", modbus_write_register(ctx, 4, 0x0012), 1);
    expect_rc("16 mask write register 4", modbus_mask_write_register(ctx, 4, 0x00F2, 0x0025), 1);
    expect_rc("03 read back register 4", modbus_read_registers(ctx, 4, 1, regs), 1);
    expect_registers("16 register 4 = (0x12 AND 0xF2) OR (0x25 AND NOT 0xF2) = 0x17", regs,
                     (const uint16_t[]){0x0017}, 1);

    /* 17 writes before it reads (V1.1b3 6.17): the read overlapping the write sees the new values. */
    const uint16_t written[3] = {111, 222, 333};
    expect_rc("17 write 40-42 and read 38-45", modbus_write_and_read_registers(ctx, 40, 3, written, 38, 8, regs), 8);
    expect_registers("17 read sees its own write", regs,
                     (const uint16_t[]){holding(38), holding(39), 111, 222, 333, holding(43), holding(44), holding(45)}, 8);
    expect_rc("03 read back registers 40-42", modbus_read_registers(ctx, 40, 3, regs), 3);
    expect_registers("17 write read back", regs, written, 3);
}

static void report_server_id(void)
{
    uint8_t data[MODBUS_MAX_PDU_LENGTH];
    /* The profile's serverId: id 4D 42, running (FF), additional data "mbscope conformance". */
    static const char additional[] = "mbscope conformance";
    uint8_t want[64] = {0x4D, 0x42, 0xFF};
    memcpy(want + 3, additional, sizeof additional - 1);
    const int length = 3 + (int)(sizeof additional - 1);
    expect_rc("11 report server id: byte count", modbus_report_slave_id(ctx, sizeof data, data), length);
    for (int i = 0; i < length; ++i) {
        if (data[i] != want[i]) {
            char g[48], e[48];
            snprintf(g, sizeof g, "0x%02X at byte %d", data[i], i);
            snprintf(e, sizeof e, "0x%02X", want[i]);
            fail("11 server id, run indicator and additional data", g, e);
        }
    }
    ok("11 server id 4D 42, running, \"mbscope conformance\"");
}

static void exceptions(void)
{
    uint16_t regs[8];
    uint8_t bits[8];
    /* 100-199 are not in the map. */
    expect_exception("03 at 100 (outside the map): exception 02", modbus_read_registers(ctx, 100, 1, regs), EMBXILADD);
    expect_exception("03 over 98-101 (runs past the map): exception 02", modbus_read_registers(ctx, 98, 4, regs), EMBXILADD);
    expect_exception("06 into the read-only block 300: exception 02", modbus_write_register(ctx, 300, 1), EMBXILADD);
    expect_exception("16 into the read-only block 305: exception 02", modbus_mask_write_register(ctx, 305, 0, 1), EMBXILADD);
    expect_exception("02 at 100 (outside the map): exception 02", modbus_read_input_bits(ctx, 100, 1, bits), EMBXILADD);
    expect_rc("03 read-only block unchanged", modbus_read_registers(ctx, 300, 1, regs), 1);
    if (regs[0] != 7)
        fail("read-only register 300 after refused writes", "changed", "7");
    ok("read-only register 300 still 7");

    /* Unit 2 answers 03 only. */
    modbus_set_slave(ctx, 2);
    expect_rc("unit 2: 03 read holding registers 0-9", modbus_read_registers(ctx, 0, 8, regs), 8);
    expect_registers("unit 2: holding registers 0-7 = 2000 + a", regs,
                     (const uint16_t[]){2000, 2001, 2002, 2003, 2004, 2005, 2006, 2007}, 8);
    expect_exception("unit 2: 01 refused with exception 01", modbus_read_bits(ctx, 0, 1, bits), EMBXILFUN);
    expect_exception("unit 2: 17 refused with exception 01",
                     modbus_write_and_read_registers(ctx, 0, 1, regs, 0, 1, regs), EMBXILFUN);
    modbus_set_slave(ctx, 1);
}

static int usage(void)
{
    fprintf(stderr, "usage: libmodbus_conformance tcp HOST PORT\n"
                    "       libmodbus_conformance rtu DEVICE BAUD\n");
    return 2;
}

int main(int argc, char **argv)
{
    if (argc != 4)
        return usage();
    if (strcmp(argv[1], "tcp") == 0)
        ctx = modbus_new_tcp(argv[2], atoi(argv[3]));
    else if (strcmp(argv[1], "rtu") == 0)
        ctx = modbus_new_rtu(argv[2], atoi(argv[3]), 'N', 8, 1);
    else
        return usage();
    if (ctx == NULL) {
        fprintf(stderr, "libmodbus_conformance: %s\n", modbus_strerror(errno));
        return 2;
    }
    modbus_set_slave(ctx, 1);
    modbus_set_response_timeout(ctx, 5, 0);
    if (modbus_connect(ctx) != 0) {
        fprintf(stderr, "libmodbus_conformance: connect to %s %s: %s\n", argv[2], argv[3], modbus_strerror(errno));
        modbus_free(ctx);
        return 2;
    }
    reads();
    writes();
    report_server_id();
    exceptions();
    modbus_close(ctx);
    modbus_free(ctx);
    printf("done\n");
    return 0;
}
