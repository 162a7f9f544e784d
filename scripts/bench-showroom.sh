#!/usr/bin/env bash
# The visibility-cuts benchmark (Iwasaki et al., Cyberworlds, §VI, Fig. 7 measure a
# 27K-vertex furniture scene): a 5 x 5 m floor with a table, four chairs, a sofa and a shelf as
# movable objects (26,226 vertices and 121 sensors) under a clear CIE sky with a sun
# (bench/furniture-showroom.json), precomputed once at the paper's defaults (32,768 directions,
# fields of 32 spheres x 6 x 32^2 points; cached in $BUILD/bench), then `relight bench` for the
# lighting (the sun moving, with the viewpoint's glossy shading timed beside it), a material
# edit (the lacquer's albedo), one chair dragged, and every object moving. One JSON line per
# run, prefixed with its label.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/rlt-cache.sh
build=${BUILD:-build}
out="$build/bench"
frames=${FRAMES:-20}
mkdir -p "$out"
if needs_precompute bench/furniture-showroom.json "$out/furniture-showroom.rlt"; then
  "$build/relight" precompute bench/furniture-showroom.json -o "$out/furniture-showroom.rlt" --no-progress
fi
run() {  # label, arguments...
  local label=$1
  shift
  printf '%-24s ' "$label"
  "$build/relight" bench "$out/furniture-showroom.rlt" --frames "$frames" "$@"
}
run "showroom lighting" --environment
run "showroom material" --materials --material lacquer
run "showroom one dragged" --objects --object "chair 1"
run "showroom all moving" --objects
