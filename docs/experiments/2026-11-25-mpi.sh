#!/usr/bin/env bash
# Frame-parallel runs (docs/mpi.md): 1 rank x 2 threads against 2 ranks x 1 thread (and 1 x 1)
# for `check` and `record`; a block's cold start; `join` against copying the file once.
# Usage: docs/experiments/2026-11-25-mpi.sh BUILD_DIR WORK_DIR [RECORD_SCENE] [JOIN_SCENE]
# Writes timings on stdout. Open MPI as root needs OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM)=1.
set -euo pipefail
bin=$(realpath "$1")/app/collidescope
work=$2
record_scene=${3:-E4}
join_scene=${4:-E4:large}
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
