# Debian package helpers shared by scripts/setup.sh, scripts/fuzz.sh and
# scripts/fresh-machine.sh (sourced, not run). The sourcing script defines log() first.
# Packages already installed are skipped, and when nothing is missing apt is not touched at
# all; runs apt as root, or through sudo. A failure says which step failed, apt's own error
# lines, and what to try.

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

# Runs one apt-get step with its output on the terminal (it is the progress a user sees) and
# a copy in a log; on failure, repeats apt's error lines and says what to try.
apt_step() {
  local what=$1 output status
  shift
  output=$(mktemp)
  set +e
  as_root env DEBIAN_FRONTEND=noninteractive apt-get "$@" 2>&1 | tee "$output"
  status=${PIPESTATUS[0]}
  set -e
  if [ "$status" -ne 0 ]; then
    {
      echo "$(basename "$0"): error: apt-get $what failed (exit $status). apt said:"
      grep -E '^(E|W|Err):' "$output" | tail -n 10 | sed 's/^/  /'
      echo "  What to try: check that this machine reaches its Debian mirror (/etc/apt/sources.list"
      echo "  and /etc/apt/sources.list.d/; proxy: http_proxy/https_proxy, or Acquire::http::Proxy"
      echo "  in /etc/apt/apt.conf.d/), run 'apt-get update' by hand to see the whole error, then"
      echo "  run this script again: it installs only what is still missing."
    } >&2
    rm -f "$output"
    exit 1
  fi
  rm -f "$output"
}

install_packages() {
  local missing
  mapfile -t missing < <(missing_packages "$@")
  if [ "${#missing[@]}" -eq 0 ]; then
    log "all ${#} packages already installed"
    return
  fi
  log "installing ${#missing[@]} missing packages with apt-get: ${missing[*]}"
  apt_step update update
  apt_step "install of ${#missing[@]} packages" install -y --no-install-recommends "${missing[@]}"
  # apt-get can exit 0 and leave a package out (held, or no candidate on this mirror).
  mapfile -t missing < <(missing_packages "${missing[@]}")
  if [ "${#missing[@]}" -ne 0 ]; then
    echo "$(basename "$0"): error: still not installed after apt-get: ${missing[*]}" \
      "(is this Debian 12 bookworm? 'apt-cache policy ${missing[0]}' says where it comes from)" >&2
    exit 1
  fi
}
