#!/usr/bin/env bash
# Starts mbscope's window. With no display (a server, CI, ssh), it renders the window offscreen
# to a PNG, prints where, and shows the headless decoder on the RosRao request instead.
set -euo pipefail
bin=${1:-build/app/mbscope}
shift || true
if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
  exec "$bin" "$@"
fi
shot=${MBSCOPE_SCREENSHOT:-$PWD/mbscope-window.png}
echo "run-mbscope: no display found; rendering the window offscreen to $shot"
QT_QPA_PLATFORM=offscreen MBSCOPE_SCREENSHOT="$shot" "$bin" "$@"
echo "run-mbscope: saved $shot"
echo "run-mbscope: the same decoder, headless: $bin decode 01 03 00 79 00 16 15 DD"
"$bin" decode 01 03 00 79 00 16 15 DD
