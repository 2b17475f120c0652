#!/usr/bin/env bash
# Quality benchmark: SwarmDesign's native Iterated F-Race against the real irace 3.5 driving
# SwarmDesign's evaluator through `swarmdesign irace-export`, at the same budget.
#
# For each design seed s = 1..N:
#   native: swarmdesign design --mission M --budget B --fsm --chocolate --seed s --threads T --json
#   irace:  swarmdesign irace-export (same mission, FSM, Chocolate, budget B, seed s), then
#           irace --scenario scenario.txt --parallel T in that folder
# Each side's best control software is re-evaluated on fresh seeds (default 100001-100020, never
# used by either design) and the mean score is recorded. The summary compares the medians over the
# N designs in the mission's direction (AAC is maximised). Run with --help for the options.
set -euo pipefail

PROG=native_vs_irace
SCRIPT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO_DIR="$(cd "$SCRIPT_DIR/.." && pwd)"
# shellcheck source=SCRIPTDIR/lib/cli.sh
source "$SCRIPT_DIR/lib/cli.sh" # die, usage_error, need_value, positive, resolve_binary

usage() {
  cat <<EOF
Usage: bench/native_vs_irace.sh [options]

Quality of native racing vs irace 3.5 on the same design problem and budget: for each design
seed s = 1..N, one native design (swarmdesign design) and one irace run driving swarmdesign
through the files of 'swarmdesign irace-export'; each best control software is re-evaluated
on fresh seeds, and the medians over the N designs are compared.

Options:
  --designs N       number of designs per side, seeds 1..N (default 5)
  --budget B        design budget in simulation runs, both sides (default 20000)
  --threads T       simulations in parallel: design --threads, irace --parallel,
                    evaluate --threads (default: nproc = $(nproc))
  --out DIR         results folder (default: bench/results/native-vs-irace-<date>-<time>);
                    an existing folder of a killed run with the same settings is continued:
                    finished stages are reused, a killed native design is resumed
  --binary PATH     swarmdesign executable (default: \$SWARMDESIGN, else the build folder's)
  --mission M       mission (default aac)
  --eval-seeds A-B  fresh seeds of the re-evaluation (default 100001-100020)
  --irace PATH      irace command-line executable (default: irace on PATH, else the one
                    shipped in R's irace package, Debian r-cran-irace)
  -h, --help        show this help

Needs: bash, jq, Rscript with the irace 3.5 package (Debian: jq r-cran-irace).
irace and native racing both refuse budgets below the minimum of iterated racing for the
design space (1008 for FSM + Chocolate); the script checks this before starting.

Writes to DIR: native/seed-S/ (design folder, design.json, eval.json), irace/seed-S/ (exported
files, irace.log, irace.Rdata, best.txt, eval.json), results.csv, results.json, summary.txt.

Example (the full benchmark, about an hour or more on 2 cores):
  bench/native_vs_irace.sh --designs 5 --budget 20000
EOF
}

# ---------------------------------------------------------------------------------------------
# Options
designs=5
budget=20000
threads="$(nproc)"
out=""
binary="" # --binary; resolve_binary falls back to $SWARMDESIGN, then the build folder
mission=aac
eval_seeds=100001-100020
irace_bin=""

while [[ $# -gt 0 ]]; do
  case "$1" in
    -h | --help) usage; exit 0 ;;
    --designs) need_value "$@"; designs="$2"; shift 2 ;;
    --budget) need_value "$@"; budget="$2"; shift 2 ;;
    --threads) need_value "$@"; threads="$2"; shift 2 ;;
    --out) need_value "$@"; out="$2"; shift 2 ;;
    --binary) need_value "$@"; binary="$2"; shift 2 ;;
    --mission) need_value "$@"; mission="$2"; shift 2 ;;
    --eval-seeds) need_value "$@"; eval_seeds="$2"; shift 2 ;;
    --irace) need_value "$@"; irace_bin="$2"; shift 2 ;;
    --designs=* | --budget=* | --threads=* | --out=* | --binary=* | --mission=* | --eval-seeds=* | --irace=*)
      set -- "${1%%=*}" "${1#*=}" "${@:2}" ;;
    *) usage_error "unknown argument '$1'" ;;
  esac
