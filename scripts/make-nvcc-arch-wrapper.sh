#!/usr/bin/env bash
# Writes a compiler wrapper that builds Ondine's kernels for another GPU architecture than
# the sm_80 Kokkos 3.4.1 is configured for (Kokkos_ARCH_AMPERE80, the newest it knows):
# Kokkos' nvcc_wrapper with its -arch=sm_80 replaced. For `make cuda CUDA_ARCH=sm_90`
# (H100/H200: their own machine code, no JIT of the PTX at the first launch of each kernel).
#   scripts/make-nvcc-arch-wrapper.sh OUT KOKKOS_CUDA_PREFIX ARCH      ARCH: sm_NN
set -euo pipefail
out=${1:?usage: make-nvcc-arch-wrapper.sh OUT KOKKOS_CUDA_PREFIX ARCH}
kokkos=${2:?}
arch=${3:?}
if ! [[ $arch =~ ^sm_[0-9]+a?$ ]]; then
  echo "make-nvcc-arch-wrapper.sh: CUDA_ARCH=$arch: expected sm_NN (e.g. sm_90)" >&2; exit 2
fi
mkdir -p "$(dirname "$out")"
tmp=$(mktemp "$out.XXXXXX")
cat > "$tmp" <<WRAP
#!/usr/bin/env bash
# Kokkos' nvcc_wrapper building for $arch (written by scripts/make-nvcc-arch-wrapper.sh)
exec "$kokkos/bin/nvcc_wrapper" "\${@/-arch=sm_80/-arch=$arch}"
WRAP
chmod +x "$tmp"
mv "$tmp" "$out"
