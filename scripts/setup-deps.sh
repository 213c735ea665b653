#!/usr/bin/env bash
# Installs Ondine's dependencies on Debian 12 and builds Kokkos (OpenMP + Serial)
# from Debian's own trilinos source package into a project-local prefix.
# Idempotent: a second run installs nothing and rebuilds nothing.
#
#   scripts/setup-deps.sh            # apt packages + Kokkos OpenMP into .deps/kokkos
#   ONDINE_KOKKOS_ROOT=/opt/kokkos   # use a Kokkos you already have (any 3.4+ / 4.x)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
deps="$root/.deps"
prefix="$deps/kokkos"
stamp="$prefix/.ondine-kokkos-3.4.1-openmp"

log() { printf '[setup] %s\n' "$*"; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null 2>&1; then sudo "$@"
  else
    log "need root to run: $*"; exit 1
  fi
}

# --- 1. Debian packages ------------------------------------------------------
packages=(build-essential cmake pkg-config dpkg-dev xz-utils
          libeigen3-dev libyaml-cpp-dev catch2
          openmpi-bin libopenmpi-dev libhdf5-openmpi-dev hdf5-tools
          libcli11-dev nlohmann-json3-dev libassimp-dev
          python3-matplotlib python3-numpy python3-h5py python3-scipy)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  log "installing: ${missing[*]}"
  as_root apt-get update -qq
  DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  log "Debian packages present"
fi

# --- 2. Kokkos with OpenMP ---------------------------------------------------
if [ -n "${ONDINE_KOKKOS_ROOT:-}" ]; then
  log "using Kokkos from ONDINE_KOKKOS_ROOT=$ONDINE_KOKKOS_ROOT"; exit 0
fi
if [ -f "$stamp" ]; then
  log "Kokkos (OpenMP) cached in $prefix"; exit 0
fi

# shellcheck source=lib/kokkos-source.sh
. "$root/scripts/lib/kokkos-source.sh"
kokkos_src=$(kokkos_source "$deps")

log "building Kokkos (OpenMP + Serial) from $kokkos_src"
rm -rf "$deps/kokkos-build"
cmake -S "$kokkos_src" -B "$deps/kokkos-build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_CXX_STANDARD=17 \
  -DKokkos_ENABLE_OPENMP=ON -DKokkos_ENABLE_SERIAL=ON \
  -DBUILD_SHARED_LIBS=OFF -DCMAKE_POSITION_INDEPENDENT_CODE=ON >/dev/null
cmake --build "$deps/kokkos-build" -j "$(nproc)" >/dev/null
cmake --install "$deps/kokkos-build" >/dev/null
touch "$stamp"
log "Kokkos installed in $prefix"
