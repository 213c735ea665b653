#!/usr/bin/env bash
# Packs a CUDA build of Ondine with the shared libraries it needs from Debian (HDF5, yaml-cpp,
# assimp, Open MPI and its components) into one archive, for a GPU machine that has the CUDA
# driver but not Debian's packages. glibc, libstdc++ and the driver are the machine's own.
#   perf/gpu/bundle.sh BUILD_DIR ARCHIVE      e.g. perf/gpu/bundle.sh build-cuda .gpu/bundle.tar.xz
# The archive unpacks to bin/ (ondine, ondine_bench and, where built, ondine_tests, stripped), lib/, ompi/
# (Open MPI's components), share/openmpi (its messages) and pairbench.cpp (the yardstick,
# when ../shared/perf/pairbench.cpp is beside the checkout). perf/gpu/check.sh runs it.
set -euo pipefail
build=${1:?usage: bundle.sh BUILD_DIR ARCHIVE}
archive=${2:?usage: bundle.sh BUILD_DIR ARCHIVE}
cd "$(dirname "$0")/../.."
ompi_components=/usr/lib/x86_64-linux-gnu/openmpi/lib/openmpi3
pmix_components=/usr/lib/x86_64-linux-gnu/pmix2/lib/pmix
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib" "$stage/ompi" "$stage/pmix" "$stage/share"
for exe in ondine perf/ondine_bench tests/ondine_tests; do
  if [ ! -x "$build/$exe" ]; then
    # the unit tests do not run on a GPU (perf/README.md, "GPU (CUDA)"): CI builds no CUDA ondine_tests
    [ "$exe" = tests/ondine_tests ] && continue
    echo "bundle.sh: $build/$exe is missing (build it first)" >&2; exit 1
  fi
  strip -o "$stage/bin/$(basename "$exe")" "$build/$exe"
done
cp "$ompi_components"/*.so "$stage/ompi/"
cp "$pmix_components"/*.so "$stage/pmix/" 2>/dev/null || true
cp -r /usr/share/openmpi "$stage/share/"
# the libraries every binary and component loads, less the C library's and the compiler's
# own (the machine's are newer) and the CUDA driver
skip='^(libc|libm|libdl|libpthread|librt|libresolv|libutil|ld-linux-x86-64|libstdc\+\+|libgcc_s|libcuda)\.so'
for f in "$stage"/bin/* "$stage"/ompi/*.so "$stage"/pmix/*.so; do
  ldd "$f" 2>/dev/null | awk '/=> \//{print $3}'
done | sort -u | while read -r lib; do
  name=$(basename "$lib")
  [[ $name =~ $skip ]] && continue
  cp -L "$lib" "$stage/lib/$name"
done
[ -f ../shared/perf/pairbench.cpp ] && cp ../shared/perf/pairbench.cpp "$stage/"
git describe --always --dirty > "$stage/commit"
mkdir -p "$(dirname "$archive")"
tar -C "$stage" -I "xz -T0 -6" -cf "$archive" .
echo "bundle.sh: $archive ($(du -h "$archive" | cut -f1)), $(ls "$stage/lib" | wc -l) libraries"
