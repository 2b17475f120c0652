#!/bin/sh
# Long libFuzzer runs (issue #34): each target for 10^6 executions (the HTTP target 10^5), one
# target at a time, from the repository's seed corpus. New inputs go to a scratch folder, never
# to fuzz/corpus; a finding (crash-*, leak-*, timeout-*) is written there too and named below.
#   bench/fuzz_long.sh [BUILD_DIR] [TARGET...]    (BUILD_DIR configured with -DSWARMDESIGN_FUZZ=ON)
# Environment: RUNS / HTTP_RUNS override the counts, SCRATCH the folder (default /tmp/sd-fuzz-long).
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build-fuzz}
[ $# -gt 0 ] && shift
targets=${*:-"config_string round_trip mission protocol weights drawing http"}
scratch=${SCRATCH:-/tmp/sd-fuzz-long}
status=0

dict_of() {
  case $1 in
    config_string|round_trip) echo config ;;
    *) echo "$1" ;;
  esac
}

printf '%-14s %10s %9s %9s  %s\n' target executions seconds exec/s result
for t in $targets; do
  bin=$build/fuzz/fuzz_$t
  [ -x "$bin" ] || { echo "no $bin: build it first (cmake --build $build --target fuzz_$t)" >&2; exit 2; }
  runs=${RUNS:-1000000}
  [ "$t" = http ] && runs=${HTTP_RUNS:-100000}
  out=$scratch/$t
  mkdir -p "$out/corpus"
  start=$(date +%s)
  "$bin" -runs="$runs" -timeout=60 -max_len=8192 -print_final_stats=1 -dict="$here/fuzz/dict/$(dict_of "$t").dict" \
    -artifact_prefix="$out/" "$out/corpus" "$here/fuzz/corpus/$t" >"$out/log" 2>&1
  rc=$?
  seconds=$(( $(date +%s) - start ))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/log" | tail -1)
  rate=$(awk -v e="${execs:-0}" -v s="$seconds" 'BEGIN { printf "%d", (s > 0 ? e / s : e) }')
  if [ $rc -eq 0 ]; then result=ok; else result="FINDING: $(ls "$out"/crash-* "$out"/leak-* "$out"/timeout-* "$out"/oom-* 2>/dev/null | head -1) (log $out/log)"; status=1; fi
  printf '%-14s %10s %9s %9s  %s\n' "$t" "${execs:-?}" "$seconds" "$rate" "$result"
done
exit $status
