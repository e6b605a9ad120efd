# PRISCA Lab — the commands a newcomer needs.
#   make run    install missing Debian packages, build, start the application
#   make test   install missing Debian packages, build, run the whole test suite (offscreen)
#   make bench  build in release mode and run the benchmarks
#   make package  the Debian package prisca-lab_<version>-1_<arch>.deb here (release build, no
#               tests; then: sudo apt install ./prisca-lab_*.deb; docs/install.md)
#   make format the sources as .clang-format has them (make test checks it)
#   make check-sanitizers  the suite under AddressSanitizer + UBSan, the threaded tests under TSan
#   make fuzz FUZZ_SECONDS=N [FUZZ_TARGETS="a b"]  each fuzz target for N seconds (libFuzzer)
#   make test-under-load RUNS=N  make test N times while busy loops keep every core busy
BUILD_DIR ?= build
PRESET    ?= default
JOBS      ?= $(shell nproc)

.PHONY: all deps configure build run test bench package format clean check-sanitizers fuzz test-under-load

all: build

deps:
	@./scripts/install-deps.sh

# Configure once; afterwards the build re-runs CMake by itself when a CMakeLists.txt changes.
configure: deps
	@test -f $(BUILD_DIR)/build.ninja || cmake --preset $(PRESET)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

run: build
	./$(BUILD_DIR)/app/prisca

test: build
	cd $(BUILD_DIR) && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j $(JOBS) -LE benchmark

# Both are unity builds (a target's sources compiled eight at a time: docs/testing.md).
# AddressSanitizer + UndefinedBehaviorSanitizer on the whole suite (less the minutes-long
# tests labelled slow, whose code the quick ones run too); ThreadSanitizer on the tests
# whose code runs on several threads (link, camera, rig loop and session, virtual rig, GUI runs,
# recordings). Suppressions name third-party code only (tests/sanitizers/*.supp say why).
SANITIZER_DIR := $(CURDIR)/tests/sanitizers
TSAN_TESTS    := test_transmitter_link test_camera test_rig_loop test_rig_session \
                 test_virtual_rig test_gui_record test_gui_experiments test_gui_run \
                 test_gui_session test_gui_rig test_gui_window test_gui_language test_gui_emergency \
                 test_recording_crash
check-sanitizers: deps
	@test -f build-asan/build.ninja || cmake --preset asan
	cmake --build build-asan -j $(JOBS)
	cd build-asan && QT_QPA_PLATFORM=offscreen \
	  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1 \
	  LSAN_OPTIONS=suppressions=$(SANITIZER_DIR)/lsan.supp:print_suppressions=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure -j $(JOBS) -LE 'benchmark|slow'
	@test -f build-tsan/build.ninja || cmake --preset tsan
	cmake --build build-tsan -j $(JOBS) --target $(TSAN_TESTS) record_child
	cd build-tsan && QT_QPA_PLATFORM=offscreen \
	  TSAN_OPTIONS=suppressions=$(SANITIZER_DIR)/tsan.supp:halt_on_error=1:second_deadlock_stack=1 \
	  ctest --output-on-failure -j $(JOBS) -R '^($(subst $(eval) ,|,$(strip $(TSAN_TESTS))))$$'

# libFuzzer on every target of tests/fuzz for FUZZ_SECONDS each, starting from the corpus in the
# tree (new inputs found stay in build-fuzz/corpus; copy the interesting ones into the tree).
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?=
fuzz:
	@./scripts/install-deps.sh fuzz
	@test -f build-fuzz/build.ninja || cmake --preset fuzz
	./scripts/run-fuzz.sh $(FUZZ_SECONDS) $(FUZZ_TARGETS)

RUNS ?= 10
test-under-load: build
	./scripts/test-under-load.sh $(RUNS)

bench: build
	cd $(BUILD_DIR) && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -L benchmark --verbose

PACKAGE_DIR := build-package
package: deps
	@test -f $(PACKAGE_DIR)/build.ninja || cmake --preset package
	cmake --build $(PACKAGE_DIR) -j $(JOBS) --target package
	rm -f prisca-lab_*.deb
	cp $(PACKAGE_DIR)/prisca-lab_*.deb .
	@ls -l prisca-lab_*.deb

format:
	find app core sim devices rigsim rig tools tests -path tests/data -prune -o \( -name '*.h' -o -name '*.cpp' \) -print | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
