/*
 * The data every test peer serves (pymodbus_server.py, fault_server.py, libmodbus_server.c), so a
 * test can check the values it reads without asking the peer. Plain C so the libmodbus peer and the
 * C++ tests share one definition; pymodbus_server.py and fault_server.py spell the same formulas
 * (keep the three in step).
 *
 * Every table holds PEER_TABLE_SIZE items, addresses 0 .. PEER_TABLE_SIZE-1 (PDU addresses, as on
 * the wire: MODBUS Application Protocol Specification V1.1b3, 4.4, "numbered from 0"). Reading past
 * the end answers exception 02 (illegal data address). Writes change the peer's copy for the rest of
 * its life; read the written values back rather than the formula.
 */
#ifndef MBSCOPE_PEER_DATAMAP_H
#define MBSCOPE_PEER_DATAMAP_H

#include <stdint.h>

#define PEER_TABLE_SIZE 10000
/* The unit (slave) id the peers answer by default. */
#define PEER_UNIT 1

/* Coils (01, 05, 0F): ON at every address divisible by 3. */
static inline int peer_coil(unsigned address) { return address % 3u == 0u; }
/* Discrete inputs (02): ON at every odd address. */
static inline int peer_discrete_input(unsigned address) { return address % 2u == 1u; }
/* Holding registers (03, 06, 10, 16, 17): 1000 + 3 * address (at most 30997). */
static inline uint16_t peer_holding_register(unsigned address) { return (uint16_t)(1000u + 3u * address); }
/* Input registers (04): 40000 + 2 * address (at most 59998). */
static inline uint16_t peer_input_register(unsigned address) { return (uint16_t)(40000u + 2u * address); }

#endif
