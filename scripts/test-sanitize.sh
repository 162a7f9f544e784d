#!/usr/bin/env bash
# `make test-sanitize`: the whole suite built with GCC's AddressSanitizer and
# UndefinedBehaviorSanitizer in its own folder (build-sanitize: RelWithDebInfo, frame pointers
# kept, UB fatal, leaks checked) and run by ctest, the studio's node tests driving the
# instrumented `relight`; then the studio server under ThreadSanitizer (below). Exits non-zero
# when a test fails or a sanitizer reports. Not part of `make test` (two more full builds; the
# runs are 2–10× slower). SANITIZE_STAGES=asan or =tsan runs one stage.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
jobs=${JOBS:-2}
asan=${SANITIZE_BUILD:-build-sanitize}
flags="-fno-omit-frame-pointer -g"
stages=${SANITIZE_STAGES:-asan,tsan}
if [[ ,$stages, == *,asan,* ]]; then
  if [[ ! -f "$asan/build.ninja" ]]; then
    cmake -S . -B "$asan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined $flags" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
  fi
  cmake --build "$asan" -j "$jobs"
  # Leaks are checked (LeakSanitizer, part of ASan); a UB report aborts the test that made it.
  export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
  # Open MPI's own allocations at MPI_Init are not relight's leaks (the file says which).
  export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitize/lsan-suppressions.txt}
  # The studio's node tests report, not assert, bounds on the server's memory (ASan's shadow).
  (cd "$asan" && RELIGHT_SANITIZER=address ctest --output-on-failure -j "$jobs" --timeout 1800)
  echo "test-sanitize: ASan + UBSan suite clean ($asan)"
fi

# The studio server under ThreadSanitizer: `relight` built with -fsanitize=thread in build-tsan
# and driven by the studio's protocol tests (many WebSocket clients, states, picks, malformed and
# hostile messages) on the demo room. With RELIGHT_THREADS=1: Debian's oneTBB is not
# instrumented, so TSan cannot see the synchronisation of its task handoffs and would report the
# data of every parallel loop; one thread per loop leaves it the server's own threads (the
# transport, the relight worker, the annual and optimizer jobs) and their locks. Every report is
# written under $tsan/tsan-reports and fails the stage.
if [[ ,$stages, == *,tsan,* ]]; then
  tsan=${TSAN_BUILD:-build-tsan}
  if [[ ! -f "$tsan/build.ninja" ]]; then
    cmake -S . -B "$tsan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS="-fsanitize=thread $flags" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" >/dev/null
  fi
  cmake --build "$tsan" -j "$jobs" --target relight
  scene=$PWD/$tsan/studio-demo/demo-room.rlt
  if [[ ! -f "$scene" ]]; then
    cmake --build "${BUILD:-build}" -j "$jobs" --target relight
    "${BUILD:-build}/relight" demo --no-serve --no-progress --width 64 --height 40 \
      -o "$tsan/studio-demo"
  fi
  reports=$PWD/$tsan/tsan-reports
  rm -rf "$reports" && mkdir -p "$reports"
  RELIGHT_THREADS=1 RELIGHT_SANITIZER=thread \
    TSAN_OPTIONS="log_path=$reports/report:second_deadlock_stack=1" \
    RELIGHT_BINARY="$PWD/$tsan/relight" STUDIO_SCENE="$scene" \
    node --test tests/studio/protocol.test.mjs tests/studio/fuzz.test.mjs \
    tests/studio/hostile.test.mjs
  if compgen -G "$reports/report*" >/dev/null; then
    cat "$reports"/report*
    echo "test-sanitize: ThreadSanitizer reported (above)" >&2
    exit 1
  fi
  echo "test-sanitize: the studio server clean under ThreadSanitizer ($tsan)"
fi

