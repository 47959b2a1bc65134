#!/bin/sh
# Build a Release tree and run the protocol-core benchmark pinned to one core, printing the
# figures (frames/s as items_per_second, bytes/s) beside the raw-parser baseline.
#
#   scripts/bench.sh [benchmark options...]     e.g. --benchmark_filter=Dissect
#
# Environment: MBSCOPE_BENCH_BUILD_DIR (default build-bench), MBSCOPE_BENCH_CPU (default 1),
# MBSCOPE_BENCH_JOBS (default 2).
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
build=${MBSCOPE_BENCH_BUILD_DIR:-$root/build-bench}
cpu=${MBSCOPE_BENCH_CPU:-1}
jobs=${MBSCOPE_BENCH_JOBS:-2}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DMBSCOPE_BUILD_UI=OFF -DMBSCOPE_BENCH=ON -DMBSCOPE_FUZZ=OFF >/dev/null
cmake --build "$build" --target bench_dissector -j"$jobs"

bench=$build/tests/bench/bench_dissector
if [ ! -x "$bench" ]; then
    echo "bench.sh: $bench was not built (is libbenchmark-dev installed?)" >&2
    exit 2
fi
pin=""
if command -v taskset >/dev/null 2>&1 && [ "$cpu" -lt "$(nproc)" ]; then
    pin="taskset -c $cpu"
    echo "pinned to CPU $cpu"
else
    echo "bench.sh: not pinned (taskset missing or CPU $cpu absent)" >&2
fi
exec $pin "$bench" "$@"
