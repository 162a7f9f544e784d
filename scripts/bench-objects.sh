#!/usr/bin/env bash
# The movable-objects benchmark (Iwasaki et al. 2007 §6 measure 50K vertices with 12
# objects): a 10 x 3 x 8 m office of about 50,000 vertices with six IES downlights and 12 movable
# objects (bench/furnished-office.json), precomputed once (cached in $BUILD/bench), then
# `relight bench` for a luminaire change (the baseline of the same run), one object dragged, and
# all 12 moving. One JSON line per run, prefixed with its label.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/rlt-cache.sh
build=${BUILD:-build}
out="$build/bench"
frames=${FRAMES:-20}
mkdir -p "$out"
photometry=$(cd ../shared/data/photometry/photometric-viewer/ies && pwd)
sed "s|PHOTOMETRY|$photometry|g" bench/furnished-office.json > "$out/furnished-office.json"
if needs_precompute bench/furnished-office.json "$out/furnished-office.rlt"; then
  "$build/relight" precompute "$out/furnished-office.json" -o "$out/furnished-office.rlt" --no-progress
fi
run() {  # label, arguments...
  local label=$1
  shift
  printf '%-24s ' "$label"
  "$build/relight" bench "$out/furnished-office.rlt" --frames "$frames" "$@"
}
run "office luminaires"
run "office one dragged" --objects --object "chair 1"
run "office all 12 moving" --objects
