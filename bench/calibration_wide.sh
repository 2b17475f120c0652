#!/usr/bin/env bash
# Calibration against ARGoS with SwarmDesign's own seed noise taken out: every controller of the
# calibration set (tests/data/argos-reference*.csv, ARGoS seeds 1-20) is run here on many more
# seeds (default 1-200), so that a difference the 20-against-20-seeds test cannot tell from seed
# luck shows, and one it flags by luck does not. Prints, per controller, both means, the ratio,
# the difference in ARGoS standard deviations and Welch's z; per group (mission and
# architecture), the median ratio, Spearman's rho, the controllers above and below ARGoS, and
# Stouffer's combined z (the sum of the controllers' z over the square root of their number),
# which tests the whole group for a bias in one direction. Run with --help for the options.
set -euo pipefail

PROG=calibration_wide
SCRIPT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO_DIR="$(cd "$SCRIPT_DIR/.." && pwd)"
# shellcheck source=SCRIPTDIR/lib/cli.sh
source "$SCRIPT_DIR/lib/cli.sh" # die, usage_error, need_value, positive, non_negative, resolve_binary

usage() {
  cat <<EOF
Usage: bench/calibration_wide.sh [options]

Runs every controller of the ARGoS calibration set on seeds 1..N (ARGoS' side has seeds 1-20)
and compares the distributions, per controller and per group.

Options:
  --seeds N        seeds per controller on SwarmDesign's side, 1..N (default 200)
  --group G        only this group (repeatable): aac, foraging, sca, lcn, aggregation180,
                   aac_bt, foraging_bt, tutti_aggregation, tutti_stop, tutti_foraging
  --threads T      evaluate --threads (default: nproc = $(nproc))
  --binary PATH    swarmdesign executable (default: \$SWARMDESIGN, else the build folder's)
  --json FILE      also write every figure as one JSON document
  -h, --help       show this help

Needs: bash, python3 (standard library). About 4 minutes for 200 seeds on 2 cores.

Columns: argos and ours are means (ours over seeds 1..N), ratio = ours / argos, dev = the
difference in ARGoS standard deviations, z = the difference over its standard error (Welch).
A group's Stouffer z beyond +-2.58 (p < 1 %) says its controllers lean one way as a whole.
EOF
}

seeds=200
threads="$(nproc)"
binary=""
json=""
groups=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) need_value "$@"; positive --seeds "$2"; seeds=$2; shift 2 ;;
    --seeds=*) positive --seeds "${1#*=}"; seeds=${1#*=}; shift ;;
    --group) need_value "$@"; groups+=("$2"); shift 2 ;;
    --group=*) groups+=("${1#*=}"); shift ;;
    --threads) need_value "$@"; non_negative --threads "$2"; threads=$2; shift 2 ;;
    --threads=*) non_negative --threads "${1#*=}"; threads=${1#*=}; shift ;;
    --binary) need_value "$@"; binary=$2; shift 2 ;;
    --binary=*) binary=${1#*=}; shift ;;
    --json) need_value "$@"; json=$2; shift 2 ;;
    --json=*) json=${1#*=}; shift ;;
    -h | --help) usage; exit 0 ;;
    *) usage_error "unknown option '$1'" ;;
  esac
done
command -v python3 >/dev/null 2>&1 || die "python3 not found"
binary="$(resolve_binary "$binary")" || exit
[[ -z "$json" || -d "$(dirname "$json")" ]] || usage_error "--json: folder $(dirname "$json") does not exist"

exec python3 "$SCRIPT_DIR/calibration_wide.py" --binary "$binary" --data "$REPO_DIR/tests/data" \
  --missions "$REPO_DIR/missions" --seeds "$seeds" --threads "$threads" --json "$json" -- "${groups[@]}"
