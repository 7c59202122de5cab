# Debian package helpers shared by scripts/setup.sh and scripts/fuzz.sh (sourced, not run).
# The sourcing script defines log() first. Packages already installed are skipped, and when
# nothing is missing apt is not touched at all; runs apt as root, or through sudo.

as_root() {
  if [ "$(id -u)" -eq 0 ]; then
    "$@"
  elif command -v sudo >/dev/null 2>&1; then
    sudo "$@"
  else
    echo "$(basename "$0"): error: not root and no sudo; run as root: $*" >&2
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
