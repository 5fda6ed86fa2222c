# Thin wrapper over the CMake presets; every target installs what is missing first.
# In CI (CI=true) the `ci` preset adds -Werror.
PRESET ?= $(if $(CI),ci,release)
JOBS ?= 2
BUILD := build/$(PRESET)
LOCUS := $(BUILD)/cli/locus
BENCH := $(BUILD)/bench/locus-bench

.PHONY: all deps configure build demo test install fuzz mutants bench notebooks format clean

all: build

deps:
	@scripts/install-deps

configure: deps
	@cmake --preset $(PRESET) >/dev/null

build: configure
	@cmake --build --preset $(PRESET) -j $(JOBS)

demo: build
	$(LOCUS) demo -o locus-demo.png

test: build
	ctest --preset $(PRESET) -j $(JOBS)

# The executable, its image module, headers, CMake package files, docs and examples under
# PREFIX; the tree may be moved afterwards.
PREFIX ?= /usr/local
install: build
	cmake --install $(BUILD) --prefix $(PREFIX)

# The libFuzzer targets (tests/fuzz), FUZZ_SECONDS each (CI: 20).
FUZZ_SECONDS ?= 60
fuzz:
	scripts/run-fuzzers --seconds $(FUZZ_SECONDS)

# Small mutations of the core, each of which the tests must catch (docs/mutants.md).
mutants: build
	JOBS=$(JOBS) scripts/mutants --preset $(PRESET)

bench: build
	$(BENCH) groebner

notebooks: deps
	scripts/run-notebooks

format:
	@git ls-files '*.h' '*.cpp' | xargs clang-format -i

clean:
	rm -rf build
