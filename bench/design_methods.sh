#!/usr/bin/env bash
# The design methods against each other (issue #57): for each seed, a design by every method at
# --budget, and Iterated F-Race's at --goal-budget (the quality a method should reach in less),
# then one `assess` of all on fresh seeds, in the design model and in a pseudo-reality.
#
#   bench/design_methods.sh [--mission aac] [--budget 20000] [--goal-budget 100000] [--seeds 3]
#                           [--methods automode,random-search,local-search] [--eval-seeds 1001-1020]
#                           [--spec sampled-around] [--samples 1-10] [--threads 0] [--out DIR]
# Prints one line per method and budget (median, min and max over the seeds of each design's
# mean on the fresh seeds, and its median wall time); DIR keeps the designs (run again with the
# same --out to reuse them) and assessment.json.
set -euo pipefail
PROG=design_methods
SCRIPT_DIR=$(cd "$(dirname "$0")" && pwd)
REPO_DIR=$(cd "$SCRIPT_DIR/.." && pwd)
source "$SCRIPT_DIR/lib/cli.sh"
mission=aac budget=20000 goal=100000 seeds=3 methods=automode,random-search,local-search
eval_seeds=1001-1020 spec=sampled-around samples=1-10 threads=0 out=design-methods
while [[ $# -gt 0 ]]; do
  case $1 in
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --mission) need_value "$@"; mission=$2; shift 2 ;;
    --budget) need_value "$@"; positive "$1" "$2"; budget=$2; shift 2 ;;
    --goal-budget) need_value "$@"; non_negative "$1" "$2"; goal=$2; shift 2 ;;
    --seeds) need_value "$@"; positive "$1" "$2"; seeds=$2; shift 2 ;;
    --methods) need_value "$@"; methods=$2; shift 2 ;;
    --eval-seeds) need_value "$@"; eval_seeds=$2; shift 2 ;;
    --spec) need_value "$@"; spec=$2; shift 2 ;;
    --samples) need_value "$@"; samples=$2; shift 2 ;;
    --threads) need_value "$@"; non_negative "$1" "$2"; threads=$2; shift 2 ;;
    --out) need_value "$@"; out=$2; shift 2 ;;
    *) usage_error "unknown option '$1'" ;;
  esac
done
bin=$(resolve_binary "") || exit
mkdir -p "$out"
runs=()  # "method budget"
IFS=, read -r -a names <<< "$methods"
for m in "${names[@]}"; do runs+=("$m $budget"); done
[[ $goal -gt 0 ]] && runs+=("automode $goal")
designs=()
for run in "${runs[@]}"; do
  read -r method b <<< "$run"
  for ((s = 1; s <= seeds; ++s)); do
    dir=$out/$method-$b-$s
    if [[ ! -f $dir.json ]]; then
      echo "$PROG: designing $dir" >&2
      "$bin" design --mission "$mission" --budget "$b" --fsm --chocolate --seed "$s" --method "$method" \
        --threads "$threads" --out "$dir" --json > "$dir.tmp" || die "the design $dir failed"
      mv "$dir.tmp" "$dir.json"
    fi
    designs+=(--design "$dir")
  done
done
"$bin" assess "${designs[@]}" --pseudo-reality "$spec" --samples "$samples" --seeds "$eval_seeds" --threads "$threads" \
  --json > "$out/assessment.json"
python3 - "$out" <<'EOF'
import json, os, statistics, sys
out = sys.argv[1]
doc = json.load(open(os.path.join(out, "assessment.json")))
groups = {}
for row in doc["software"]:
    name = os.path.basename(row["label"].removesuffix(" best").rstrip("/"))
    method, budget, _ = name.rsplit("-", 2)
    report = json.load(open(os.path.join(out, name + ".json")))
    groups.setdefault((method, int(budget)), []).append(
        (row["design_mean"], row["pseudo_reality_mean"], report["timing"]["wall_s"]))
print(f"{'method':<14} {'budget':>7} {'designs':>7} {'median':>9} {'min':>9} {'max':>9} {'in PR':>9} {'wall s':>7}")
for (method, budget), rows in sorted(groups.items(), key=lambda kv: (kv[0][1], kv[0][0])):
    model = [r[0] for r in rows]
    print(f"{method:<14} {budget:>7} {len(rows):>7} {statistics.median(model):>9.4g} {min(model):>9.4g} "
          f"{max(model):>9.4g} {statistics.median(r[1] for r in rows):>9.4g} {statistics.median(r[2] for r in rows):>7.0f}")
EOF
