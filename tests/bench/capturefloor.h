#pragma once

// The floor for offline analysis (bench_capture, issue 32): a plain C loop (capturefloor.cpp,
// C compiled as C++ with the project's flags) that only reads a
// little-endian pcapng of Ethernet/IPv4/TCP Modbus traffic in 1 MiB read()s and pairs each
// response with its request by transaction id (one table of 65,536 start times, no allocation
// per packet), summing the latencies. What any analysis must do at least; mbscope analyze is
// printed beside it as a ratio.
#ifdef __cplusplus
extern "C" {
#endif

struct CaptureFloorResult {
    long long packets;
    long long requests;
    long long pairs;
    long long latencyNsSum;
    int error; // 0, or the reason it stopped: 1 cannot open, 2 not a little-endian pcapng, 3 damaged
};

struct CaptureFloorResult captureFloorRun(const char *path, unsigned short serverPort);

#ifdef __cplusplus
}
#endif
