# The two commands of the README:
#   make demo   installs what is missing, builds, runs the main job on a generated scene
#   make test   installs what is missing, builds, runs every test
BUILD_DIR ?= build
BUILD_TYPE ?= Release
CMAKE_ARGS ?=
JOBS ?= $(shell nproc)

.PHONY: all deps build demo test doc format-check clean

all: build

deps:
	bash scripts/install_deps.sh

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_ARGS)
	cmake --build $(BUILD_DIR) -j$(JOBS)

demo: build
	bash scripts/demo.sh $(BUILD_DIR)/bin out/demo

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j$(JOBS)

# The API reference of every public header (build/doc/html); a Doxygen warning fails.
doc: deps
	doxygen doc/Doxyfile

# Every tracked C++ file formatted by .clang-format.
format-check: deps
	bash scripts/check_format.sh

clean:
	rm -rf $(BUILD_DIR) out
