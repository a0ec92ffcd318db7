# Thin wrapper over CMake. `make demo` and `make test` work on a fresh Debian 12
# machine: the first step installs the missing Debian packages.

BUILD_DIR ?= build
JOBS ?= $(shell nproc)

.DEFAULT_GOAL := build
.PHONY: deps configure build demo test bench tile-simulation format doc pictures clean fuzz-deps \
        fuzz-build fuzz fuzz-ci sanitize-configure sanitize

deps:
	@scripts/install_dependencies.sh

# Configure only once; afterwards the generated build system re-runs CMake itself
# when a CMakeLists.txt changes. A failed configuration removes the cache so that
# the next `make` tries again.
$(BUILD_DIR)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release || { rm -f $@; exit 1; }

configure: $(BUILD_DIR)/CMakeCache.txt

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	$(BUILD_DIR)/src/tspline/tspline demo --output out/demo

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) --no-tests=error

bench: build
	@found=0; \
	for exe in $(BUILD_DIR)/benchmark/bench_*; do \
	  if [ -f "$$exe" ] && [ -x "$$exe" ]; then \
	    found=1; echo "== $$exe"; "$$exe" || exit 1; \
	  fi; \
	done; \
	if [ $$found -eq 0 ]; then echo "no benchmark executables in $(BUILD_DIR)/benchmark"; fi

# The tile-parallel simulation of doc/design/tile_parallel.md (not built by default):
# TILE_ARGS='--n 10000000' for the design's 10^7 points.
TILE_ARGS ?=
tile-simulation: configure
	cmake --build $(BUILD_DIR) --target tile_simulation -j $(JOBS)
	$(BUILD_DIR)/tile_simulation $(TILE_ARGS)

format: deps
	find include src test examples benchmark \( -name '*.h' -o -name '*.cpp' \) -print0 \
	  | xargs -0 -r clang-format -i

# Regenerates the pictures of README.md and the manual (doc/Triangular_spline/fig/).
pictures: build
	BUILD_DIR=$(BUILD_DIR) scripts/make_pictures.sh

doc: deps
	mkdir -p build/doc
	doxygen doc/Doxyfile

# libFuzzer harnesses of the readers (fuzz/), built with clang++ in a tree of their own: each
# runs FUZZ_SECONDS on a corpus seeded from data/ and data/bad/; the target fails and names the
# input if one finds a crash, a sanitizer report, a leak, a timeout or 2 GB of memory.
FUZZ_BUILD_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 2

fuzz-deps:
	@scripts/install_dependencies.sh --fuzz

$(FUZZ_BUILD_DIR)/CMakeCache.txt: | fuzz-deps
	cmake -S fuzz -B $(FUZZ_BUILD_DIR) -DCMAKE_CXX_COMPILER=clang++ || { rm -f $@; exit 1; }

fuzz-build: $(FUZZ_BUILD_DIR)/CMakeCache.txt
	cmake --build $(FUZZ_BUILD_DIR) --target fuzzers -j $(FUZZ_JOBS)

fuzz: fuzz-build
	FUZZ_JOBS=$(FUZZ_JOBS) fuzz/run_fuzzers.sh $(FUZZ_BUILD_DIR) $(FUZZ_SECONDS)

# What CI runs after `make test`: 30 s per reader, with a fixed seed so that a run here and
# on CI explore the same inputs (new findings come from `make fuzz`, with random seeds).
fuzz-ci:
	FUZZ_SEED=1 $(MAKE) fuzz FUZZ_SECONDS=30

# The tests, examples and CLI with AddressSanitizer and UndefinedBehaviorSanitizer (g++);
# any report fails its test. About an hour on two cores.
SANITIZE_BUILD_DIR ?= build-sanitize
SANITIZE_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=undefined \
                  -fno-omit-frame-pointer -O1 -g

# -DNDEBUG as in Release: the CLI is checked as it ships (tests and examples undefine it).
$(SANITIZE_BUILD_DIR)/CMakeCache.txt: | deps
	cmake -S . -B $(SANITIZE_BUILD_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$(SANITIZE_FLAGS) -DNDEBUG" \
	  -DTRIANGULAR_SPLINE_BUILD_BENCHMARKS=OFF || { rm -f $@; exit 1; }

sanitize-configure: $(SANITIZE_BUILD_DIR)/CMakeCache.txt

# The Python tests (and the install test, which imports the module) load the instrumented
# module into an uninstrumented python: the ASan runtime must come first, and CPython's own
# allocations at exit are not leaks of ours.
SANITIZE_PRELOAD = $$($(CXX) -print-file-name=libasan.so):$$($(CXX) -print-file-name=libubsan.so)

sanitize: sanitize-configure
	cmake --build $(SANITIZE_BUILD_DIR) -j $(JOBS)
	cd $(SANITIZE_BUILD_DIR) && UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j $(JOBS) --no-tests=error -E '^(python|install)[.]'
	cd $(SANITIZE_BUILD_DIR) && LD_PRELOAD="$(SANITIZE_PRELOAD)" ASAN_OPTIONS=detect_leaks=0 \
	  UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -R '^(python|install)[.]'

clean:
	rm -rf $(BUILD_DIR) out build/doc $(FUZZ_BUILD_DIR) $(SANITIZE_BUILD_DIR)
