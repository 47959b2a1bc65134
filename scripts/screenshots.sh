#!/usr/bin/env bash
# Renders the user guide's screenshots offscreen, so they always show the current program:
#   scripts/screenshots.sh [BUILD_DIR] [OUT_DIR]      (defaults: build, docs/guide/images)
# The window states come from mbscope's own options (--screenshot, --size,
# --screenshot-before-send, --screenshot-poll COUNT, --dock NAME); the plots from
# `mbscope poll --histogram` and `mbscope sweep --histogram` against `mbscope simulate` on a free
# loopback port. No display is used. A dock the window does not have (yet) is said and skipped;
# any other failure stops the script with exit status 1. The PNGs are shrunk with pngquant or optipng when installed.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$here/build}
out=${2:-$here/docs/guide/images}
bin=$build/app/mbscope
[[ -x $bin ]] || { echo "screenshots: $bin is not built (cmake --build $build --target mbscope)" >&2; exit 1; }
mkdir -p "$out"
out=$(cd "$out" && pwd)

# The same pictures on every machine: no display, English, no settings or recent targets of
# the user's, a private runtime folder.
scratch=$(mktemp -d)
sim_pid=
cleanup() {
    [[ -n $sim_pid ]] && kill -INT "$sim_pid" 2>/dev/null && wait "$sim_pid" 2>/dev/null || true
    rm -rf "$scratch"
}
trap cleanup EXIT
export QT_QPA_PLATFORM=offscreen LANG=C.UTF-8 LC_ALL=C.UTF-8 LANGUAGE=en
export HOME=$scratch/home XDG_CONFIG_HOME=$scratch/config XDG_RUNTIME_DIR=$scratch/runtime
mkdir -p "$HOME" "$XDG_CONFIG_HOME" && mkdir -m 700 "$XDG_RUNTIME_DIR"

size=1400x900
window() { # NAME [OPTIONS...]: the window, on its first run with the simulator
    local name=$1; shift
    "$bin" --screenshot "$out/$name.png" --size "$size" "$@" 2> >(grep -v propagateSizeHints >&2)
    echo "screenshots: $name.png"
}
dock() { # NAME DOCK [OPTIONS...]: the window with the dock raised; skipped when the window has no such dock
    local name=$1 which=$2
    shift 2
    if "$bin" --screenshot "$out/$name.png" --size "$size" --dock "$which" "$@" 2>"$scratch/dock.err"; then
        echo "screenshots: $name.png"
    elif grep -q "names no dock" "$scratch/dock.err"; then
        echo "screenshots: $name.png skipped: this build's window has no $which dock"
    else
        cat "$scratch/dock.err" >&2
        exit 1
    fi
}

window first-run --screenshot-before-send
window answer
# After a poll of 100 requests, so the lists and plots have something to show.
dock traffic traffic --screenshot-poll 100
dock registers registers --screenshot-poll 100
dock analysis analysis --screenshot-poll 100
dock simulator simulator --screenshot-poll 100
# The example session opened: its test plan, ready to run.
dock test-plan "test plan" --session "$here/docs/examples/rosrao-gamma.mbscope.json"

# The simulated RosRao detector on a free port, for the poll and the sweep.
"$bin" simulate --profile rosrao-gamma --listen rtu-tcp://127.0.0.1:0 --seed 1 --quiet >"$scratch/sim.out" 2>&1 &
sim_pid=$!
target=
for _ in $(seq 100); do
    target=$(sed -n 's/^listening \(rtu-tcp:[^ ]*\).*/\1/p' "$scratch/sim.out")
    [[ -n $target ]] && break
    sleep 0.1
done
[[ -n $target ]] || { echo "screenshots: the simulator did not start:" >&2; cat "$scratch/sim.out" >&2; exit 1; }

