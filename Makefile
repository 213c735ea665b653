# Ondine: the two commands of the quick start are `make run` and `make test`.
# Both set up the dependencies on first use (scripts/setup-deps.sh), configure and build.
BUILD    ?= build
CASE     ?= cases/dam_break_2d.yaml
ARGS     ?=
JOBS     ?= $(shell nproc)
KOKKOS   ?= $(if $(ONDINE_KOKKOS_ROOT),$(ONDINE_KOKKOS_ROOT),$(CURDIR)/.deps/kokkos)
export OMP_PROC_BIND ?= spread
export OMP_PLACES    ?= threads

.PHONY: all setup configure build run test clean cuda setup-cuda validate

# `make cuda`: the CUDA build (compiled, not run, where there is no GPU). Kokkos 3.4.1
# with CUDA goes to .deps/kokkos-cuda (scripts/setup-kokkos-cuda.sh), Ondine to
# $(BUILD_CUDA) with Kokkos' nvcc_wrapper as its C++ compiler. No nvcc: nothing to do.
BUILD_CUDA  ?= build-cuda
# the CUDA targets to build: empty, every one; CI (.ci/run) builds "ondine ondine_bench" (the unit
# tests read device views from the host and do not run on a GPU)
CUDA_TARGETS ?=
CUDA_ROOT   ?= $(if $(ONDINE_CUDA_ROOT),$(ONDINE_CUDA_ROOT),/usr/local/cuda)
KOKKOS_CUDA ?= $(CURDIR)/.deps/kokkos-cuda
CUDA_CMAKE_ARGS ?=
# CUDA_ARCH=sm_90: Ondine's kernels built for that architecture (the H100/H200's own code)
# instead of sm_80 + PTX, through scripts/make-nvcc-arch-wrapper.sh; use its own BUILD_CUDA
CUDA_ARCH   ?=
CUDA_CXX     = $(if $(CUDA_ARCH),$(CURDIR)/$(BUILD_CUDA)/nvcc_wrapper_$(CUDA_ARCH),$(KOKKOS_CUDA)/bin/nvcc_wrapper)

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

# `make validate`: the whole validation (accuracy ladders and stability suite, full level,
# about 100 min on one core: the c0 = 1480 dam break at 50 x 100 alone takes an hour); runs under $(VALIDATE_OUT), the report table and figures go into
# docs/validation.md (between its markers) and docs/validation/. Exits 1 when a run fails.
VALIDATE_OUT ?= out/validation-full
# The level interface's pressure noise of the APR dam break (issue 7) goes to docs/validation/apr_interface_noise.json.
# The cases can also run as separate processes and be merged: scripts/merge_validation.py.
# The runs join the record (docs/validation/validation.json) through scripts/merge_validation.py,
# replacing its runs of the same case, scheme and level; the report is made from the merged record.
validate: build
	$(BUILD)/ondine validate --level full --case all --out $(VALIDATE_OUT); s=$$?; \
	  /usr/bin/python3 scripts/merge_validation.py --replace $(VALIDATE_OUT)-record docs/validation $(VALIDATE_OUT) && \
	  /usr/bin/python3 scripts/plot_validation.py $(VALIDATE_OUT)-record . --docs docs/validation.md && \
	  /usr/bin/python3 scripts/apr_interface_noise.py $(VALIDATE_OUT)/apr_dam_break_2d --json docs/validation/apr_interface_noise.json && exit $$s

ifneq ($(wildcard $(CUDA_ROOT)/bin/nvcc),)
cuda setup-cuda $(BUILD_CUDA)/CMakeCache.txt: export PATH := $(CUDA_ROOT)/bin:$(PATH)

setup-cuda: setup
	@ONDINE_CUDA_ROOT="$(CUDA_ROOT)" scripts/setup-kokkos-cuda.sh

$(BUILD_CUDA)/CMakeCache.txt: | setup-cuda
	$(if $(CUDA_ARCH),scripts/make-nvcc-arch-wrapper.sh "$(CUDA_CXX)" "$(KOKKOS_CUDA)" "$(CUDA_ARCH)")
	cmake -S . -B $(BUILD_CUDA) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$(CUDA_CXX)" \
	  -DCMAKE_PREFIX_PATH="$(KOKKOS_CUDA)" $(CUDA_CMAKE_ARGS)

cuda: setup-cuda $(BUILD_CUDA)/CMakeCache.txt
	cmake --build $(BUILD_CUDA) -j $(JOBS) $(if $(CUDA_TARGETS),--target $(CUDA_TARGETS))
else
setup-cuda cuda:
	@echo "make $@: no nvcc at $(CUDA_ROOT)/bin/nvcc (set CUDA_ROOT); skipped"
endif

clean:
	rm -rf $(BUILD) out
