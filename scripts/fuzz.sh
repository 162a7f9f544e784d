#!/usr/bin/env bash
# `make fuzz [FUZZ_SECONDS=N]`: builds the libFuzzer targets (tests/fuzz/fuzz_NAME.cpp)
# with Debian's clang, AddressSanitizer and UndefinedBehaviorSanitizer in their own folder
# (build-fuzz), then runs each for N seconds (60 by default) from its seed corpus
# (tests/fuzz/corpus/NAME/, copied: what a run adds stays in build-fuzz/corpus/NAME/). Prints
# one line per target, "fuzz_NAME: E execs, C crashes", then a summary, and exits 1 on any
# crash, hang or leak. A crash's input lands in build-fuzz/crashes/NAME/: fix the defect and
# add the input to tests/fuzz/corpus/NAME/, which `make test` replays.
# FUZZ_RUNS=R also stops a target after R executions (whichever comes first); FUZZ_TARGETS="a b"
# runs only those targets. The targets whose readers take a file write each input to a
# temporary file: in /dev/shm when it is there (tmpfs; on a disk, rewriting the file every
# execution makes the mesh targets several times slower).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh --fuzz
seconds=${FUZZ_SECONDS:-60}
build=${FUZZ_BUILD:-build-fuzz}
all_targets=(ies ldt scene state obj ply gltf epw photo envmap rlt message targets cubemap)
read -r -a targets <<<"${FUZZ_TARGETS:-${all_targets[*]}}"
for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || { echo "fuzz: no target \"$t\"" >&2; exit 2; }
done
runs=${FUZZ_RUNS:--1}
if [[ -d /dev/shm && -w /dev/shm ]]; then export TMPDIR=/dev/shm; fi
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -g"
if [[ ! -f "$build/build.ninja" ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DRELIGHT_FUZZ=ON -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
fi
cmake --build "$build" -j "${JOBS:-2}" --target "${targets[@]/#/fuzz_}"
total_execs=0
total_crashes=0
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  crashes="$build/crashes/$t"
  rm -rf "$crashes"
  mkdir -p "$corpus" "$crashes"
  cp tests/fuzz/corpus/"$t"/* "$corpus"/
  log="$build/fuzz_$t.log"
  "$build/fuzz_$t" "$corpus" -max_total_time="$seconds" -runs="$runs" -print_final_stats=1 -timeout=10 \
    -rss_limit_mb=4096 -artifact_prefix="$crashes/" >"$log" 2>&1 || true
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  execs=${execs:-0}
  found=$(find "$crashes" -type f | wc -l)
  echo "fuzz_$t: $execs execs, $found crashes"
  total_execs=$((total_execs + execs))
  total_crashes=$((total_crashes + found))
done
limit="${seconds} s"
((runs < 0)) || limit="$limit or $runs execs"
echo "fuzz: ${#targets[@]} targets, $total_execs execs, $total_crashes crashes ($limit each; logs in $build)"
((total_crashes == 0))
