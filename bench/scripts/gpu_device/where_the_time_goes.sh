#!/bin/bash
# Where the GPU cull's time goes on the device: C:default frames 40:60, method gpu through EGL,
# varying the depth resolution, the read-back (queries/flags), threads and the object level.
B=$PWD/.devbundle  # built by bench/scripts/gpu_device/make_bundle.sh
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
OUT=${OUT:-/tmp/out}; mkdir -p $OUT
cs() { timeout 60 "$B/lib/ld-linux-x86-64.so.2" --library-path "$B/lib:/usr/local/nvidia/lib64" "$B/collidescope" "$@"; }
nvidia-smi -L
run() {
  label=$1; shift
  cs check --scene C:default --frames 40:60 --method gpu --gl egl --exit-zero -q --stats $OUT/s.jsonl "$@" 2>/dev/null
  python3 - "$label" $OUT/s.jsonl <<'PY'
import json, sys, statistics
rows = [json.loads(l) for l in open(sys.argv[2])]
med = lambda k: statistics.median(r["ms"][k] for r in rows)
g = rows[-1].get("gpu", {})
print("%-28s total %7.2f  render %7.2f  readback %6.2f  queries %s  pcs_tri_out %s" % (sys.argv[1], med("total"), med("gpu_render"), med("gpu_readback"), g.get("queries"), g.get("pcs_triangles_out")))
PY
}
run "default (256, queries, 16t)"
run "resolution 64" --gpu-resolution 64
run "resolution 1024" --gpu-resolution 1024
run "flags" --gpu-cull flags
run "threads 1" --threads 1
run "no object level" --gpu-no-object-level
run "P=256 fixed" --triangles-per-query 256 --gpu-fixed-p
run "one view (z) fixed" --gpu-views z --gpu-fixed-views
