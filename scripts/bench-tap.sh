#!/bin/sh
# Build a Release tree (without the window) and run the inline tap's benchmark: `mbscope tap` in
# front of `mbscope simulate`, beside the direct path and socat, the added latency at p50 and p99,
# throughput with 1, 4 and 16 masters, and a serial target (a socat pty pair and a paced line)
# beside the line's limit (tests/bench/bench_tap.cpp, docs/benchmarks.md "The tap").
#
#   scripts/bench-tap.sh [bench_tap options...]
#       e.g. --rounds 7 --sections latency,throughput --pipeline 8
#       --cpu 0: the added latency again with every process on CPU 0, both pinnings side by side
#
# Defaults: 20000 requests for the latency, 2000 per master for the throughput, 5 rounds, 200
# requests per master (4 masters) on the serial line at 115200 and 19200 baud. Environment:
# MBSCOPE_BENCH_BUILD_DIR (default build-bench), MBSCOPE_BENCH_JOBS (default 2).
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
build=${MBSCOPE_BENCH_BUILD_DIR:-$root/build-bench}
jobs=${MBSCOPE_BENCH_JOBS:-2}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DMBSCOPE_BUILD_UI=OFF -DMBSCOPE_BENCH=ON -DMBSCOPE_FUZZ=OFF >/dev/null
cmake --build "$build" --target bench_tap -j"$jobs"

bench=$build/tests/bench/bench_tap
if [ ! -x "$bench" ]; then
    echo "bench-tap.sh: $bench was not built (are libmodbus-dev and socat installed?)" >&2
    exit 2
fi
exec "$bench" "$@"
