#!/usr/bin/env bash
# The README's two commands as a new user meets them: on a bare Debian 12 (bookworm) system
# made for the run with debootstrap (minbase: no compiler, no cmake, nothing that
# scripts/setup.sh does not install), in a fresh clone of this repository's HEAD, command (a)
# then command (b), verbatim as README.md has them. Reports each with its time, and the last
# lines of a failure. CI runs it (.ci/run); docs/how-to/fresh-machine.md says how and why.
#
# Usage: scripts/fresh-machine.sh [OPTIONS]
#   --commands LIST   what to run, in order, comma-separated (default a,b):
#                       a        README command (a), the main job
#                       a-setup  command (a) up to the build of `collidescope` (setup,
#                                configure, build), without its record and replay
#                       b        README command (b), the tests
#   --dir DIR         where the bare system goes (default: a new folder under /var/tmp)
#   --keep            keep the system afterwards (enter it with: chroot DIR/root bash)
#   --apt-cache DIR   keep the .deb files apt downloads in DIR between runs (only faster; the
#                     system is still bare). Off by default and in CI.
#   --mirror URL      Debian mirror (default: the host's own bookworm source)
#   --quiet           the commands' output to the logs only, not to stdout
#   --print-commands  print the commands it would run, one per line, and exit
#   --tests-not-run LOG  print the tests that ctest's summary in LOG lists as not run (skipped,
#                     not run, disabled) and exit 1 when there are any, 0 when none: the check
#                     applied to each command's log (no root needed)
# Exit status: 0 every command passed, 1 a command failed, 2 this script could not run
# (usage, not root, debootstrap failed).
#
# From the host it copies into the system only what any machine on the same network has to
# reach the package registries: /etc/resolv.conf, the CA certificates under
# /usr/local/share/ca-certificates, npm's client configuration (user and global npmrc: setup
# fetches the dragon from the registry they name), and
# proxy variables (http_proxy, https_proxy, no_proxy) when set.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
commands=a,b
dir=""
keep=0
apt_cache=""
mirror=""
quiet=0
print_only=0
check_log=""

log() { echo "fresh-machine: $*"; }
die() { echo "fresh-machine: error: $*" >&2; exit 2; }

while [ $# -gt 0 ]; do
  case "$1" in
    --commands) commands=${2:?--commands needs a list}; shift 2 ;;
    --dir) dir=${2:?--dir needs a folder}; shift 2 ;;
    --keep) keep=1; shift ;;
    --apt-cache) apt_cache=${2:?--apt-cache needs a folder}; shift 2 ;;
    --mirror) mirror=${2:?--mirror needs a URL}; shift 2 ;;
    --quiet) quiet=1; shift ;;
    --print-commands) print_only=1; shift ;;
    --tests-not-run) check_log=${2:?--tests-not-run needs a log file}; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option '$1' (see --help)" ;;
  esac
done

# --- the checks of a command's log ---------------------------------------------------------------
# The tests ctest lists under "The following tests did not run:" (skipped, not run, disabled):
# on a bare system that setup made, every test must run, so a skip fails the command (a test
# guard also fails under CI=true, tests/support/ci.hpp; this catches any other kind of skip).
tests_not_run() {
  awk '/^The following tests did not run:/ { listing = 1; next }
       listing && /^[[:space:]]+[0-9]+ - / { print; next }
       { listing = 0 }' "$1"
}

if [ -n "$check_log" ]; then
  [ -r "$check_log" ] || die "cannot read $check_log"
  not_run=$(tests_not_run "$check_log")
  [ -z "$not_run" ] && exit 0
  echo "$not_run"
  exit 1
fi

# The command in the ```sh block right after <!-- MARKER --> in README.md.
readme_command() {
  awk -v marker="<!-- $1 -->" '
    $0 == marker { after = 1; next }
    after && $0 == "```sh" { inblock = 1; next }
    inblock { print; exit }
  ' "$repo/README.md"
}

