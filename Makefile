# PRISCA Lab — the commands a newcomer needs.
#   make run    install missing Debian packages, build, start the application
#   make test   install missing Debian packages, build, run the whole test suite (offscreen)
#   make bench  build in release mode and run the benchmarks
BUILD_DIR ?= build
PRESET    ?= default
JOBS      ?= $(shell nproc)

.PHONY: all deps configure build run test bench format clean

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

bench: build
	cd $(BUILD_DIR) && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -L benchmark --verbose

format:
	find app core sim devices tests -name '*.h' -o -name '*.cpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