done
positive --designs "$designs"
positive --budget "$budget"
positive --threads "$threads"
[[ "$eval_seeds" =~ ^[0-9]+-[0-9]+$ ]] || usage_error "--eval-seeds must be a range A-B, not '$eval_seeds'"
((${eval_seeds%-*} <= ${eval_seeds#*-})) || usage_error "--eval-seeds: A must not exceed B in '$eval_seeds'"
# Design seeds are 1..N: fresh seeds must not overlap them (irace's instance seeds are random).
((${eval_seeds%-*} > designs)) || usage_error "--eval-seeds must start above the design seeds 1..$designs"

# ---------------------------------------------------------------------------------------------
# Tools
command -v jq >/dev/null 2>&1 || die "jq not found (Debian: apt-get install jq)"
command -v Rscript >/dev/null 2>&1 || die "Rscript not found: irace 3.5 is missing (Debian: apt-get install r-cran-irace)"
Rscript -e 'suppressMessages(library(irace))' >/dev/null 2>&1 ||
  die "R package irace not found: irace 3.5 is missing (Debian: apt-get install r-cran-irace)"
irace_version="$(Rscript -e 'cat(as.character(packageVersion("irace")))' 2>/dev/null)"
[[ "$irace_version" == 3.5* ]] ||
  echo "$PROG: warning: irace $irace_version found; irace-export writes irace 3.5 files" >&2
if [[ -z "$irace_bin" ]]; then
  if command -v irace >/dev/null 2>&1; then
    irace_bin="$(command -v irace)"
  else
    irace_bin="$(Rscript -e 'cat(system.file("bin", "irace", package = "irace"))' 2>/dev/null || true)"
  fi
fi
[[ -n "$irace_bin" && -x "$irace_bin" ]] || die "irace executable not found (give --irace PATH, or apt-get install r-cran-irace)"

binary="$(resolve_binary "$binary")" || exit
export SWARMDESIGN="$binary" # target-runner uses it; irace-export also writes this path into it

direction="$("$binary" missions --json | jq -r --arg m "$mission" '.[] | select(.name == $m) | .direction')"
[[ "$direction" == maximize || "$direction" == minimize ]] || die "unknown mission '$mission' (see swarmdesign missions)"

# ---------------------------------------------------------------------------------------------
# Helpers
start_s=$(date +%s)
log() {
  local e=$(($(date +%s) - start_s))
  printf '[%02d:%02d:%02d] %s\n' $((e / 3600)) $((e % 3600 / 60)) $((e % 60)) "$*"
}
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
fmt() { printf '%.1f' "$1"; }
median() { # numbers as arguments
  printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
squeeze() { printf '%s' "$1" | tr -s ' \t' ' ' | sed 's/^ //; s/ $//'; }
# Last lines of a log, joined, for one-line errors.
tail_of() { tail -n "${2:-3}" "$1" 2>/dev/null | tr '\n' ' ' | sed 's/  */ /g'; }

# R: the minimum maxExperiments irace 3.5 accepts for an exported folder (irace's own formula).
# shellcheck disable=SC2016 # R code, not shell
R_MINIMUM_BUDGET='
suppressMessages(library(irace))
setwd(commandArgs(trailingOnly = TRUE)[1])
s <- irace::checkScenario(irace::readScenario("scenario.txt"))
p <- irace::readParameters(s$parameterFile, digits = s$digits)
it <- floor(if (s$nbIterations == 0) irace:::computeNbIterations(p$nbVariable) else s$nbIterations)
sv <- floor(if (s$minNbSurvival == 0) irace:::computeTerminationOfRace(p$nbVariable) else s$minNbSurvival)
cat(irace:::computeMinimumBudget(s, sv, it, NULL), p$nbVariable, "\n")
'
# R: irace best configuration (first elite of the last iteration) as a command line, with its
# training mean cost, its number of runs and the experiments irace used. One field per line.
# shellcheck disable=SC2016 # R code, not shell
R_IRACE_BEST='
suppressMessages(library(irace))
load(commandArgs(trailingOnly = TRUE)[1])
r <- iraceResults
elites <- r$allElites[[length(r$allElites)]]
best <- elites[1]
conf <- r$allConfigurations[r$allConfigurations$.ID. == best, , drop = FALSE]
line <- irace::buildCommandLine(conf[, r$parameters$names, drop = FALSE], r$parameters$switches)
costs <- r$experiments[, as.character(best)]
costs <- costs[!is.na(costs)]
cat(best, trimws(line), format(mean(costs), digits = 15), length(costs), r$state$experimentsUsedSoFar, sep = "\n")
'

# ---------------------------------------------------------------------------------------------
# Preflight: both optimisers refuse a budget below the minimum of iterated racing.
preflight="$(mktemp -d "${TMPDIR:-/tmp}/native-vs-irace-preflight.XXXXXX")"
trap 'rm -rf "$preflight" "$preflight.log"' EXIT
"$binary" irace-export --mission "$mission" --fsm --chocolate --budget "$budget" --seed 1 --out "$preflight/irace" \
  >"$preflight.log" 2>&1 || die "swarmdesign irace-export failed: $(tail_of "$preflight.log")"
read -r irace_min nb_params < <(Rscript -e "$R_MINIMUM_BUDGET" "$preflight/irace" 2>>"$preflight.log") ||
  die "irace cannot read the exported files: $(tail_of "$preflight.log")"
native_min=""
if ! "$binary" design --mission "$mission" --budget 1 --fsm --chocolate --seed 1 --threads 1 \
  --out "$preflight/native" >>"$preflight.log" 2>&1; then
  native_min="$(grep -o 'minimum of [0-9]*' "$preflight.log" | grep -o '[0-9]*$' | head -n 1 || true)"
fi
rm -rf "$preflight" "$preflight.log"
trap - EXIT
if [[ -n "$native_min" && "$native_min" != "$irace_min" ]]; then
  echo "$PROG: warning: native racing's minimum budget ($native_min) differs from irace's ($irace_min)" >&2
fi
minimum=$irace_min
if [[ -n "$native_min" ]] && ((native_min > minimum)); then minimum=$native_min; fi
if ((budget < minimum)); then
  die "budget $budget is below the minimum of $minimum simulation runs that irace 3.5 (and native racing) need for $mission with FSM + Chocolate ($nb_params free parameters): use --budget $minimum or more"
fi

# ---------------------------------------------------------------------------------------------
# Output folder; a folder of an earlier run is continued only with the same settings
if [[ -z "$out" ]]; then
  out="$SCRIPT_DIR/results/native-vs-irace-$(date +%Y%m%d-%H%M%S)"
  [[ ! -e "$out" ]] || out="$(mktemp -d "$out-XXXX")"
fi
mkdir -p "$out" || die "cannot create $out"
out="$(cd "$out" && pwd)"
settings="mission=$mission budget=$budget eval_seeds=$eval_seeds architecture=fsm flavour=chocolate irace=$irace_version"
if [[ -f "$out/settings.txt" ]]; then
  [[ "$(cat "$out/settings.txt")" == "$settings" ]] ||
    die "$out holds a run with other settings ($(cat "$out/settings.txt")): use another --out"
else
  echo "$settings" >"$out/settings.txt"
fi

log "native vs irace $irace_version on $mission ($direction), FSM + Chocolate ($nb_params free parameters): $designs designs, budget $budget (minimum $minimum), $threads threads"
log "binary $binary; irace $irace_bin; re-evaluation seeds $eval_seeds"
log "results in $out"

# ---------------------------------------------------------------------------------------------
# Stages. Each writes its result files last, so a killed run is continued where it stopped.
run_native() { # seed dir
  local s=$1 dir=$2 t0 t1
  if [[ -s "$dir/design.json" && -s "$dir/wall_s" ]] && jq -e '.best.configuration' "$dir/design.json" >/dev/null 2>&1; then
    log "seed $s/$designs native design: reused ($(cat "$dir/wall_s") s)"
    return
  fi
  mkdir -p "$dir"
  local args=(design --mission "$mission" --budget "$budget" --fsm --chocolate --seed "$s" --out "$dir/design")
  if [[ -e "$dir/design/design.db" ]]; then
    args=(design --resume "$dir/design")
    touch "$dir/resumed" # its wall time below misses the killed part
    log "seed $s/$designs native design: resuming the killed design in $dir/design"
  else
    rm -rf "$dir/design" "$dir/resumed"
    log "seed $s/$designs native design: started"
  fi
  t0=$(now)
  "$binary" "${args[@]}" --threads "$threads" --json >"$dir/design.json.tmp" 2>"$dir/design.log" ||
    die "seed $s: native design failed (exit $?): $(tail_of "$dir/design.log") (see $dir/design.log)"
  t1=$(now)
  jq -e '.best.configuration' "$dir/design.json.tmp" >/dev/null || die "seed $s: native design printed no best configuration ($dir/design.json.tmp)"
  mv "$dir/design.json.tmp" "$dir/design.json"
  # The design's own wall time excludes an earlier, killed part; record what this run measured.
  elapsed "$t0" "$t1" >"$dir/wall_s"
  log "seed $s/$designs native design: done in $(cat "$dir/wall_s") s, $(jq -r '.experiments_used' "$dir/design.json") runs, training mean $(fmt "$(jq -r '.best.mean_score' "$dir/design.json")") over $(jq -r '.best.evaluations' "$dir/design.json") runs"
}

run_irace() { # seed dir
  local s=$1 dir=$2 t0 t1
  if [[ -s "$dir/best.txt" && -s "$dir/wall_s" ]]; then
    log "seed $s/$designs irace: reused ($(cat "$dir/wall_s") s)"
    return
  fi
  rm -rf "$dir"
  "$binary" irace-export --mission "$mission" --fsm --chocolate --budget "$budget" --seed "$s" --out "$dir" \
    >"$dir.export.log" 2>&1 || die "seed $s: swarmdesign irace-export failed: $(tail_of "$dir.export.log")"
  mv "$dir.export.log" "$dir/export.log"
  log "seed $s/$designs irace: started (exported to $dir)"
  t0=$(now)
  if ! (cd "$dir" && "$irace_bin" --scenario scenario.txt --parallel "$threads" >irace.log 2>&1); then
    if grep -q 'Insufficient budget' "$dir/irace.log"; then
      die "seed $s: irace refuses budget $budget: $(grep -o "require a value of 'maxExperiments' of at least '[0-9]*'" "$dir/irace.log" | head -n 1)"
    fi
    die "seed $s: irace failed: $(grep -m 1 -A 2 'Error' "$dir/irace.log" | tr '\n' ' ' | cut -c 1-400) (see $dir/irace.log)"
  fi
  t1=$(now)
  [[ -s "$dir/irace.Rdata" ]] || die "seed $s: irace wrote no irace.Rdata (see $dir/irace.log)"
  local fields
  mapfile -t fields < <(Rscript -e "$R_IRACE_BEST" "$dir/irace.Rdata" 2>"$dir/best.err") ||
    die "seed $s: cannot read irace's best configuration: $(tail_of "$dir/best.err")"
  ((${#fields[@]} == 5)) || die "seed $s: cannot read irace's best configuration from $dir/irace.Rdata: $(tail_of "$dir/best.err")"
  local id=${fields[0]} config=${fields[1]} cost=${fields[2]} runs=${fields[3]} used=${fields[4]}
  [[ "$config" == --fsm-config* ]] || die "seed $s: irace's best is not FSM control software: '$config'"
  # Cross-check with the log's "# Best configurations as commandlines" (first one is the best).
  local logged
  logged="$(awk '/^# Best configurations as commandlines/ { getline; sub(/^[0-9]+ +/, ""); print; exit }' "$dir/irace.log")"
  if [[ "$(squeeze "$logged")" != "$(squeeze "$config")" ]]; then
    echo "$PROG: warning: seed $s: irace.Rdata's best ($id) differs from the log's first commandline" >&2
  fi
  local score=$cost
  [[ "$direction" == maximize ]] && score=$(awk -v c="$cost" 'BEGIN { printf "%.15g", -c }')
  jq -n --argjson id "$id" --arg config "$config" --argjson score "$score" --argjson runs "$runs" --argjson used "$used" \
    '{id: $id, configuration: $config, mean_score: $score, evaluations: $runs, experiments_used: $used}' >"$dir/best.json"
  elapsed "$t0" "$t1" >"$dir/wall_s"
  printf '%s\n' "$config" >"$dir/best.txt"
  log "seed $s/$designs irace: done in $(cat "$dir/wall_s") s, $used runs, best #$id training mean $(fmt "$score") over $runs runs"
}

run_eval() { # seed dir side config
  local s=$1 dir=$2 side=$3 config=$4 t0 t1
  if [[ -s "$dir/eval.json" ]] && jq -e '.mean' "$dir/eval.json" >/dev/null 2>&1; then
    log "seed $s/$designs $side re-evaluation: reused (mean $(fmt "$(jq -r '.mean' "$dir/eval.json")"))"
    return
  fi
  local -a cs
  read -r -a cs <<<"$config"
  t0=$(now)
  "$binary" evaluate --mission "$mission" --seeds "$eval_seeds" --threads "$threads" --json "${cs[@]}" \
    >"$dir/eval.json.tmp" 2>"$dir/eval.log" || die "seed $s: $side re-evaluation failed: $(tail_of "$dir/eval.log")"
  t1=$(now)
  mv "$dir/eval.json.tmp" "$dir/eval.json"
  log "seed $s/$designs $side re-evaluation on seeds $eval_seeds: mean $(fmt "$(jq -r '.mean' "$dir/eval.json")") ($(elapsed "$t0" "$t1") s)"
}

for ((s = 1; s <= designs; s++)); do
  ndir="$out/native/seed-$s"
  idir="$out/irace/seed-$s"
  mkdir -p "$ndir" "$out/irace"
  run_native "$s" "$ndir"
  run_eval "$s" "$ndir" native "$(jq -r '.best.configuration' "$ndir/design.json")"
  run_irace "$s" "$idir"
  run_eval "$s" "$idir" irace "$(cat "$idir/best.txt")"
done

# ---------------------------------------------------------------------------------------------
# Results
records="$out/records.jsonl"
: >"$records"
for ((s = 1; s <= designs; s++)); do
  ndir="$out/native/seed-$s"
  idir="$out/irace/seed-$s"
  resumed=false
  [[ -e "$ndir/resumed" ]] && resumed=true
  jq -n -c --argjson seed "$s" --argjson resumed "$resumed" \
    --slurpfile nj "$ndir/design.json" --slurpfile ne "$ndir/eval.json" --argjson nw "$(cat "$ndir/wall_s")" \
    --slurpfile ij "$idir/best.json" --slurpfile ie "$idir/eval.json" --argjson iw "$(cat "$idir/wall_s")" \
    '{design_seed: $seed,
      native: {mean: $ne[0].mean, median: $ne[0].median, wall_s: $nw, resumed: $resumed, training_mean: $nj[0].best.mean_score,
               training_runs: $nj[0].best.evaluations, experiments_used: $nj[0].experiments_used,
               configuration: $nj[0].best.configuration},
      irace: {mean: $ie[0].mean, median: $ie[0].median, wall_s: $iw, training_mean: $ij[0].mean_score,
              training_runs: $ij[0].evaluations, experiments_used: $ij[0].experiments_used,
              configuration: $ij[0].configuration}}' >>"$records"
done

mapfile -t native_means < <(jq -r '.native.mean' "$records")
mapfile -t irace_means < <(jq -r '.irace.mean' "$records")
native_median=$(median "${native_means[@]}")
irace_median=$(median "${irace_means[@]}")
ratio=$(awk -v n="$native_median" -v i="$irace_median" 'BEGIN { if (i == 0) print "nan"; else printf "%.4f", n / i }')
if [[ "$direction" == maximize ]]; then
  ok=$(awk -v n="$native_median" -v i="$irace_median" 'BEGIN { print (n >= i) ? "true" : "false" }')
  better="higher is better"
else
  ok=$(awk -v n="$native_median" -v i="$irace_median" 'BEGIN { print (n <= i) ? "true" : "false" }')
  better="lower is better"
fi

jq -s --arg mission "$mission" --arg direction "$direction" --argjson budget "$budget" --argjson designs "$designs" \
  --argjson threads "$threads" --arg eval_seeds "$eval_seeds" --arg irace_version "$irace_version" \
  --argjson nm "$native_median" --argjson im "$irace_median" --arg ratio "$ratio" --argjson ok "$ok" \
  '{mission: $mission, direction: $direction, architecture: "fsm", flavour: "chocolate", budget: $budget,
    designs: $designs, threads: $threads, eval_seeds: $eval_seeds, irace_version: $irace_version,
    summary: {native_median_of_means: $nm, irace_median_of_means: $im,
              ratio_native_over_irace: ($ratio | tonumber? // null), native_at_least_as_good: $ok},
    runs: .}' "$records" >"$out/results.json"

{
  echo "design_seed,native_mean,irace_mean,native_median,irace_median,native_wall_s,irace_wall_s,native_training_mean,irace_training_mean,native_experiments,irace_experiments,native_configuration,irace_configuration"
  jq -r '[.design_seed, .native.mean, .irace.mean, .native.median, .irace.median, .native.wall_s, .irace.wall_s,
          .native.training_mean, .irace.training_mean, .native.experiments_used, .irace.experiments_used,
          .native.configuration, .irace.configuration] | @csv' "$records"
} >"$out/results.csv"
rm -f "$records"

summary="$out/summary.txt"
{
  echo "Native racing vs irace $irace_version: $mission ($direction, $better), FSM + Chocolate, budget $budget, $threads threads"
  echo "Mean score of each design's best control software re-evaluated on seeds $eval_seeds"
  echo
  printf '%-5s %12s %12s %13s %13s %11s %11s\n' seed native_mean irace_mean native_wall_s irace_wall_s native_runs irace_runs
  jq -r '.runs[] | [.design_seed, .native.mean, .irace.mean, .native.wall_s, (if .native.resumed then "*" else " " end),
                     .irace.wall_s, .native.experiments_used, .irace.experiments_used] | @tsv' \
    "$out/results.json" |
    while IFS=$'\t' read -r sd nm im nw mark iw nu iu; do
      printf '%-5s %12.1f %12.1f %12.1f%1s %13.1f %11s %11s\n' "$sd" "$nm" "$im" "$nw" "$mark" "$iw" "$nu" "$iu"
    done
  if jq -e 'any(.runs[]; .native.resumed)' "$out/results.json" >/dev/null; then
    echo "* native design resumed after a kill: its wall time counts only the resumed part"
  fi
  echo
  printf 'median of means: native %.1f, irace %.1f; ratio native/irace %s\n' "$native_median" "$irace_median" "$ratio"
  if [[ "$ok" == true ]]; then
    echo "native at least as good as irace ($better): YES"
  else
    echo "native at least as good as irace ($better): NO"
  fi
} >"$summary"

log "done"
echo
cat "$summary"
echo
echo "Wrote $out/results.csv, $out/results.json and $out/summary.txt"
