# Thin wrapper over CMake. `make demo` and `make test` work on a fresh Debian 12
# machine: the first step installs the missing Debian packages.

BUILD_DIR ?= build
JOBS ?= $(shell nproc)

.DEFAULT_GOAL := build
.PHONY: deps configure build demo test bench format doc pictures clean

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
	$(BUILD_DIR)/src/tspline/tspline demo --output-dir out/demo

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

format: deps
	find include src test examples benchmark \( -name '*.h' -o -name '*.cpp' \) -print0 \
	  | xargs -0 -r clang-format -i

# Regenerates the pictures of README.md and the manual (doc/Triangular_spline/fig/).
pictures: build
	BUILD_DIR=$(BUILD_DIR) scripts/make_pictures.sh

doc: deps
	mkdir -p build/doc
	doxygen doc/Doxyfile

clean:
	rm -rf $(BUILD_DIR) out build/doc
