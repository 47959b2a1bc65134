# Convenience entry points; the build itself is CMake (see CMakePresets.json).
BUILD ?= build
JOBS ?= 2
FUZZ_SECONDS ?= 20
CMAKE_FLAGS ?= -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo

.PHONY: all deps test-deps configure build run test package fuzz clean

all: build

deps:
	scripts/install-deps.sh

test-deps:
	scripts/install-deps.sh --tests

configure:
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: deps configure
	cmake --build $(BUILD) -j$(JOBS)

# Installs what is missing, builds, and opens mbscope (offscreen when there is no display).
run: build
	scripts/run-mbscope.sh $(BUILD)/app/mbscope

# Installs what is missing (peers included), builds, runs the fuzzers briefly (a separate clang
# build with sanitizers), then runs every test; prints the time of each phase, then CTest's summary
# last (scripts/make-test.sh).
test:
	scripts/make-test.sh $(BUILD) $(JOBS) $(FUZZ_SECONDS) $(CMAKE_FLAGS)

# Builds the Debian package build/mbscope_VERSION_ARCH.deb (CPack; Depends computed by dpkg-shlibdeps).
package: build
	cmake --build $(BUILD) --target package

fuzz:
	scripts/fuzz.sh $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD)
