#!/usr/bin/env bash
# A compiler launcher that logs each compile's wall time: "MILLISECONDS OUTPUT" per line, appended
# to $COMPILE_TIMES (default: compile-times.txt in the working directory of the compile, so set
# it to an absolute path). The compile's exit status is kept. Usage (docs/how-to/toolchain.md):
#   cmake -S . -B build -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/scripts/time-compile.sh
#   COMPILE_TIMES=$PWD/times.txt cmake --build build -j2
#   sort -rn times.txt | head    # the slowest objects
started=$(date +%s%N)
"$@"
status=$?
output=""
previous=""
for argument in "$@"; do
  [ "$previous" = "-o" ] && output=$argument
  previous=$argument
done
echo "$((($(date +%s%N) - started) / 1000000)) $output" >> "${COMPILE_TIMES:-compile-times.txt}"
exit $status
