#!/usr/bin/env bash
# The thesis' three experiments at a reduced scale, timed, then their reports: the benchmark of
# issue #17. Prints the --dry-run estimate of the full protocol next to the wall time of each
# experiment. Re-running with the same --out resumes whatever was interrupted.
#
#   bench/experiments.sh [options]    (relative paths are taken from the repository root)
#     --scale S       budget scale of every design (default 0.05)
#     --designs N     designs per condition (default 3)
#     --threads T     simulations in parallel; 0 = all cores (default 0)
#     --out DIR       results folder (default: bench/results/experiments-<date>-<time>)
#     --binary PATH   swarmdesign executable (default: $SWARMDESIGN, else the build folder's)
#     -h, --help      show this help
set -euo pipefail

PROG=experiments
SCRIPT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO_DIR="$(cd "$SCRIPT_DIR/.." && pwd)"
# shellcheck source=SCRIPTDIR/lib/cli.sh
source "$SCRIPT_DIR/lib/cli.sh" # die, usage_error, need_value, positive, non_negative, resolve_binary

# The help is the comment block at the top of this file, without its "# ".
usage() { awk 'NR > 1 { if (!/^#/) exit; sub(/^# ?/, ""); print }' "$SCRIPT_DIR/experiments.sh"; }

scale=0.05 designs=3 threads=0 out="" binary=""
while (($#)); do
  case "$1" in
    -h | --help) usage; exit 0 ;;
    --scale) need_value "$@"; scale="$2"; shift 2 ;;
    --designs) need_value "$@"; designs="$2"; shift 2 ;;
    --threads) need_value "$@"; threads="$2"; shift 2 ;;
    --out) need_value "$@"; out="$2"; shift 2 ;;
    --binary) need_value "$@"; binary="$2"; shift 2 ;;
    --scale=* | --designs=* | --threads=* | --out=* | --binary=*)
      set -- "${1%%=*}" "${1#*=}" "${@:2}" ;;
    *) usage_error "unknown argument '$1'" ;;
  esac
done
positive_number --scale "$scale"
positive --designs "$designs"
non_negative --threads "$threads"
binary="$(resolve_binary "$binary")" || exit

# --out and --binary are read from where the script was called; the default goes in the repository.
out="${out:-$REPO_DIR/bench/results/experiments-$(date +%Y%m%d-%H%M%S)}"
mkdir -p "$out" || die "cannot create the results folder $out"
out="$(cd "$out" && pwd)"
cd "$REPO_DIR"
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
  "$binary" experiment "$experiment" --dry-run --threads "$threads" | tail -n 1 ||
    die "the dry run of $experiment failed"
  echo "== $experiment at budget scale $scale, $designs designs per condition"
  start=$(date +%s)
  "$binary" experiment "$experiment" --budget-scale "$scale" --designs "$designs" --threads "$threads" \
    >"$out/$experiment.log" 2>&1 ||
    die "$experiment failed (exit $?): $(tail -n 1 "$out/$experiment.log") (log: $out/$experiment.log); run again with the same --out to resume"
  echo "   wall time $(( $(date +%s) - start )) s (log: $out/$experiment.log)"
  "$binary" report "$experiment" --out "$out/$experiment-report" | tee "$out/$experiment-report.txt" ||
    die "the report of $experiment failed"
done
