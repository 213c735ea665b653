# Ondine: the two commands of the quick start are `make run` and `make test`.
# Both set up the dependencies on first use (scripts/setup-deps.sh), configure and build.
BUILD    ?= build
CASE     ?= cases/taylor_green_2d.yaml
ARGS     ?=
JOBS     ?= $(shell nproc)
KOKKOS   ?= $(if $(ONDINE_KOKKOS_ROOT),$(ONDINE_KOKKOS_ROOT),$(CURDIR)/.deps/kokkos)
export OMP_PROC_BIND ?= spread
export OMP_PLACES    ?= threads

.PHONY: all setup configure build run test clean

all: build

setup:
	@scripts/setup-deps.sh

$(BUILD)/CMakeCache.txt: | setup
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$(KOKKOS)"

configure: setup $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

run: build
	$(BUILD)/ondine run $(CASE) $(ARGS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j 1

clean:
	rm -rf $(BUILD) out
