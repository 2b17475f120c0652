#!/usr/bin/env bash
# Robust designs against plain ones of equal budget, assessed on pseudo-realities neither saw.
# For each seed: a plain design (design model only) and a robust one (--pseudo-realities SPEC,
# samples 101-120), then one `assess` of all of them on held-out samples and fresh seeds.
#
#   bench/robust_vs_plain.sh [--mission aac] [--budget 10000] [--seeds 2] [--spec sampled-around]
#                            [--samples 1-30] [--eval-seeds 1-10] [--threads 0] [--out DIR]
# Prints assess's table; DIR keeps the designs (re-run with the same --out to reuse them) and
# assessment.json.
set -euo pipefail
PROG=robust_vs_plain
SCRIPT_DIR=$(cd "$(dirname "$0")" && pwd)
REPO_DIR=$(cd "$SCRIPT_DIR/.." && pwd)
source "$SCRIPT_DIR/lib/cli.sh"
mission=aac budget=10000 seeds=2 spec=sampled-around samples=1-30 eval_seeds=1-10 threads=0 out=robust-vs-plain
while [[ $# -gt 0 ]]; do
  case $1 in
    -h|--help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --mission) need_value "$@"; mission=$2; shift 2 ;;
    --budget) need_value "$@"; positive "$1" "$2"; budget=$2; shift 2 ;;
    --seeds) need_value "$@"; positive "$1" "$2"; seeds=$2; shift 2 ;;
    --spec) need_value "$@"; spec=$2; shift 2 ;;
    --samples) need_value "$@"; samples=$2; shift 2 ;;
    --eval-seeds) need_value "$@"; eval_seeds=$2; shift 2 ;;
    --threads) need_value "$@"; non_negative "$1" "$2"; threads=$2; shift 2 ;;
    --out) need_value "$@"; out=$2; shift 2 ;;
    *) usage_error "unknown option '$1'" ;;
  esac
done
bin=$(resolve_binary "") || exit
mkdir -p "$out"
designs=()
for ((s = 1; s <= seeds; ++s)); do
  for kind in plain robust; do
    dir=$out/$kind-$s
    extra=()
    [[ $kind == robust ]] && extra=(--pseudo-realities "$spec")
    if [[ ! -f $dir/design.db ]]; then
      echo "$PROG: designing $dir" >&2
      "$bin" design --mission "$mission" --budget "$budget" --fsm --chocolate --seed "$s" --threads "$threads" \
        "${extra[@]}" --out "$dir" --json > "$dir.json" || die "the design $dir failed"
    fi
    designs+=(--design "$dir")
  done
done
"$bin" assess "${designs[@]}" --pseudo-reality "$spec" --samples "$samples" --seeds "$eval_seeds" --threads "$threads"
"$bin" assess "${designs[@]}" --pseudo-reality "$spec" --samples "$samples" --seeds "$eval_seeds" --threads "$threads" \
  --json > "$out/assessment.json"
