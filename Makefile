# relight — the two commands of the quick start: `make demo` and `make test`.
# Each bootstraps missing Debian packages, builds in Release, then runs.
BUILD ?= build
JOBS  ?= 2
DEMO_OUT ?= out/demo

.PHONY: all bootstrap build demo test test-sanitize bench fuzz soak install format clean

all: build

bootstrap:
	@scripts/bootstrap.sh

$(BUILD)/build.ninja: | bootstrap
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null

build: bootstrap $(BUILD)/build.ninja
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@$(BUILD)/relight demo -o $(DEMO_OUT)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# `make install PREFIX=/opt/relight`: relight in PREFIX/bin, the studio client (with three.js)
# in PREFIX/share/relight/studio, where `relight serve` finds it.
PREFIX ?= /usr/local
install: build
	@cmake --install $(BUILD) --prefix $(PREFIX)

# Benchmarks: Google Benchmark programs on the demo room, then the 1M-receiver dragon
# scene and the near-field scenes (dragon res2, a church-like nave; assets from npm through
# the bootstrap). Not part of `make test`.
bench: build
	@scripts/bootstrap.sh --bench
	@$(BUILD)/relight_benchmarks
	@BUILD=$(BUILD) scripts/bench-dragon.sh
	@BUILD=$(BUILD) scripts/bench-dragon.sh dragon-window
	@BUILD=$(BUILD) scripts/bench-nearfield.sh

# Fuzzing: libFuzzer targets built with clang, ASan and UBSan in build-fuzz, each run
# FUZZ_SECONDS (60) from its seed corpus, or until FUZZ_RUNS executions when that comes first;
# FUZZ_TARGETS="ies ldt" runs some. Exits non-zero on any crash. Not part of `make test`, which
# replays the corpora (seeds and regression inputs) through the normal build.
FUZZ_SECONDS ?= 60
FUZZ_RUNS ?= -1
fuzz:
	@FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_RUNS=$(FUZZ_RUNS) FUZZ_TARGETS="$(FUZZ_TARGETS)" \
	  JOBS=$(JOBS) scripts/fuzz.sh

# Sanitizers: the suite under ASan + UBSan in build-sanitize, then the studio server
# under TSan in build-tsan (scripts/test-sanitize.sh). Not part of `make test` (two more full
# builds).
test-sanitize:
	@JOBS=$(JOBS) scripts/test-sanitize.sh

# Studio soak: `relight serve` on the demo room with 16 WebSocket clients sending
# states, picks, pings and malformed messages every 20-100 ms for MINUTES (10), one of them
# stalled (not reading) for the second half; prints memory, frame times and latencies and
# exits non-zero on a crash, > 16 MiB growth after the 1-minute warm-up or a server-side p99
# over 20 ms (scripts/studio-soak.mjs). Not part of `make test`.
MINUTES ?= 10
soak: build
	@test -f $(BUILD)/studio-demo/demo-room.rlt || $(BUILD)/relight demo --no-serve --no-progress --width 64 --height 40 -o $(BUILD)/studio-demo
	@BUILD=$(BUILD) node scripts/studio-soak.mjs --minutes $(MINUTES)

format:
	@clang-format -i $$(git ls-files 'src/*.cpp' 'src/*.h' 'tests/*.cpp' 'tests/*.h' 'bench/*.cpp')

clean:
	@rm -rf $(BUILD)
