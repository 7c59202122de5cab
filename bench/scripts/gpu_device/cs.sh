#!/bin/bash
# collidescope through the bundle: CS_MODE=bundled (default: Debian's loader and glibc from lib/)
# or system (the machine's loader and glibc, the bundle's other libraries via /tmp/libsys).
# NVDIR: the folder of libEGL_nvidia.so.0, searched after the bundle.
B=$(cd "$(dirname "$0")" && pwd)
NVDIR=${NVDIR:-/usr/local/nvidia/lib64}
if [ "${CS_MODE:-bundled}" = bundled ]; then
  exec "$B/lib/ld-linux-x86-64.so.2" --library-path "$B/lib:$NVDIR" "$B/collidescope" "$@"
else
  LD_LIBRARY_PATH="/tmp/libsys:$NVDIR" exec "$B/collidescope" "$@"
fi
