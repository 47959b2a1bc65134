#!/usr/bin/env bash
# Installs, through apt-get, only the Debian 12 packages mbscope needs that are missing.
# Idempotent: a second run finds nothing to do and touches nothing.
# Usage: scripts/install-deps.sh [--tests]   (--tests adds the real peers the test suite starts)
set -euo pipefail

build_pkgs=(
  build-essential cmake ninja-build pkg-config ccache
  qt6-base-dev qt6-base-dev-tools qt6-serialbus-dev qt6-serialport-dev qt6-tools-dev qt6-tools-dev-tools
  qt6-declarative-dev  # QJSEngine (Qt6::Qml): the simulator's device scripts
  qt6-l10n-tools libqcustomplot-dev libqcustomplot2.1-qt6 libgl-dev
  qt6-qpa-plugins qt6-svg-dev
  librsvg2-bin dpkg-dev
  # the watch service: Prometheus endpoint and MQTT (Qt6HttpServer's CMake package needs qt6-websockets-dev,
  # which Debian's qt6-httpserver-dev does not pull in)
  qt6-httpserver-dev qt6-websockets-dev libmosquitto-dev
)
test_pkgs=(
  tshark socat libmodbus-dev mbpoll python3-pymodbus python3-serial python3-serial-asyncio python3-jsonschema
  xvfb clang libclang-rt-14-dev libbenchmark-dev xauth
  desktop-file-utils appstream
  prometheus mosquitto mosquitto-clients
  shellcheck  # tst_shellscripts
  zsh  # tst_cli_completion: `zsh -n` parses `mbscope completion zsh`
  poppler-utils  # tst_cli_conform, tst_conformancedialog: pdftotext reads the scorecard PDF back
)

want=("${build_pkgs[@]}")
if [[ "${1:-}" == "--tests" ]]; then
  want+=("${test_pkgs[@]}")
fi

# Node-RED with node-red-contrib-modbus, for tst_cli_exportmap (an exported flow run for real), from
# the npm registry into a folder of its own (never Debian's npm package; node and npm must be there).
# node-red-contrib-modbus 5.23.3 is the newest whose dependencies all come from the npm registry
# (later ones fetch modbus-serial from a tarball on another host). Quick when already installed.
nodered_dir=/opt/mbscope-nodered
nodered_pkgs=(node-red@4.1.15 node-red-contrib-modbus@5.23.3)
install_nodered() {
  local have
  have=$(node -e "try{const v=p=>require('$nodered_dir/node_modules/'+p+'/package.json').version;console.log('node-red@'+v('node-red')+' node-red-contrib-modbus@'+v('node-red-contrib-modbus'))}catch(e){}" 2>/dev/null || true)
  if [[ "$have" == "${nodered_pkgs[*]}" ]]; then
    echo "install-deps: ${nodered_pkgs[*]} present in $nodered_dir"
    return 0
  fi
  if ! command -v npm >/dev/null || ! command -v node >/dev/null; then
    echo "install-deps: node and npm are not installed: Node-RED (${nodered_pkgs[*]}) left out; tst_cli_exportmap skips its flow run" >&2
    return 0
  fi
  echo "install-deps: installing ${nodered_pkgs[*]} into $nodered_dir"
  local sudo=""
  if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
  $sudo mkdir -p "$nodered_dir"
  $sudo npm install --prefix "$nodered_dir" --no-audit --no-fund --loglevel=error "${nodered_pkgs[@]}"
}
if [[ "${1:-}" == "--tests" ]]; then
  install_nodered
fi

missing=()
for p in "${want[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#want[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
# tshark asks whether non-root users may capture; answer it up front so no prompt blocks CI.
echo "wireshark-common wireshark-common/install-setuid boolean false" | $sudo debconf-set-selections
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
