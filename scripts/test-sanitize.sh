#!/usr/bin/env bash
# `make test-sanitize` (issue 16): the whole suite built with GCC's AddressSanitizer and
# UndefinedBehaviorSanitizer in its own folder (build-sanitize: RelWithDebInfo, frame pointers
# kept, UB fatal) and run by ctest, the studio's node tests driving the instrumented `relight`;
# then the studio server built with ThreadSanitizer (build-tsan: the relight binary only) under
# the studio's protocol and annual tests, whose server threads (network, worker, annual,
# optimiser) share state. Debian's TBB and Embree are not instrumented: TSan is told to ignore
# races reported from inside them (scripts/tsan.supp). Exits non-zero when either run reports.
# Not part of `make test` (the instrumented build is a second full build, its run 2–3× slower).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
jobs=${JOBS:-2}
asan=${SANITIZE_BUILD:-build-sanitize}
tsan=${TSAN_BUILD:-build-tsan}
flags="-fno-omit-frame-pointer -g"
if [[ ! -f "$asan/build.ninja" ]]; then
  cmake -S . -B "$asan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined $flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
fi
cmake --build "$asan" -j "$jobs"
# Leaks are checked (LeakSanitizer, part of ASan); a UB report aborts the test that made it.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
(cd "$asan" && ctest --output-on-failure -j "$jobs" --timeout 1800)
echo "test-sanitize: ASan + UBSan suite clean ($asan)"

if [[ ! -f "$tsan/build.ninja" ]]; then
  cmake -S . -B "$tsan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS="-fsanitize=thread $flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
    >/dev/null
fi
cmake --build "$tsan" -j "$jobs" --target relight
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp"
# The studio tests that run the server's threads, against the TSan binary (studio_support.mjs
# reads RELIGHT_BINARY; the demo room is the one the ASan run's fixture made).
for t in protocol annual optimize; do
  RELIGHT_BINARY="$PWD/$tsan/relight" STUDIO_SCENE="$PWD/$asan/studio-demo/demo-room.rlt" \
    node --test "tests/studio/$t.test.mjs"
done
echo "test-sanitize: TSan studio server clean ($tsan)"
