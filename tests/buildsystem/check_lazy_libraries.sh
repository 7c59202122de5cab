#!/usr/bin/env bash
# Mesa's OSMesa (with LLVM) and FFmpeg's libraries are opened on first use, never linked
# (docs/explanation/architecture.md, "Libraries loaded on first use"): a command that renders and encodes
# nothing starts without them. Usage: check_lazy_libraries.sh EXECUTABLE_OR_LIBRARY...
set -euo pipefail
status=0
for binary in "$@"; do
  needed=$(readelf -d "$binary" | awk '/\(NEEDED\)/ {gsub(/[\[\]]/, "", $5); print $5}')
  # The check must see the dynamic section at all (a wrong path would pass vacuously).
  if ! grep -q '^libc\.so\.' <<<"$needed"; then
    echo "$binary: no NEEDED entry for libc (not a dynamic executable?)"
    status=1
  fi
  heavy=$(grep -E '^lib(OSMesa|avcodec|avformat|avfilter|avutil|swscale)\.so' <<<"$needed" || true)
  if [ -n "$heavy" ]; then
    echo "$binary links what it should open on first use (collidescope/shared_library.hpp):" $heavy
    status=1
  fi
done
exit $status
