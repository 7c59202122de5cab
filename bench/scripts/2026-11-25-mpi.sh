#!/usr/bin/env bash
# Frame-parallel runs (docs/how-to/mpi.md): 1 rank x 2 threads against 2 ranks x 1 thread (and 1 x 1)
# for `check` and `record`; a block's cold start; `join` against copying the file once.
# Then (section "virtual"): `join --virtual` against copying the parts once and the copying
# join, and `record` serial against `mpirun -np 2` with the (default) virtual join.
# Usage: bench/scripts/2026-11-25-mpi.sh BUILD_DIR WORK_DIR [RECORD_SCENE] [JOIN_SCENE] [SECTIONS]
# SECTIONS: all (default), or virtual (only the virtual join's sections, which record
# RECORD_SCENE whole twice: E4:large writes about 11 GiB per recording; the big files are
# removed at the end). Writes timings on stdout (and the load average before each section).
# Open MPI as root needs OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM)=1.
set -euo pipefail
bin=$(realpath "$1")/app/collidescope
work=$2
record_scene=${3:-E4}
join_scene=${4:-E4:large}
sections=${5:-all}
mkdir -p "$work"
cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

seconds() {  # seconds COMMAND...: wall time of one run, on stdout; the command's output to run.log
  local start end
  start=$(date +%s.%N)
  "$@" > run.log 2>&1 || [ $? -eq 1 ]
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l | xargs printf '%.2f'
}

if [ "$sections" = all ]; then
echo "== check --scene C --method aabb (pairs to a file)"
c1=$(seconds "$bin" check --scene C --method aabb --threads 1 -q --pairs c11.tsv)
c2=$(seconds "$bin" check --scene C --method aabb --threads 2 -q --pairs c12.tsv)
c3=$(seconds mpirun --oversubscribe -np 2 "$bin" check --scene C --method aabb --threads 1 -q --pairs c21.tsv)
cmp c11.tsv c21.tsv && cmp c11.tsv c12.tsv && echo "pairs identical"
echo "1 rank x 1 thread: $c1 s; 1 rank x 2 threads: $c2 s; 2 ranks x 1 thread: $c3 s"

echo "== record --scene $record_scene --method aabb"
r1=$(seconds "$bin" record --scene "$record_scene" --method aabb --threads 1 -q -o r11.h5)
r2=$(seconds "$bin" record --scene "$record_scene" --method aabb --threads 2 -q -o r12.h5)
r3=$(seconds mpirun --oversubscribe -np 2 "$bin" record --scene "$record_scene" --method aabb --threads 1 -q -o r21.h5)
"$bin" compare r11.h5 r21.h5 > /dev/null && echo "pairs identical (compare exit 0)"
echo "1 rank x 1 thread: $r1 s; 1 rank x 2 threads: $r2 s; 2 ranks x 1 thread: $r3 s; $(du -h r11.h5 | cut -f1)"

echo "== cold start: check --scene $record_scene --method aabb --threads 1, blocks of L frames from frame 100"
for length in 1 2 4 8 16 32 64; do
  t=$(seconds "$bin" check --scene "$record_scene" --method aabb --threads 1 -q --frames "100:$((100 + length))" --stats s.jsonl)
  first=$(head -1 s.jsonl | /usr/bin/python3 -c 'import json,sys; print(json.loads(sys.stdin.read())["ms"]["total"])')
  rest=$(tail -n +2 s.jsonl | /usr/bin/python3 -c 'import json,sys; v=[json.loads(l)["ms"]["total"] for l in sys.stdin]; print(sum(v)/len(v) if v else float("nan"))')
  echo "L=$length: wall $t s (process start and scene load included), first frame $first ms, later frames $rest ms each"
done

echo "== join against a copy: record --scene $join_scene --frames :40 in 2 parts"
"$bin" record --scene "$join_scene" --method aabb --frames :20 -q -o j0.h5
"$bin" record --scene "$join_scene" --method aabb --frames 20:40 -q -o j1.h5
cat j0.h5 j1.h5 > /dev/null  # both in the page cache, as for the copy
echo "parts: $(du -ch j0.h5 j1.h5 | tail -1 | cut -f1)"
cp_s=$(seconds sh -c 'cp j0.h5 c0.h5 && cp j1.h5 c1.h5 && sync')
join_s=$(seconds sh -c "'$bin' join j0.h5 j1.h5 -o joined.h5 && sync")
echo "copy both parts: $cp_s s; join: $join_s s; $(tail -1 run.log)"
rm -f c0.h5 c1.h5
fi

