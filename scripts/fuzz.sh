#!/bin/sh
# Build the libFuzzer targets with clang (core instrumented too) and run each for N seconds
# (default 30) from the seed corpus in tests/fuzz/corpus. Exits non-zero on any crash, timeout,
# leak or sanitizer report.
#
#   scripts/fuzz.sh [seconds]
#
# Environment: MBSCOPE_FUZZ_BUILD_DIR (default build-fuzz), MBSCOPE_FUZZ_JOBS (default 2).
set -eu

seconds=${1:-30}
case $seconds in
    ''|*[!0-9]*) echo "usage: $0 [seconds]" >&2; exit 2 ;;
esac

root=$(cd "$(dirname "$0")/.." && pwd)
build=${MBSCOPE_FUZZ_BUILD_DIR:-$root/build-fuzz}
jobs=${MBSCOPE_FUZZ_JOBS:-2}

for tool in clang++ cmake; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "fuzz.sh: $tool is not installed (Debian: apt-get install clang cmake)" >&2
        exit 2
    fi
done

# The core library is compiled with fuzzer-no-link (coverage for libFuzzer) and the sanitizers;
# the fuzz executables add -fsanitize=fuzzer themselves (tests/fuzz/CMakeLists.txt).
# Warnings are errors in the gcc build that make test gates on; here clang's own opinions are
# printed but do not stop the fuzzing.
# Build type None: these flags alone (RelWithDebInfo would append -O2, slower to compile with the
# sanitizers and no help to a 20 s fuzz run); -g1 is the line tables a sanitizer report needs.
flags="-g1 -O1 -DNDEBUG -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
cmake -S "$root" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=None \
    -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DMBSCOPE_FUZZ=ON -DMBSCOPE_WERROR=OFF -DMBSCOPE_BUILD_UI=OFF -DMBSCOPE_BENCH=OFF >/dev/null
cmake --build "$build" --target fuzz_dissector fuzz_framers fuzz_simserver fuzz_capture fuzz_session fuzz_journal fuzz_script -j"$jobs"

# ASan records the stack of every allocation with its fast unwinder, which follows frame
# pointers; Debian's Qt is built without them, so every frame beyond the caller of Qt's
# allocator is an arbitrary word from the stack. Each such stack is new to ASan's stack depot,
# which then grows without end and dominates the run: fuzz_dissector, whose outputs allocate
# QStrings by the hundred, made 433 executions a second in 20 s with the default 30 frames and
# 721 with 2 (725 and 181 MB peak resident); with 3 frames no faster than 30. Two frames (the
# allocation and its caller) are kept;
# a crash's own stack is unwound fully either way. To see whole allocation stacks of a saved
# crash, run it again with ASAN_OPTIONS=malloc_context_size=30.
# A smaller quarantine (256 MB by default) keeps the peak memory of the long runs down.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:malloc_context_size=2:quarantine_size_mb=64}
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
summary=""
# One of libFuzzer's final figures (-print_final_stats) from the current target's log.
figure() { sed -n "s/^stat::$1: *//p" "$log" | tail -1; }
for name in dissector framers simserver capture session journal script; do
    work=$build/tests/fuzz/corpus-$name
    mkdir -p "$work"
    log=$build/tests/fuzz/fuzz_$name.log
    echo "== fuzz_$name: $seconds s (log: $log)"
    # QJSEngine's V4 engine keeps allocations of its own past the engine's end (LeakSanitizer
    # reports them on the first input, all allocated inside libQt6Qml); with two-frame stacks they
    # cannot be told from the harness's, so the script target runs without leak detection.
    options=$ASAN_OPTIONS
    [ "$name" = script ] && options="$ASAN_OPTIONS:detect_leaks=0"
    if ! ASAN_OPTIONS=$options "$build/tests/fuzz/fuzz_$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
            -print_final_stats=1 -artifact_prefix="$build/tests/fuzz/crash-$name-" \
            "$work" "$root/tests/fuzz/corpus/$name" >"$log" 2>&1; then
        echo "fuzz_$name FAILED:" >&2
        grep -E 'ERROR|runtime error|SUMMARY|Test unit written|#0 |#1 |#2 |#3 ' "$log" | head -40 >&2
        status=1
        continue
    fi
    if grep -qE 'runtime error|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)' "$log"; then
        echo "fuzz_$name: sanitizer report:" >&2
        grep -E 'runtime error|ERROR' "$log" | head -20 >&2
        status=1
        continue
    fi
    grep -E '^stat::number_of_executed_units|^stat::average_exec_per_sec|^stat::new_units_added|^stat::peak_rss_mb' "$log" | sed 's/^/    /'
    echo "    corpus: $(ls "$work" | wc -l) inputs, no crash"
    summary="$summary$(printf '%-22s %10s %10s %12s' "fuzz_$name" "$(figure average_exec_per_sec)" "$(figure number_of_executed_units)" "$(figure peak_rss_mb)")
"
done
# Executions per second side by side: a target far slower than the others tries far fewer
# inputs in the same time (issue 19: the dissector's ran 30 times slower than the capture's).
echo "== summary ($seconds s each)"
printf '%-22s %10s %10s %12s\n' target "exec/s" runs "peak RSS MB"
printf '%s' "$summary"
exit $status