# Command (a) up to the build of the collidescope target: everything before its first run of
# the built binary.
setup_part() {
  local command=$1
  echo "${command%% && build/app/collidescope *}"
}

command_for() {
  case "$1" in
    a) readme_command readme-command-a ;;
    a-setup) setup_part "$(readme_command readme-command-a)" ;;
    b) readme_command readme-command-b ;;
    *) die "unknown command '$1' in --commands (a, a-setup or b)" ;;
  esac
}

IFS=, read -r -a names <<<"$commands"
[ "${#names[@]}" -gt 0 ] || die "--commands is empty"
declare -A to_run
for name in "${names[@]}"; do
  to_run[$name]=$(command_for "$name")
  [ -n "${to_run[$name]}" ] || die "README.md has no command for '$name' (its <!-- readme-command-* --> block)"
done
if [ "$print_only" -eq 1 ]; then
  for name in "${names[@]}"; do echo "${to_run[$name]}"; done
  exit 0
fi

[ "$(id -u)" -eq 0 ] || die "needs root (debootstrap, chroot, mount); run it with sudo"
[ -r /etc/debian_version ] || die "needs a Debian host for debootstrap"
git -C "$repo" rev-parse --verify -q HEAD >/dev/null || die "$repo is not a git checkout with a commit"
if ! command -v debootstrap >/dev/null 2>&1; then
  log "installing debootstrap on the host (apt-get)"
  # shellcheck source=apt_packages.sh
  source "$repo/scripts/apt_packages.sh"
  install_packages debootstrap
fi

