#!/bin/sh
# Build a Release tree (without the window) and run the start-up benchmark: `mbscope read` of 10
# registers beside the same read in mbscope-full and mbpoll's, against one `mbscope simulate`,
# 20 runs each interleaved, median wall time and peak resident memory (tests/bench/bench_startup.cpp,
# docs/benchmarks.md "Start-up").
#
#   scripts/bench-startup.sh [bench_startup options...]     e.g. --runs 50
#
# Environment: MBSCOPE_BENCH_BUILD_DIR (default build-bench), MBSCOPE_BENCH_JOBS (default 2).
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
build=${MBSCOPE_BENCH_BUILD_DIR:-$root/build-bench}
jobs=${MBSCOPE_BENCH_JOBS:-2}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DMBSCOPE_BUILD_UI=OFF -DMBSCOPE_BENCH=ON -DMBSCOPE_FUZZ=OFF >/dev/null
cmake --build "$build" --target bench_startup -j"$jobs"

exec "$build/tests/bench/bench_startup" --runs 20 "$@"
