#!/usr/bin/env bash
# No library object may call a GL function through a linked symbol: libOSMesa and libEGL's
# vendors export the same names, and a call bound to the wrong one silently does nothing under
# the other context. Every GL call goes through the current context's table
# (platform/include/collidescope/gl_api.hpp). Usage: check_gl_symbols.sh LIBRARY.a...
set -euo pipefail
status=0
for library in "$@"; do
  direct=$(nm -u "$library" | awk '$1 == "U" && $2 ~ /^gl[A-Z]/ {print $2}' | sort -u)
  if [ -n "$direct" ]; then
    echo "$library calls GL through linked symbols (call them through gl_api.hpp):" $direct
    status=1
  fi
  # The check must see the archive's objects at all (a wrong path would pass vacuously).
  if ! nm "$library" | awk '$2 == "T" {found = 1} END {exit !found}'; then
    echo "$library: no defined functions (not an archive of objects?)"
    status=1
  fi
done
exit $status
