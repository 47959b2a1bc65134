#!/bin/sh
# Build a Release tree and run the polling benchmark: a local libmodbus server polled as fast as
# possible by a raw socket loop, libmodbus's client and mbscope's engine (sequential with traffic
# logging, then pipelined), side by side in one run. bench_poll pins itself, the server and the
# engine's thread to one CPU (sched_setaffinity, inherited by the server it starts): see the
# comment at the top of tests/bench/bench_poll.cpp.
#
# Two tables: against libmodbus_server tcp (one request per read) and libmodbus_server tcp --batch
# (every request of a read answered, the answers corked into one segment: the server for the
# pipelined figures). On a machine shared with other work, --rounds 5 makes the clients take turns.
#
#   scripts/bench-poll.sh [bench_poll options...]    e.g. --count 50000 --pipeline 2,4,8,16 --rounds 5
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
cmake --build "$build" --target bench_poll -j"$jobs"

bench=$build/tests/bench/bench_poll
if [ ! -x "$bench" ]; then
    echo "bench-poll.sh: $bench was not built (is libmodbus-dev installed?)" >&2
    exit 2
fi
exec "$bench" --cpu "$cpu" "$@"
