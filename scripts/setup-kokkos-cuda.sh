#!/usr/bin/env bash
# Builds Kokkos 3.4.1 with CUDA (+ Serial on the host) into .deps/kokkos-cuda for
# `make cuda`, from the same Debian trilinos source as scripts/setup-deps.sh,
# patched for CUDA 13 (scripts/patches/*.patch, each says why).
# Idempotent: a stamp file records the patches and options of the installed build.
# Skips (exit 0) where there is no nvcc.
#
#   scripts/setup-kokkos-cuda.sh
#   ONDINE_CUDA_ROOT=/usr/local/cuda   # the CUDA toolkit (default)
#
# Architecture: Kokkos_ARCH_AMPERE80 (sm_80; the newest Kokkos 3.4 knows). nvcc
# embeds compute_80 PTX as well, so Hopper (sm_90) GPUs run it after a JIT step.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
deps="$root/.deps"
prefix="$deps/kokkos-cuda"
src_copy="$deps/kokkos-cuda-src"
build="$deps/kokkos-cuda-build"
stamp="$prefix/.ondine-kokkos-3.4.1-cuda"
cuda="${ONDINE_CUDA_ROOT:-/usr/local/cuda}"
arch=AMPERE80

log() { printf '[setup-cuda] %s\n' "$*"; }
as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null 2>&1; then sudo "$@"
  else
    log "need root to run: $*"; exit 1
  fi
}

if [ ! -x "$cuda/bin/nvcc" ]; then
  log "no nvcc at $cuda/bin/nvcc: skipping the CUDA build of Kokkos (set ONDINE_CUDA_ROOT)"
  exit 0
fi
export PATH="$cuda/bin:$PATH"  # nvcc_wrapper calls the nvcc on PATH

patches=("$root"/scripts/patches/kokkos-3.4.1-*.patch)
want=$( { cat "${patches[@]}"; echo "arch=$arch cuda=$cuda $(nvcc --version | tail -n1)"; } | sha256sum | cut -d' ' -f1)
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
  log "Kokkos (CUDA) cached in $prefix"; exit 0
fi

# The pristine source: extracted by scripts/setup-deps.sh (which also installs
# dpkg-dev and the build tools); re-extracted here if it has gone since.
# shellcheck source=lib/kokkos-source.sh
. "$root/scripts/lib/kokkos-source.sh"
if ! ls "$deps"/src/*/packages/kokkos/CMakeLists.txt >/dev/null 2>&1; then
  "$root/scripts/setup-deps.sh"
fi
kokkos_src=$(kokkos_source "$deps")

log "copying $kokkos_src to $src_copy and patching it for CUDA 13"
rm -rf "$src_copy" "$build"
cp -a "$kokkos_src" "$src_copy"
for p in "${patches[@]}"; do
  log "  $(basename "$p")"
  patch -d "$src_copy" -p1 --forward --silent < "$p"
done

log "building Kokkos (CUDA $arch + Serial) with $(nvcc --version | tail -n1)"
start=$(date +%s)
cmake -S "$src_copy" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$src_copy/bin/nvcc_wrapper" -DCMAKE_CXX_STANDARD=17 \
  -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DKokkos_ENABLE_CUDA=ON -DKokkos_ENABLE_CUDA_LAMBDA=ON -DKokkos_ARCH_"$arch"=ON \
  -DKokkos_ENABLE_SERIAL=ON \
  -DBUILD_SHARED_LIBS=OFF -DCMAKE_POSITION_INDEPENDENT_CODE=ON >/dev/null
cmake --build "$build" -j "$(nproc)" >/dev/null
rm -rf "$prefix"
cmake --install "$build" >/dev/null
echo "$want" > "$stamp"
log "Kokkos (CUDA) installed in $prefix in $(( $(date +%s) - start )) s; compiler: $prefix/bin/nvcc_wrapper"
