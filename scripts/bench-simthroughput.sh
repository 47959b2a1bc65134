#!/bin/sh
# Build a Release tree (without the window) and run the simulator's throughput benchmark: the same
# N libmodbus clients against libmodbus's own select() server and `mbscope simulate`, the servers
# pinned to one CPU and the clients to another, rounds taking turns, medians and the ratio
# mbscope/libmodbus printed (tests/bench/bench_simthroughput.cpp, docs/benchmarks.md).
#
#   scripts/bench-simthroughput.sh [bench_simthroughput options...]
#       e.g. --clients 50 --requests 1000 --rounds 7 --rows libmodbus,simulate,record
#
# Defaults: 50 clients x 1000 requests, 5 rounds. Environment: MBSCOPE_BENCH_BUILD_DIR (default
# build-bench), MBSCOPE_BENCH_JOBS (default 2).
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
build=${MBSCOPE_BENCH_BUILD_DIR:-$root/build-bench}
jobs=${MBSCOPE_BENCH_JOBS:-2}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DMBSCOPE_BUILD_UI=OFF -DMBSCOPE_BENCH=ON -DMBSCOPE_FUZZ=OFF >/dev/null
cmake --build "$build" --target bench_simthroughput -j"$jobs"

bench=$build/tests/bench/bench_simthroughput
if [ ! -x "$bench" ]; then
    echo "bench-simthroughput.sh: $bench was not built (is libmodbus-dev installed?)" >&2
    exit 2
fi
exec "$bench" "$@"
