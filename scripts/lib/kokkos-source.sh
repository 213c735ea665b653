# shellcheck shell=bash
# Sourced by scripts/setup-deps.sh and scripts/setup-kokkos-cuda.sh (not run on its own).
# kokkos_source DEPS: prints the path of the Kokkos 3.4.1 source tree extracted from
# Debian's trilinos source package under DEPS/src, downloading the package and
# extracting packages/kokkos first if needed (the download needs dpkg-dev, which
# scripts/setup-deps.sh installs). The caller defines log and as_root; everything
# but the path goes to stderr.
kokkos_source() {
  local src="$1/src"
  _kokkos_source_fetch "$src" >&2 || return 1
  ls -d "$src"/*/packages/kokkos | head -n1
}

_kokkos_source_fetch() {
  local src="$1" tarball list
  mkdir -p "$src"
  # The orig tarball unpacks as Trilinos-trilinos-release-13-2-0/.
  if ls "$src"/*/packages/kokkos/CMakeLists.txt >/dev/null 2>&1; then return 0; fi
  if ! ls "$src"/trilinos_*.orig.tar.* >/dev/null 2>&1; then
    # Debian's Kokkos binary package is Serial-only; the source package carries Kokkos 3.4.1.
    list=/etc/apt/sources.list.d/ondine-deb-src.sources
    if ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ && ! grep -qs '^deb-src' /etc/apt/sources.list; then
      log "adding a deb-src entry ($list)"
      printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm bookworm-updates\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
        | as_root tee "$list" >/dev/null
      as_root apt-get update -qq
    fi
    log "downloading Debian's trilinos source package"
    (cd "$src" && apt-get source --download-only -qq trilinos)
  fi
  tarball=$(ls "$src"/trilinos_*.orig.tar.* | head -n1)
  log "extracting packages/kokkos from $(basename "$tarball")"
  tar -xf "$tarball" -C "$src" --wildcards '*/packages/kokkos/*'
}
