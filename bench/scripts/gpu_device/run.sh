#!/bin/bash
# Device run of collidescope's GPU paths through EGL on an NVIDIA GPU, with a bundle of Debian 12
# libraries (its own loader and glibc). Run from the repository root: bash .devbundle/run.sh
# Writes $OUT/log.txt, $OUT/results.tgz (stats, bench, pair digests), $OUT/frame_0041.png.
# QUICK=1 (local test): small presets instead of default.
set -u
OUT=${OUT:-/tmp/out}; mkdir -p "$OUT"
exec > >(tee "$OUT/log.txt") 2>&1
T0=$(date +%s)
DEADLINE=${DEADLINE:-240}   # seconds after start past which further checks and benches are skipped
TMO=${TMO:-50}              # per-command timeout (s)
elapsed() { echo $(( $(date +%s) - T0 )); }
B=$PWD/.devbundle
W=/tmp/cs; rm -rf $W; mkdir -p $W/stats $W/pairs
export COLLIDESCOPE_DATA=$B/data

echo "== machine"; uname -a; nvidia-smi -L; nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader
grep PRETTY /etc/os-release 2>/dev/null; ldd --version 2>/dev/null | head -1; nproc

echo "== NVIDIA EGL vendor"
VJSON=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f $VJSON ] || VJSON=$(ls /usr/local/nvidia/share/glvnd/egl_vendor.d/*.json /usr/share/glvnd/egl_vendor.d/*nvidia*.json /etc/glvnd/egl_vendor.d/*nvidia*.json 2>/dev/null | head -1)
echo "vendor json: $VJSON"; cat "$VJSON" 2>/dev/null
NVLIB=$(ls /usr/local/nvidia/lib64/libEGL_nvidia.so.0 /usr/local/nvidia/lib/libEGL_nvidia.so.0 /usr/lib/x86_64-linux-gnu/libEGL_nvidia.so.0 /usr/lib64/libEGL_nvidia.so.0 2>/dev/null | head -1)
[ -n "$NVLIB" ] || NVLIB=$(timeout 20 find / -xdev -name 'libEGL_nvidia.so.0' 2>/dev/null | head -1)
NVDIR=$(dirname "${NVLIB:-/usr/local/nvidia/lib64/x}")
echo "libEGL_nvidia: $NVLIB (dir $NVDIR)"; ls $NVDIR 2>&1 | grep -iE 'egl|glsi|eglcore|gpucomp|GLdispatch' | head -20
ls /dev/nvidia* /dev/dri 2>&1 | head
ldconfig -p 2>/dev/null | grep -iE 'libEGL|GLdispatch' | head
if [ -n "$VJSON" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$VJSON; else echo "no NVIDIA vendor json: glvnd default vendors"; fi

# Mode bundled: Debian's loader and glibc from the bundle. Mode system: the device's loader and
# glibc, the bundle's other libraries (fallback when NVIDIA's libraries need a newer glibc).
LD="$B/lib/ld-linux-x86-64.so.2"
LP="$B/lib:$NVDIR"
mkdir -p /tmp/libsys
for f in $B/lib/*; do case ${f##*/} in ld-linux*|libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|libresolv.so*|libutil.so*|libanl.so*|libnss_*) ;; *) ln -sf $f /tmp/libsys/ ;; esac; done
export CS_MODE=bundled NVDIR
CS() { "$B/cs.sh" "$@"; }
echo "== dependencies of libEGL_nvidia through the bundled loader"
"$LD" --library-path "$LP" --list "$NVLIB" 2>&1 | head -30
CS --version

