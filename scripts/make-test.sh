#!/usr/bin/env bash
# `make test`: installs what is missing (peers included), configures, builds, runs the fuzzers
# briefly (a separate clang build with sanitizers), then every test with CTest. Each phase is
# timed; the table of phases is printed at the end, whatever failed, followed by CTest's own
# summary lines so that they stay the last lines of the run.
#
#   scripts/make-test.sh BUILD_DIR JOBS FUZZ_SECONDS [cmake configure flags...]
set -uo pipefail

build=${1:?usage: $0 BUILD_DIR JOBS FUZZ_SECONDS [cmake flags...]}
jobs=${2:?jobs}
fuzz_seconds=${3:?fuzz seconds}
shift 3
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root" || exit 2

phases=()
status=0
begin=$(date +%s%N)
ctest_log=$(mktemp)
trap 'rm -f "$ctest_log"' EXIT

now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
# phase NAME START_MS RC: records one phase's wall time and exit status.
phase() {
    local ms=$(( $(now_ms) - $2 ))
    phases+=("$(printf '%-10s %6d.%d s  %s' "$1" $((ms / 1000)) $((ms % 1000 / 100)) \
        "$([ "$3" -eq 0 ] && echo ok || echo "FAILED (exit $3)")")")
}
# run NAME COMMAND...: runs one phase and times it.
run() {
    local name=$1 start rc
    shift
    start=$(now_ms)
    "$@"
    rc=$?
    phase "$name" "$start" $rc
    return $rc
}

summary() {
    echo
    echo "== make test: time per phase"
    printf '%s\n' "${phases[@]}"
    local ms=$(( ($(date +%s%N) - begin) / 1000000 ))
    printf '%-10s %6d.%d s\n' total $((ms / 1000)) $((ms % 1000 / 100))
    # This run's compilations only (ccache's own totals span every run since they were zeroed).
    if command -v ccache >/dev/null 2>&1; then
        local hits misses
        hits=$(( $(ccache_stat direct_cache_hit) + $(ccache_stat preprocessed_cache_hit) - ccache_hits_before ))
        misses=$(( $(ccache_stat cache_miss) - ccache_misses_before ))
        echo "ccache: this run $hits hit(s), $misses miss(es) (compilations served from the cache / compiled)"
    fi
    # CTest's closing lines last, as CTest printed them.
    if [ -s "$ctest_log" ]; then
        echo
        grep -E 'tests passed|tests failed|Total Test time|The following tests FAILED|^[[:space:]]+[0-9]+ - ' "$ctest_log"
    fi
}

# ccache_stat NAME: one counter of `ccache --print-stats` (0 when ccache or the counter is missing).
ccache_stat() {
    local v
    v=$(ccache --print-stats 2>/dev/null | awk -v k="$1" '$1 == k { print $2 }')
    echo "${v:-0}"
}

run deps scripts/install-deps.sh --tests || status=1
ccache_hits_before=0
ccache_misses_before=0
if command -v ccache >/dev/null 2>&1; then
    ccache_hits_before=$(( $(ccache_stat direct_cache_hit) + $(ccache_stat preprocessed_cache_hit) ))
    ccache_misses_before=$(ccache_stat cache_miss)
fi
if [ $status -eq 0 ]; then
    run configure cmake -S . -B "$build" "$@" || status=1
fi
if [ $status -eq 0 ]; then
    run build cmake --build "$build" -j"$jobs" || status=1
fi
if [ $status -eq 0 ]; then
    run fuzz scripts/fuzz.sh "$fuzz_seconds" || status=1
fi
if [ $status -eq 0 ]; then
    start=$(now_ms)
    ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout 600 2>&1 | tee "$ctest_log"
    rc=${PIPESTATUS[0]}
    phase ctest "$start" "$rc"
    [ "$rc" -eq 0 ] || status=1
fi
summary
exit $status
