#!/usr/bin/env bash
# Side-by-side speed of two builds of the benchmark harness: runs OLD and NEW alternately
# (so that both see the same machine load), REPS times each, and prints per benchmark the
# fastest and the mean time of each side and the speed-up NEW over OLD.
#
#   bench/compare_builds.sh OLD/bench/swarmdesign_bench build/bench/swarmdesign_bench [REPS] [FILTER]
set -euo pipefail
if [[ $# -lt 2 || $1 == -h || $1 == --help ]]; then
  sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'
  exit $(( $# < 2 ? 2 : 0 ))
fi
old=$1 new=$2 reps=${3:-3} filter=${4:-.}
for bin in "$old" "$new"; do
  [[ -x $bin ]] || { echo "compare_builds: not an executable: $bin" >&2; exit 2; }
done
rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
for ((r = 1; r <= reps; ++r)); do
  for side in old new; do
    bin=$old; [[ $side == new ]] && bin=$new
    echo "run $r/$reps: $side" >&2
    "$bin" --benchmark_filter="$filter" --benchmark_format=csv --benchmark_min_time=1.5 2>/dev/null |
      awk -F, -v side="$side" '/^"BM_/ { gsub(/"/, "", $1); sub(/\/(min_time|iterations):.*/, "", $1); print side, $1, $4 }' >> "$rows"
  done
done
awk '{ key = $2; t = $3 + 0; n[$1, key]++; sum[$1, key] += t
       if (!(($1, key) in lo) || t < lo[$1, key]) lo[$1, key] = t; names[key] = 1 }
     END { printf "%-32s %10s %10s %10s %10s %9s %9s\n", "benchmark (ms)", "old min", "old mean", "new min", "new mean", "x (min)", "x (mean)"
           for (k in names) printf "%-32s %10.2f %10.2f %10.2f %10.2f %8.2fx %8.2fx\n", k, lo["old", k], sum["old", k] / n["old", k],
             lo["new", k], sum["new", k] / n["new", k], lo["old", k] / lo["new", k], (sum["old", k] / n["old", k]) / (sum["new", k] / n["new", k]) }' "$rows"