read_all="01 03 00 79 00 16 15 DD"
"$bin" poll --target "$target" --hex "$read_all" --interval 10ms --count 300 --histogram "$out/poll-histogram.png" >/dev/null
echo "screenshots: poll-histogram.png"
"$bin" sweep --target "$target" --hex "$read_all" --intervals 0,10,50 --count 100 --histogram "$out/sweep.png" >/dev/null
echo "screenshots: sweep.png"
# Tools > Scan: the dialog after a scan of the simulated detector's ids 1-6, Map unit on unit 3,
# Timing on unit 1 and Serial settings on the simulated Arduino behind a pty pair, rendered by
# their GUI tests.
scan_test=$build/tests/ui/tst_scandialog
if [[ -x $scan_test ]]; then
    MBSCOPE_SCAN_SCREENSHOT="$out/scan.png" MBSCOPE_MAP_SCREENSHOT="$out/scan-map.png" \
        MBSCOPE_TIMING_SCREENSHOT="$out/scan-timing.png" MBSCOPE_LINE_SCREENSHOT="$out/scan-line.png" \
        "$scan_test" scanListsEveryId mapUnitClonesIt timingOfAFoundUnit serialSettingsFound >"$scratch/scan.out" 2>&1 \
        || { echo "screenshots: tst_scandialog failed:" >&2; cat "$scratch/scan.out" >&2; exit 1; }
    echo "screenshots: scan.png scan-map.png scan-timing.png scan-line.png"
else
    echo "screenshots: scan.png, scan-map.png, scan-timing.png and scan-line.png skipped: $scan_test is not built"
fi

# Tools > Conformance: the scorecard of the simulator's conformance profile, writes allowed,
# rendered by its GUI test.
conform_test=$build/tests/ui/tst_conformancedialog
if [[ -x $conform_test ]]; then
    MBSCOPE_CONFORMANCE_SCREENSHOT="$out/conformance.png" "$conform_test" "runFillsTheScorecard:writes where allowed" \
        >"$scratch/conform.out" 2>&1 || { echo "screenshots: tst_conformancedialog failed:" >&2; cat "$scratch/conform.out" >&2; exit 1; }
    echo "screenshots: conformance.png"
else
    echo "screenshots: conformance.png skipped: $conform_test is not built"
fi

# The window as a tap in front of the first-run simulator, a master's read through it: rendered
# by its GUI test.
tap_test=$build/tests/ui/tst_tapwindow
if [[ -x $tap_test ]]; then
    MBSCOPE_TAP_SCREENSHOT="$out/tap.png" "$tap_test" tapInTheWindow:read >"$scratch/tap.out" 2>&1 \
        || { echo "screenshots: tst_tapwindow failed:" >&2; cat "$scratch/tap.out" >&2; exit 1; }
    echo "screenshots: tap.png"
else
    echo "screenshots: tap.png skipped: $tap_test is not built"
fi

# The Watches tab: the simulated M221 on a free port, the example watch session pointed at it,
# its watches started; in the light and the dark theme.
"$bin" simulate --profile m221-plc --listen tcp://127.0.0.1:0 --quiet >"$scratch/plc.out" 2>&1 &
plc_pid=$!
plc=
for _ in $(seq 100); do
    plc=$(sed -n 's/^listening \(tcp:[^ ]*\).*/\1/p' "$scratch/plc.out")
    [[ -n $plc ]] && break
    sleep 0.1
done
[[ -n $plc ]] || { echo "screenshots: the PLC simulator did not start:" >&2; cat "$scratch/plc.out" >&2; exit 1; }
sed "s|tcp://127.0.0.1:5020|$plc|g" "$here/docs/examples/plc-watches.mbscope.json" >"$scratch/plc-watches.mbscope.json"
window workspace --session "$scratch/plc-watches.mbscope.json" --tab watches --start-watches --theme light
window workspace-dark --session "$scratch/plc-watches.mbscope.json" --tab watches --start-watches --theme dark
kill -INT "$plc_pid" 2>/dev/null && wait "$plc_pid" 2>/dev/null || true

if command -v pngquant >/dev/null; then
    pngquant --force --skip-if-larger --strip --ext .png -- "$out"/*.png || true
elif command -v optipng >/dev/null; then
    optipng -quiet -o2 -strip all -- "$out"/*.png
fi