# The host's own Debian mirror, so the system reaches what the host reaches.
if [ -z "$mirror" ]; then
  mirror=$(grep -rhoE '^(URIs:|deb) +[a-z]+://[^ ]+/debian/?( |$)' /etc/apt/sources.list /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list 2>/dev/null \
    | head -n 1 | awk '{print $2}') || true
  mirror=${mirror:-http://deb.debian.org/debian}
fi
security_mirror="${mirror%/debian*}/debian-security"

if [ -z "$dir" ]; then
  dir=$(mktemp -d /var/tmp/collidescope-fresh.XXXXXX)
else
  mkdir -p "$dir"
fi
dir=$(cd "$dir" && pwd)
root="$dir/root"
logs="$dir/logs"
mkdir -p "$logs"
[ ! -e "$root" ] || die "$root exists already: give another --dir, or remove it"

# --- cleanup: never remove a folder that still has something mounted below it ---------------
mounts_below() { awk -v r="$root" '$2 == r || index($2, r "/") == 1 { print $2 }' /proc/mounts | sort -r; }
cleanup() {
  local status=$? pid mount
  [ -d "$root" ] || return "$status"
  for pid in /proc/[0-9]*; do  # processes a command left running inside the system
    if [ "$(readlink "$pid/root" 2>/dev/null)" = "$root" ]; then kill -9 "${pid#/proc/}" 2>/dev/null || true; fi
  done
  while read -r mount; do
    [ -n "$mount" ] && { umount "$mount" 2>/dev/null || umount -l "$mount" 2>/dev/null || true; }
  done < <(mounts_below)
  if [ -n "$(mounts_below)" ]; then
    echo "fresh-machine: warning: still mounted below $root; not removing it" >&2
  elif [ "$keep" -eq 0 ]; then
    rm -rf --one-file-system "$root"
  else
    log "kept the system in $root (logs in $logs)"
  fi
  return "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# --- the bare system -------------------------------------------------------------------------
head=$(git -C "$repo" rev-parse --short=12 HEAD)
log "bare Debian 12 (debootstrap minbase) in $root from $mirror; logs in $logs"
started=$SECONDS
debootstrap_ok=0
for attempt in 1 2 3; do
  rm -rf --one-file-system "$root"
  if debootstrap --variant=minbase bookworm "$root" "$mirror" >"$logs/debootstrap.log" 2>&1; then
    debootstrap_ok=1
    break
  fi
  log "debootstrap failed (attempt $attempt of 3): $(grep -E '^(E|W):' "$logs/debootstrap.log" | tail -n 1)"
  sleep $((attempt * 10))
done
if [ "$debootstrap_ok" -eq 0 ]; then
  tail -n 20 "$logs/debootstrap.log" >&2
  die "debootstrap failed three times; its log: $logs/debootstrap.log"
fi
debootstrap_seconds=$((SECONDS - started))
log "bare system ready in ${debootstrap_seconds} s ($(cat "$root/etc/debian_version"), $(du -sm "$root" | cut -f1) MB)"

# A stock Debian 12 machine's sources: the release, its updates and security.
cat >"$root/etc/apt/sources.list" <<EOF
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb $security_mirror bookworm-security main
EOF

# What a machine on this network has to reach the registries, and nothing else.
cp -L /etc/resolv.conf "$root/etc/resolv.conf"
if compgen -G "/usr/local/share/ca-certificates/*" >/dev/null; then
  mkdir -p "$root/usr/local/share/ca-certificates"
  cp -rL /usr/local/share/ca-certificates/. "$root/usr/local/share/ca-certificates/"
fi
copy_npmrc() {  # host file -> same path in the system
  [ -f "$1" ] || return 0
  mkdir -p "$root$(dirname "$1")"
  cp -L "$1" "$root$1"
}
copy_npmrc "${HOME:-/root}/.npmrc"
if command -v npm >/dev/null 2>&1; then
  copy_npmrc "$(npm config get globalconfig 2>/dev/null || true)"
  copy_npmrc "$(npm config get userconfig 2>/dev/null || true)"
fi
# Debian's npm reads /etc/npmrc as its global configuration; a host whose npm keeps it
# elsewhere (/usr/etc/npmrc for a NodeSource node) gets the same settings there.
for npmrc in /usr/etc/npmrc /usr/local/etc/npmrc; do
  if [ -f "$npmrc" ] && [ ! -f "$root/etc/npmrc" ]; then cp -L "$npmrc" "$root/etc/npmrc"; fi
done
# The user's .npmrc belongs to root in the system (the commands run as root).
if [ "${HOME:-/root}" != /root ] && [ -f "$root${HOME}/.npmrc" ]; then cp "$root${HOME}/.npmrc" "$root/root/.npmrc"; fi

mount -t proc proc "$root/proc"
mount -t sysfs sysfs "$root/sys"
mount --rbind /dev "$root/dev"
mount --make-rslave "$root/dev"
if [ -n "$apt_cache" ]; then
  mkdir -p "$apt_cache/partial"
  mount --bind "$apt_cache" "$root/var/cache/apt/archives"
fi

# A fresh clone of HEAD (committed work only), as a new user would get it.
checkout=/root/collidescope
git -c advice.detachedHead=false clone -q --no-hardlinks "$repo" "$root$checkout"
git -C "$root$checkout" -c advice.detachedHead=false checkout -q --detach "$(git -C "$repo" rev-parse HEAD)"
log "cloned HEAD $head into $checkout"

# The phases of a command's log: the traced commands (marker lines "+fresh-machine-phase EPOCH
# COMMAND", the last one "(end)"), each with the seconds until the next, and below a traced
# command the phases it reported itself ("sanitize: phase NAME took N s").
phase_table() {
  local label=$1 log_file=$2
  awk -v marker="$phase_marker" -v label="$label" '
    function flush() {
      if (name != "" && name !~ /^cd /) {
        printf "fresh-machine:   %-4s %-62s %6d s\n", label, substr(name, 1, 62), epoch - start
        for (k = 1; k <= inner; ++k) print inner_lines[k]
      }
      inner = 0
    }
    index($0, marker " ") == 1 {
      epoch = $2
      flush()
      start = $2
      name = $0
      sub(/^[^ ]+ [^ ]+ /, "", name)
      next
    }
    /^sanitize: phase .* took [0-9]+ s$/ {
      line = $0
      sub(/^sanitize: phase /, "", line)
      seconds = line; sub(/.* took /, "", seconds); sub(/ s$/, "", seconds)
      sub(/ took [0-9]+ s$/, "", line)
      inner_lines[++inner] = sprintf("fresh-machine:          %-57s %6d s", "sanitize.sh: " line, seconds)
    }
  ' "$log_file"
}

# --- the commands ------------------------------------------------------------------------------
environment=(HOME=/root LANG=C.UTF-8 TERM=dumb PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin)
for variable in CI http_proxy https_proxy no_proxy HTTP_PROXY HTTPS_PROXY NO_PROXY; do
  if [ -n "${!variable:-}" ]; then environment+=("$variable=${!variable}"); fi
done

declare -A result seconds
failed=""
# Each simple command of a README command is traced (bash's xtrace; the command's text is run as
# it is written) with the time it started, so the report can say where the time went; the
# scripts it starts are not traced, and scripts/sanitize.sh says its own phases' times.
phase_marker="+fresh-machine-phase"
for name in "${names[@]}"; do
  if [ -n "$failed" ]; then
    result[$name]="not run (command ($failed) failed)"
    continue
  fi
  log "command ($name): ${to_run[$name]}"
  started=$SECONDS
  traced="PS4='$phase_marker \$(date +%s) '; set -x; cd $checkout && ${to_run[$name]}"
  set +e
  if [ "$quiet" -eq 1 ]; then
    chroot "$root" /usr/bin/env -i "${environment[@]}" bash -c "$traced" \
      </dev/null >"$logs/command-$name.log" 2>&1
    status=$?
  else
    chroot "$root" /usr/bin/env -i "${environment[@]}" bash -c "$traced" \
      </dev/null 2>&1 | tee "$logs/command-$name.log"
    status=${PIPESTATUS[0]}
  fi
  set -e
  seconds[$name]=$((SECONDS - started))
  echo "$phase_marker $(date +%s) (end)" >>"$logs/command-$name.log"
  not_run=$(tests_not_run "$logs/command-$name.log")
  if [ "$status" -eq 0 ] && [ -n "$not_run" ]; then
    result[$name]="FAILED (tests skipped or not run)"
    failed=$name
    log "command ($name): ctest passed, but these tests did not run (a skip is a failure here):"
    echo "$not_run" | sed 's/^/  | /'
  elif [ "$status" -eq 0 ]; then
    result[$name]="passed"
  else
    result[$name]="FAILED (exit $status)"
    failed=$name
  fi
  log "command ($name): ${result[$name]} in ${seconds[$name]} s"
done

# --- the report --------------------------------------------------------------------------------
echo
log "report: HEAD $head on a bare Debian $(cat "$root/etc/debian_version") (debootstrap minbase, ${debootstrap_seconds} s)"
for name in "${names[@]}"; do
  printf 'fresh-machine:   command (%s)  %-32s %s\n' "$name" "${result[$name]}" \
    "${seconds[$name]:+${seconds[$name]} s, log $logs/command-$name.log}"
done
echo
log "phase times (cold: a new system, nothing built; the sum is CI's time less the clone):"
printf 'fresh-machine:   %-67s %6d s\n' "debootstrap" "$debootstrap_seconds"
total=$debootstrap_seconds
for name in "${names[@]}"; do
  [ -f "$logs/command-$name.log" ] || continue
  phase_table "($name)" "$logs/command-$name.log"
  total=$((total + ${seconds[$name]:-0}))
done
printf 'fresh-machine:   %-67s %6d s\n' "total" "$total"
if [ -n "$failed" ]; then
  echo
  log "the last lines of command ($failed):"
  tail -n 40 "$logs/command-$failed.log" | sed 's/^/  | /'
  exit 1
fi
