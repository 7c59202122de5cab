#!/bin/bash
# usage: batch.sh FROM TO  (soak run dirs must exist)
for s in $(seq $1 $2); do
  d=/tmp/w/soak/run/$s
  [ -d $d ] || continue
  objs=$(ls $d/o*.0000.obj | sed 's/\.0000\.obj$/.####.obj/')
  for self in "" "--self"; do
    out=$(timeout 300 /tmp/w/ccdsoak/ccdsoak $objs $self 2>&1); rc=$?
    last=$(echo "$out" | tail -1)
    echo "seed $s $self rc $rc: $last"
    if [ $rc -ne 0 ]; then echo "$out" | grep -v "^contacts" | head -5; fi
  done
done
