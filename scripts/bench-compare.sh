#!/usr/bin/env bash
# Before/after figures in one run (docs/log/performance-history.md, "Restructuring"): two relight binaries,
# e.g. main's build and a branch's, on the same scenes, interleaved so that both see the same
# machine. Per scene: the precompute's wall time with each, then `relight bench` (luminaire
# frames) and `relight bench --sky` (sky frames), ROUNDS times each alternately; prints one
# JSON line per run and a median summary per binary and mode.
#   scripts/bench-compare.sh BASE_RELIGHT NEW_RELIGHT [SCENE.json ...]
# Without scenes: the demo room (written by NEW_RELIGHT demo --no-serve).
set -euo pipefail
base=$1
new=$2
shift 2
out=${OUT:-$(mktemp -d)}
mkdir -p "$out"
rounds=${ROUNDS:-5}
frames=${FRAMES:-50}
scenes=("$@")
if [[ ${#scenes[@]} -eq 0 ]]; then
  "$new" demo --no-serve --no-progress --width 32 --height 20 -o "$out/demo" > /dev/null
  scenes=("$out/demo/demo-room.json")
fi
results="$out/results.jsonl"
: > "$results"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  for which in base new; do
    bin=${!which}
    start=$(date +%s.%N)
    "$bin" precompute "$scene" -o "$out/$name-$which.rlt" --no-progress > /dev/null
    end=$(date +%s.%N)
    echo "{\"scene\":\"$name\",\"binary\":\"$which\",\"mode\":\"precompute\",\"seconds\":$(awk "BEGIN { print $end - $start }")}" >> "$results"
  done
  modes=(luminaires)
  grep -q '"portals"' "$scene" && modes+=(sky)
  for _ in $(seq 1 "$rounds"); do
    for mode in "${modes[@]}"; do
      for which in base new; do
        bin=${!which}
        flag=()
        [[ $mode == sky ]] && flag=(--sky)
        line=$("$bin" bench "$out/$name-$which.rlt" --frames "$frames" "${flag[@]}")
        echo "{\"scene\":\"$name\",\"binary\":\"$which\",${line:1}" >> "$results"
      done
    done
  done
done
cat "$results"
node -e '
  const lines = require("fs").readFileSync(process.argv[1], "utf8").trim().split("\n").map(JSON.parse);
  const median = (a) => { const s = [...a].sort((x, y) => x - y); return s[Math.floor(s.length / 2)]; };
  const groups = {};
  for (const l of lines) (groups[`${l.scene} ${l.mode}`] ??= { base: [], new: [] })[l.binary].push(l);
  for (const [key, g] of Object.entries(groups)) {
    if (key.endsWith("precompute")) {
      const b = g.base[0].seconds, n = g.new[0].seconds;
      console.log(`${key}: base ${b.toFixed(2)} s, new ${n.toFixed(2)} s, new/base ${(n / b).toFixed(3)}`);
      continue;
    }
    const f = (a, k) => median(a.map((l) => l[k]));
    console.log(`${key}: median frame base ${f(g.base, "median_ms").toFixed(3)} ms new ` +
      `${f(g.new, "median_ms").toFixed(3)} ms; ratio to streaming read base ` +
      `${f(g.base, "ratio").toFixed(3)} new ${f(g.new, "ratio").toFixed(3)}; ` +
      `new/base frame ${(f(g.new, "median_ms") / f(g.base, "median_ms")).toFixed(3)}`);
  }
' "$results"