# check SCENE METHOD GL [extra...]: stats + pair digest, total line in the log
check() {
  local s=$1 m=$2 gl=$3; shift 3
  [ -n "${QUICK:-}" ] && s=${s/:default/:small}
  local tag="${s//:/_}__${m}__${gl}${*:+__${@: -1}}"
  if [ "$(elapsed)" -gt "$DEADLINE" ]; then echo "SKIP (deadline) $tag"; return; fi
  local t=$(date +%s%N)
  timeout -k 5 $TMO "$B/cs.sh" \
      check --scene "$s" --method "$m" --gl "$gl" --exit-zero -q --stats $W/stats/$tag.jsonl --pairs $W/pairs/$tag.tsv "$@" 2>&1 | sed "s/^/[$tag] /"
  local rc=${PIPESTATUS[0]}
  local md5=$(md5sum < $W/pairs/$tag.tsv 2>/dev/null | cut -c1-12)
  echo "[$tag] rc=$rc wall=$(( ($(date +%s%N) - t) / 1000000 ))ms pairs_md5=$md5 renderer=$(grep -o '"renderer":"[^"]*"' $W/stats/$tag.jsonl 2>/dev/null | sort -u | tr '\n' ' ')"
  echo "$tag $md5" >> $W/pairs_md5.txt; rm -f $W/pairs/$tag.tsv
}
egl_ok() { grep -q 'via EGL' $W/stats/$1.jsonl 2>/dev/null; }

echo "== first EGL context (C:small gpu, gl egl then auto) mode $CS_MODE"
check C:small gpu egl
if ! egl_ok C_small__gpu__egl; then
  echo "== EGL FAILED in mode bundled: loader debug"
  LD_DEBUG=libs timeout 30 "$LD" --library-path "$LP" "$B/collidescope" check --scene C:small --method gpu --gl egl --frames 0:1 --exit-zero -q 2>&1 \
    | grep -iE 'egl|nvidia|glvnd|error|cannot|not found|GLIBC' | head -60
  echo "== trying mode system (device loader + glibc)"
  CS_MODE=system; LD_LIBRARY_PATH="/tmp/libsys:$NVDIR" ldd $B/collidescope 2>&1 | grep -iE 'not found|GLIBC' | head
  mv $W/stats/C_small__gpu__egl.jsonl $W/stats/C_small__gpu__egl-bundledfail.jsonl 2>/dev/null
  check C:small gpu egl
  egl_ok C_small__gpu__egl || { echo "== EGL FAILED in mode system too; GPU checks will fail"; TMO=20; CS_MODE=bundled; }
fi
echo "CS_MODE=$CS_MODE"
check C:small gpu auto

echo "== checks (elapsed $(elapsed)s)"
for s in C:default contact-layers:default; do
  for m in aabb gpu hybrid adaptive; do check $s $m egl; done
  check $s gpu egl --gpu-cull flags
done

echo "== record + replay through EGL (elapsed $(elapsed)s)"
timeout -k 5 $TMO "$B/cs.sh" record --scene C --method gpu --gl egl --frames 40:46 --depth every:1 -o $W/C.h5 2>&1
timeout -k 5 $TMO "$B/cs.sh" replay $W/C.h5 --gl egl -o $W/replay --threads 4 2>&1
cp $W/replay/frame_0041.png "$OUT/" 2>/dev/null && echo "copied frame_0041.png"

for s in E1:default cloth-slide:default; do
  for m in aabb gpu hybrid adaptive; do check $s $m egl; done
done

echo "== bench small C,D (elapsed $(elapsed)s)"
if [ "$(elapsed)" -lt "$DEADLINE" ]; then
  timeout -k 5 80 "$B/cs.sh" bench --scenes C,D --preset small -o $W/bench --gl egl 2>&1
  echo "bench rc=$?"
fi
BPRESET=default; [ -n "${QUICK:-}" ] && BPRESET=small
echo "== bench $BPRESET C,contact-layers (elapsed $(elapsed)s)"
if [ "$(elapsed)" -lt $((DEADLINE - 60)) ]; then
  timeout -k 5 60 "$B/cs.sh" bench --scenes C,contact-layers --preset $BPRESET -o $W/bench_default --gl egl 2>&1
  echo "bench default rc=$?"
fi

echo "== summary (elapsed $(elapsed)s)"
python3 $B/summarize.py $W 2>&1 || echo "summarize failed"
tar -C $W -czf "$OUT/results.tgz" stats pairs_md5.txt bench bench_default 2>/dev/null; ls -l "$OUT"
echo "done in $(elapsed)s"; sleep 0.5