echo "== $(date -u '+%F %T') UTC, load average: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== join --virtual against a copy and the copying join: record --scene $join_scene --frames :40 in 2 parts"
"$bin" record --scene "$join_scene" --method aabb --threads 1 --frames :20 -q -o j0.h5
"$bin" record --scene "$join_scene" --method aabb --threads 1 --frames 20:40 -q -o j1.h5
"$bin" record --scene "$join_scene" --method aabb --threads 1 --frames :40 -q -o j40.h5
cat j0.h5 j1.h5 > /dev/null  # both in the page cache, as for the copy
echo "parts: $(du -ch j0.h5 j1.h5 | tail -1 | cut -f1); load $(cut -d' ' -f1-3 /proc/loadavg)"
cp_s=$(seconds sh -c 'cp j0.h5 c0.h5 && cp j1.h5 c1.h5 && sync')
rm -f c0.h5 c1.h5
copy_join_s=$(seconds sh -c "'$bin' join j0.h5 j1.h5 -o joined.h5 && sync")
copy_line=$(tail -1 run.log)
virtual_s=$(seconds sh -c "'$bin' join --virtual j0.h5 j1.h5 -o virtual.h5 && sync")
virtual_line=$(tail -1 run.log)
echo "copy both parts: $cp_s s; join (copying): $copy_join_s s ($copy_line); join --virtual: $virtual_s s ($virtual_line)"
echo "sizes: joined $(du -h joined.h5 | cut -f1), virtual $(du -h virtual.h5 | cut -f1)"
"$bin" compare j40.h5 virtual.h5 > /dev/null && echo "virtual join against record --frames :40: compare exit 0"
"$bin" compare joined.h5 virtual.h5 > /dev/null && echo "virtual against copying join: compare exit 0"
/usr/bin/python3 -c '
import sys, h5py, numpy as np
a, b = h5py.File("j40.h5", "r"), h5py.File("virtual.h5", "r")
names = []
a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) and ("positions" in n or "triangles" in n or n.endswith("pairs")) else None)
for n in names:
    if not np.array_equal(a[n][()], b[n][()]): sys.exit("h5py: " + n + " differs")
print("h5py: " + ", ".join(names) + " equal element for element")'
rm -f j0.h5 j1.h5 j40.h5 joined.h5 virtual.h5

echo "== $(date -u '+%F %T') UTC, load average: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== record --scene $record_scene --method aabb --threads 1: serial against mpirun -np 2 (virtual join)"
s11=$(seconds "$bin" record --scene "$record_scene" --method aabb --threads 1 -q -o s11.h5)
echo "serial: $s11 s, $(du -h s11.h5 | cut -f1); load $(cut -d' ' -f1-3 /proc/loadavg)"
v21=$(seconds mpirun --oversubscribe -np 2 "$bin" record --scene "$record_scene" --method aabb --threads 1 -q -o v21.h5)
echo "2 ranks x 1 thread, virtual join: $v21 s ($(grep 'joined the' run.log)); v21.h5 $(du -h v21.h5 | cut -f1), parts $(du -sh v21.h5.parts | cut -f1); load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "speed-up: $(echo "$s11 / $v21" | bc -l | xargs printf '%.2f')x"
"$bin" compare s11.h5 v21.h5 > /dev/null && echo "pairs identical (compare exit 0)"
rm -rf s11.h5 v21.h5 v21.h5.parts

echo "== $(date -u '+%F %T') UTC, load average: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== the same per core: serial under taskset -c 0, ranks bound one core each"
/usr/bin/time -f "serial, taskset -c 0: wall %e s, user %U, sys %S, cpu %P" \
  taskset -c 0 "$bin" record --scene "$record_scene" --method aabb --threads 1 -q -o s1.h5
/usr/bin/time -f "2 ranks, --bind-to core: wall %e s, user %U, sys %S, cpu %P" \
  mpirun --oversubscribe --bind-to core --map-by core -np 2 "$bin" record --scene "$record_scene" --method aabb --threads 1 -q -o p2.h5
"$bin" compare s1.h5 p2.h5 > /dev/null && echo "pairs identical (compare exit 0)"
rm -rf s1.h5 p2.h5 p2.h5.parts
