#!/usr/bin/env bash
# The thesis' three experiments at a reduced scale, timed, then their reports: the benchmark of
# issue #17. Prints the --dry-run estimate of the full protocol next to the wall time of each
# experiment. Re-running with the same --out resumes whatever was interrupted.
#
#   bench/experiments.sh [--scale 0.05] [--designs 3] [--threads N] [--out DIR] [--binary PATH]
set -euo pipefail
cd "$(dirname "$0")/.."

scale=0.05 designs=3 threads=0 out="" binary="$PWD/build/swarmdesign"
while (($#)); do
  case "$1" in
    --scale) scale="$2"; shift 2 ;;
    --designs) designs="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --binary) binary="$2"; shift 2 ;;
    -h|--help) sed -n 2,6p "$0"; exit 0 ;;
    *) echo "experiments.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
out="${out:-bench/results/experiments-$(date +%Y%m%d-%H%M%S)}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
export SWARMDESIGN_HOME="$out/home"
password="bench-password-1"
if [ ! -f "$SWARMDESIGN_HOME/swarmdesign.db" ]; then
  printf '%s\n' "$password" | "$binary" sign-up bench --password-stdin >/dev/null
  printf '%s\n' "$password" | "$binary" sign-in bench --password-stdin >/dev/null
  "$binary" new-project thesis >/dev/null
  "$binary" select-project thesis >/dev/null
fi

for experiment in validation combination architecture; do
  echo "== $experiment: full protocol (dry run)"
  "$binary" experiment "$experiment" --dry-run --threads "$threads" | tail -n 1
  echo "== $experiment at budget scale $scale, $designs designs per condition"
  start=$(date +%s)
  "$binary" experiment "$experiment" --budget-scale "$scale" --designs "$designs" --threads "$threads" \
    >"$out/$experiment.log" 2>&1
  echo "   wall time $(( $(date +%s) - start )) s (log: $out/$experiment.log)"
  "$binary" report "$experiment" --out "$out/$experiment-report" | tee "$out/$experiment-report.txt"
done
