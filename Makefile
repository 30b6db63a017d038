# The two commands of the README, and the steps they are made of.
# Every target installs what is missing first (scripts/install-deps.sh), then builds.
SHELL := /bin/bash
JOBS ?= $(shell nproc)
DEMO_OUT ?= out/demo
DEMO_CAMPAIGN ?= campaigns/ans1/ans1_throughput.toml

.PHONY: all deps disk-check build build-hilrig build-asan build-fuzz demo test test-unit test-asan test-vm fuzz fuzz-smoke bench format format-check clean

all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	@cmake --preset default >/dev/null
	@cmake --build --preset default -j $(JOBS)

build-asan: deps
	@cmake --preset asan >/dev/null
	@cmake --build --preset asan -j $(JOBS)

# Only the hilrig program: what the demo needs, minutes sooner than the whole test build.
build-hilrig: deps
	@cmake --preset default >/dev/null
	@cmake --build --preset default -j $(JOBS) --target hilrig

# Runs a shipped campaign on the virtual bus and prints where its report is; exits with the
# campaign's status (0 passed, 1 a check failed, 2 bad input, 3 rig fault).
demo: build-hilrig
	@status=0; build/hilrig run $(DEMO_CAMPAIGN) --out $(DEMO_OUT) || status=$$?; \
	echo ""; \
	echo "demo: $(DEMO_CAMPAIGN) -> exit $$status"; \
	echo "demo: report   $(abspath $(DEMO_OUT))/report.html"; \
	echo "demo: results  $(abspath $(DEMO_OUT))/results.json, junit.xml, trace.vcd"; \
	exit $$status

test-unit: build
	@ctest --preset default -j $(JOBS)

test-asan: build-asan
	@ctest --preset asan -j $(JOBS)

# The RT VM lane: Debian's PREEMPT_RT kernel under QEMU with gpio-sim, SocketCAN and UARTs.
# Payloads: the kernel-backend tests (libgpiod 1.6 build), the same gpiod tests built against
# libgpiod 2.x (build-gpiod2/, bookworm-backports unpacked privately by install-deps --vm),
# the end-to-end ANS1 campaigns through gpio-sim, CAN and Modbus RTU, and a campaign's can.log
# replayed by canplayer onto vcan0.
GPIOD2_ROOT := $(CURDIR)/build-gpiod2/libgpiod2-root
test-vm: build
	@bash scripts/install-deps.sh --vm
	@cmake --preset default -B build-gpiod2 -DHILRIG_GPIOD_API=2 -DHILRIG_GPIOD_ROOT=$(GPIOD2_ROOT) >/dev/null
	@cmake --build build-gpiod2 -j $(JOBS) --target test_kernel_gpiod
	@bash rt-config/vm/run-lane.sh build-vm rt-config/vm/payload-kernel-tests.sh \
	  rt-config/vm/payload-gpiod2.sh rt-config/vm/payload-e2e.sh rt-config/vm/payload-can-log.sh

# The libFuzzer targets (fuzz/): clang++ in their own build directory, only the libraries they link.
FUZZERS := fuzz_campaign fuzz_rig_config fuzz_modbus_tcp fuzz_modbus_rtu fuzz_candump
build-fuzz: deps
	@cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
	  -DHILRIG_FUZZ=ON -DHILRIG_BUILD_TESTS=OFF -DHILRIG_BUILD_BENCH=OFF >/dev/null
	@cmake --build build-fuzz -j $(JOBS) --target $(FUZZERS)

# A short deterministic run of every fuzzer (fixed seed and run count, seeded from the shipped
# files): part of make test. make fuzz runs each for FUZZ_SECONDS (default 600) and keeps its corpus.
fuzz-smoke: build-fuzz
	@bash fuzz/run.sh smoke $(FUZZERS)

fuzz: build-fuzz
	@bash fuzz/run.sh long $(FUZZERS)

# Stops before building when the disk cannot hold the build trees (scripts/check-disk.sh).
disk-check:
	@bash scripts/check-disk.sh

# Every test, then the sanitizer build's tests, the fuzzers' short run, then the RT VM lane,
# in that order (one step after another, each timed: a CI log says where the time went).
TEST_STEPS := disk-check test-unit test-asan format-check fuzz-smoke test-vm
test:
	@start=$$(date +%s); \
	for step in $(TEST_STEPS); do \
	  t=$$(date +%s); \
	  $(MAKE) --no-print-directory $$step || { echo "make test: $$step FAILED after $$(( $$(date +%s) - t )) s"; exit 1; }; \
	  echo "make test: $$step passed in $$(( $$(date +%s) - t )) s ($$(( $$(date +%s) - start )) s so far)"; \
	done
	@echo "make test: all suites passed (default and ASan+UBSan builds)"
	@echo "make test: build trees hold $$(du -scm build build-asan build-fuzz build-gpiod2 build-vm 2>/dev/null | tail -1 | cut -f1) MiB"

bench: deps
	@cmake --preset release >/dev/null
	@cmake --build --preset release -j $(JOBS)
	@bash bench/run-all.sh

format:
	@git ls-files '*.cpp' '*.hpp' | xargs clang-format -i

format-check:
	@git ls-files '*.cpp' '*.hpp' | xargs -r clang-format --dry-run -Werror

clean:
	rm -rf build build-asan build-release build-gpiod2 build-vm build-fuzz
