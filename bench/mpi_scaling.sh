#!/usr/bin/env bash
# MPI scaling benchmark: `mpirun -np R swarmdesign ...` against the threaded evaluator, side by
# side in one run, so that all figures see the same machine load.
#
#   a. evaluate --seeds 1-N (one big batch) on R = 1, 2, 4 ranks (--threads 1 each) and on
#      1, 2 threads without mpirun; mpirun's start-up (`mpirun -np R swarmdesign --version`)
#      is measured apart and subtracted; rank 0's SWARMDESIGN_MPI_STATS line gives the seconds
#      spent evaluating, which exclude start-up altogether.
#   b. a design (--fsm --chocolate, one seed) on R = 1, 2, 4 ranks: wall time, stats line, and
#      whether every design's JSON "best" is the same (the bit-for-bit promise).
#   c. the width of every race step (runs per iteration and position of the design's
#      experiments table), the per-run cost and the per-batch overhead of rank 0.
#
# Prints a compact table, writes everything to one JSON file, then runs bench/mpi_model.py on it
# (the model of 64 and 256 ranks). Run with --help for the options.
set -euo pipefail

PROG=mpi_scaling
SCRIPT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO_DIR="$(cd "$SCRIPT_DIR/.." && pwd)"
# shellcheck source=SCRIPTDIR/lib/cli.sh
source "$SCRIPT_DIR/lib/cli.sh" # die, usage_error, need_value, positive, resolve_binary

usage() {
  cat <<EOF
Usage: bench/mpi_scaling.sh [options]

Scaling of the MPI backend on this machine, next to the threaded evaluator: evaluations per
second of one big batch (evaluate --seeds 1-N) and the wall time of a real design, on each
rank count of --ranks (one thread per rank); the widths of the design's race steps, the
per-run cost and rank 0's per-batch overhead; then bench/mpi_model.py's model of 64 and 256
ranks from those figures.

Options:
  --runs N          runs of the evaluate batch, seeds 1-N (default 1000)
  --budget B        design budget in simulation runs (default 3000; FSM + Chocolate needs 1008)
  --ranks "R ..."   rank counts (default "1 2 4"; 1 is always measured: it is the base)
  --threads "T ..." thread counts of the reference runs without mpirun (default "1 2")
  --mission M       mission name or file (default aac)
  --duration S      run a copy of the mission lasting S seconds instead (e.g. 30: quicker)
  --seed S          design seed (default 1)
  --reps K          repetitions of every evaluate run and start-up timing; the fastest counts
                    (default 3); the designs run once per rank count
  --out FILE        results JSON (default: bench/results/mpi-scaling-<date>-<time>.json); the
                    raw logs and design folders go to the folder of the same name without .json
  --binary PATH     swarmdesign executable (default: \$SWARMDESIGN, else the build folder's)
  --mpirun-args A   extra mpirun options (default "--oversubscribe --bind-to none")
  -h, --help        show this help

Needs: OpenMPI's mpirun, python3 (standard library). As root, the script sets
OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM). Rank counts above the number of cores ($(nproc) here) are
oversubscribed: the table says so, and their efficiency ceiling is cores/R.

Example (about 2 minutes on 2 idle cores; the 30 s check below, under a minute):
  bench/mpi_scaling.sh
  bench/mpi_scaling.sh --runs 200 --budget 1500 --duration 30
EOF
}

# ---------------------------------------------------------------------------------------------
# Options
runs=1000
budget=3000
ranks="1 2 4"
thread_counts="1 2"
mission=aac
duration=""
seed=1
reps=3
out=""
binary="" # --binary; resolve_binary falls back to $SWARMDESIGN, then the build folder
mpirun_args="--oversubscribe --bind-to none"

while [[ $# -gt 0 ]]; do
  case "$1" in
    -h | --help) usage; exit 0 ;;
    --runs) need_value "$@"; runs="$2"; shift 2 ;;
    --budget) need_value "$@"; budget="$2"; shift 2 ;;
    --ranks) need_value "$@"; ranks="$2"; shift 2 ;;
    --threads) need_value "$@"; thread_counts="$2"; shift 2 ;;
    --mission) need_value "$@"; mission="$2"; shift 2 ;;
    --duration) need_value "$@"; duration="$2"; shift 2 ;;
    --seed) need_value "$@"; seed="$2"; shift 2 ;;
    --reps) need_value "$@"; reps="$2"; shift 2 ;;
    --out) need_value "$@"; out="$2"; shift 2 ;;
    --binary) need_value "$@"; binary="$2"; shift 2 ;;
    --mpirun-args) [[ $# -ge 2 ]] || usage_error "$1 needs a value"; mpirun_args="$2"; shift 2 ;;
    --runs=* | --budget=* | --ranks=* | --threads=* | --mission=* | --duration=* | --seed=* | --reps=* | \
      --out=* | --binary=* | --mpirun-args=*)
      set -- "${1%%=*}" "${1#*=}" "${@:2}" ;;
    *) usage_error "unknown argument '$1'" ;;
  esac
done
positive --runs "$runs"
positive --budget "$budget"
positive --seed "$seed"
positive --reps "$reps"
for r in $ranks; do positive --ranks "$r"; done
for t in $thread_counts; do positive --threads "$t"; done
[[ -z "$duration" || "$duration" =~ ^[0-9]+([.][0-9]+)?$ ]] || usage_error "--duration must be a number of seconds, not '$duration'"
# Rank 1 is the base of every efficiency; sorted, without repeats (split on purpose: integers).
# shellcheck disable=SC2086
ranks="$(printf '%s\n' 1 $ranks | sort -n -u | tr '\n' ' ' | sed 's/ $//')"
# shellcheck disable=SC2086
thread_counts="$(printf '%s\n' $thread_counts | sort -n -u | tr '\n' ' ' | sed 's/ $//')"

# ---------------------------------------------------------------------------------------------
# Tools
command -v mpirun >/dev/null 2>&1 || die "mpirun not found (Debian: apt-get install openmpi-bin)"
command -v python3 >/dev/null 2>&1 || die "python3 not found"
binary="$(resolve_binary "$binary")" || exit
version="$("$binary" --version 2>&1)" || die "$binary --version failed: $version"
mpi_version="$(mpirun --version 2>&1 | head -n 1)"
cores="$(nproc)"
if [[ "$(id -u)" == 0 ]]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export SWARMDESIGN_MPI_STATS=1
read -r -a mpirun_extra <<<"$mpirun_args"

# ---------------------------------------------------------------------------------------------
# Output
if [[ -z "$out" ]]; then
  out="$SCRIPT_DIR/results/mpi-scaling-$(date +%Y%m%d-%H%M%S).json"
fi
[[ "$out" == *.json ]] || usage_error "--out must end in .json, not '$out'"
mkdir -p "$(dirname "$out")" || die "cannot create $(dirname "$out")"
out="$(cd "$(dirname "$out")" && pwd)/$(basename "$out")"
raw="${out%.json}"
[[ ! -e "$raw" && ! -e "$out" ]] || die "$out or $raw exists already: give another --out"
mkdir -p "$raw"
# A copy of the binary runs every measurement: a rebuild during the run cannot mix two builds.
cp "$binary" "$raw/swarmdesign" || die "cannot copy $binary to $raw"
source_binary="$binary"
binary="$raw/swarmdesign"
[[ "$("$binary" --version 2>&1)" == "$version" ]] || die "the copy of $source_binary does not run (being rebuilt?): try again"

start_s=$(date +%s)
log() {
  local e=$(($(date +%s) - start_s))
  printf '[%02d:%02d:%02d] %s\n' $((e / 3600)) $((e % 3600 / 60)) $((e % 60)) "$*"
}
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.6f", b - a }'; }
tail_of() { tail -n "${2:-3}" "$1" 2>/dev/null | tr '\n' ' ' | sed 's/  */ /g'; }

# The mission: by name, or a copy with a shorter duration.
mission_arg="$mission"
if [[ -n "$duration" ]]; then
  source_file=""
  if [[ -f "$mission" ]]; then
    source_file="$mission"
  elif [[ -f "$REPO_DIR/missions/$mission.json" ]]; then
    source_file="$REPO_DIR/missions/$mission.json"
  fi
  [[ -n "$source_file" ]] || { rm -rf "$raw"; die "--duration needs the mission's file: no $mission nor missions/$mission.json"; }
  grep -Eq '"duration"[[:space:]]*:' "$source_file" || { rm -rf "$raw"; die "$source_file has no \"duration\" to change"; }
  sed -E "s/(\"duration\"[[:space:]]*:[[:space:]]*)[0-9.]+/\1$duration/" "$source_file" >"$raw/mission.json"
  mission_arg="$raw/mission.json"
fi

# Preflight: the mission loads, and the budget is not below the minimum of iterated racing
# (the design says so at once, before simulating anything). A failure leaves no results folder.
preflight_die() {
  local message="$*"
  rm -rf "$raw"
  die "$message"
}
"$binary" evaluate --mission "$mission_arg" --seed 1 --fsm-config --nstates 1 --s0 0 --rwm0 50 >"$raw/preflight.log" 2>&1 ||
  preflight_die "mission '$mission' does not evaluate: $(tail_of "$raw/preflight.log")"
if ! "$binary" design --mission "$mission_arg" --budget 1 --fsm --chocolate --seed 1 --threads 1 \
  --out "$raw/preflight-design" >>"$raw/preflight.log" 2>&1; then
  minimum="$(grep -o 'minimum of [0-9]*' "$raw/preflight.log" | grep -o '[0-9]*$' | head -n 1 || true)"
  if [[ -n "$minimum" ]] && ((budget < minimum)); then
    preflight_die "budget $budget is below the minimum of $minimum simulation runs of iterated racing for FSM + Chocolate: use --budget $minimum or more"
  fi
fi
rm -rf "$raw/preflight-design" "$raw/preflight.log"

# The control software of the evaluate batch: a 3-state FSM of AAC (any mission accepts it).
EVAL_CONFIG=(--fsm-config --nstates 3 --s0 14 --att0 3.5 --n0 1 --n0x0 1 --c0x0 13 --p0x0 5 --w0x0 2
  --s1 11 --s2 10 --rwm2 7)

oversubscribed=""
for r in $ranks; do ((r <= cores)) || oversubscribed+="$r "; done
log "MPI scaling on $mission_arg${duration:+ ($duration s)}: evaluate --seeds 1-$runs x $reps, design budget $budget seed $seed"
log "ranks $ranks (one thread each), threads $thread_counts without mpirun; $cores cores${oversubscribed:+; oversubscribed: ${oversubscribed% } ranks}"
log "$version; $mpi_version; mpirun $mpirun_args"
log "results in $out (raw logs in $raw)"
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
binary_sum="$(sha256sum "$binary" | cut -c1-16)"
if awk -v l="${load_before%% *}" -v c="$cores" 'BEGIN { exit !(l > c / 2) }'; then
  log "warning: the machine is busy (load $load_before on $cores cores): the figures will be noisy"
fi

# Every measurement is one line of runs.tsv: kind label ranks threads rep wall_s stdout stderr.
printf 'kind\tlabel\tranks\tthreads\trep\twall_s\tstdout\tstderr\tcommand\n' >"$raw/runs.tsv"
measure() { # kind label ranks threads rep -- command...
  local kind=$1 label=$2 r=$3 t=$4 rep=$5 t0 t1 rc=0
  shift 6
  local base="$raw/$kind-$label-rep$rep"
  t0=$(now)
  "$@" >"$base.out" 2>"$base.err" || rc=$?
  t1=$(now)
  ((rc == 0)) || die "$kind $label failed (exit $rc): $(tail_of "$base.err") (see $base.err)"
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$kind" "$label" "$r" "$t" "$rep" "$(elapsed "$t0" "$t1")" \
    "$base.out" "$base.err" "$*" >>"$raw/runs.tsv"
  LAST_WALL=$(elapsed "$t0" "$t1")
}
MPI=(mpirun "${mpirun_extra[@]}" -x SWARMDESIGN_MPI_STATS -np)

# ---------------------------------------------------------------------------------------------
# a. Start-up and one big batch, interleaved repetition by repetition.
for rep in $(seq 1 "$reps"); do
  measure startup plain 0 0 "$rep" -- "$binary" --version
  for r in $ranks; do measure startup "np$r" "$r" 1 "$rep" -- "${MPI[@]}" "$r" "$binary" --version; done
  for t in $thread_counts; do
    measure evaluate "threads$t" 0 "$t" "$rep" -- "$binary" evaluate --mission "$mission_arg" --seeds "1-$runs" \
      --threads "$t" "${EVAL_CONFIG[@]}"
    log "evaluate $runs runs, $t threads: ${LAST_WALL%????} s (rep $rep/$reps)"
  done
  for r in $ranks; do
    measure evaluate "np$r" "$r" 1 "$rep" -- "${MPI[@]}" "$r" "$binary" evaluate --mission "$mission_arg" --seeds "1-$runs" \
      --threads 1 "${EVAL_CONFIG[@]}"
    log "evaluate $runs runs, $r ranks: ${LAST_WALL%????} s (rep $rep/$reps)"
  done
done

# b. The design on every rank count.
for r in $ranks; do
  measure design "np$r" "$r" 1 1 -- "${MPI[@]}" "$r" "$binary" design --mission "$mission_arg" --budget "$budget" --seed "$seed" \
    --fsm --chocolate --threads 1 --out "$raw/design-np$r" --json
  log "design on $r ranks: ${LAST_WALL%????} s"
done
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
binary_sum_after="$(sha256sum "$source_binary" | cut -c1-16)"
[[ "$binary_sum" == "$binary_sum_after" ]] ||
  log "note: $source_binary was rebuilt during the run; its copy $binary ran every measurement"

# ---------------------------------------------------------------------------------------------
# c. Analysis: the table and the JSON.
MS_CORES=$cores MS_RUNS=$runs MS_RANKS="$ranks" MS_THREADS="$thread_counts" MS_BUDGET=$budget MS_SEED=$seed \
  MS_REPS=$reps MS_MISSION="$mission" MS_MISSION_ARG="$mission_arg" MS_DURATION="$duration" MS_RAW="$raw" \
  MS_DATE="$(date -Iseconds)" MS_LOAD_BEFORE="$load_before" MS_LOAD_AFTER="$load_after" MS_OPENMPI="$mpi_version" \
  MS_VERSION="$version" MS_MPIRUN_ARGS="$mpirun_args" MS_BINARY="$source_binary" MS_SUM="$binary_sum" \
  MS_SUM_AFTER="$binary_sum_after" \
  python3 - "$raw/runs.tsv" "$out" <<'EOF'
import csv, json, math, os, re, sqlite3, statistics, sys

tsv, out_path = sys.argv[1], sys.argv[2]
env = os.environ
cores = int(env["MS_CORES"])
runs_n = int(env["MS_RUNS"])
ranks = [int(r) for r in env["MS_RANKS"].split()]
thread_counts = [int(t) for t in env["MS_THREADS"].split()]
budget, seed, nreps = int(env["MS_BUDGET"]), int(env["MS_SEED"]), int(env["MS_REPS"])
mission, duration = env["MS_MISSION"], env["MS_DURATION"] or None
STATS = re.compile(r"^mpi: (\d+) batches, (\d+) chunks, ([0-9.]+) s evaluating \(([0-9.]+) s on rank 0\); runs by rank:((?: \d+)*)\s*$")

rows = list(csv.DictReader(open(tsv), delimiter="\t"))
def read(path):
    with open(path, errors="replace") as f:
        return f.read()

def stats_of(err_text):
    """Rank 0's stats lines (one per evaluator), summed; None without any."""
    lines = [STATS.match(l) for l in err_text.splitlines()]
    lines = [m for m in lines if m]
    if not lines:
        return None
    by_rank = [0] * max(len(m.group(5).split()) for m in lines)
    for m in lines:
        for i, v in enumerate(m.group(5).split()):
            by_rank[i] += int(v)
    return {"lines": len(lines), "batches": sum(int(m.group(1)) for m in lines),
            "chunks": sum(int(m.group(2)) for m in lines),
            "evaluating_s": sum(float(m.group(3)) for m in lines),
            "rank0_evaluating_s": sum(float(m.group(4)) for m in lines), "runs_by_rank": by_rank}

warnings = []
def other_stderr(row):
    """Whatever else went to stderr (OpenMPI's warnings, say), once per distinct line."""
    for line in read(row["stderr"]).splitlines():
        if line.strip() and not STATS.match(line) and line not in warnings:
            warnings.append(line)

for row in rows:
    other_stderr(row)

def best(values):
    return min(values) if values else None

# Start-up: the fastest of the repetitions.
startup = {}
for row in rows:
    if row["kind"] == "startup":
        startup.setdefault(row["label"], []).append(float(row["wall_s"]))
startup_s = {k: best(v) for k, v in startup.items()}

# a. Evaluate: one batch.
evaluate = []
outputs = {}
for label in [f"threads{t}" for t in thread_counts] + [f"np{r}" for r in ranks]:
    reps = [r for r in rows if r["kind"] == "evaluate" and r["label"] == label]
    if not reps:
        continue
    walls = [float(r["wall_s"]) for r in reps]
    stats = [stats_of(read(r["stderr"])) for r in reps]
    outputs[label] = {read(r["stdout"]) for r in reps}
    mpi = label.startswith("np")
    n = int(reps[0]["ranks"]) if mpi else int(reps[0]["threads"])
    start = startup_s["np%d" % n] if mpi else startup_s["plain"]
    entry = {"setup": f"mpirun -np {n}" if mpi else f"{n} threads", "label": label, "mpi": mpi,
             "ranks": n if mpi else 1, "threads": 1 if mpi else n, "width": n,
             "oversubscribed": n > cores, "ceiling": min(1.0, cores / n),
             "wall_s": walls, "best_wall_s": best(walls), "startup_s": start,
             "net_wall_s": best(walls) - start,
             "evals_per_s_raw": runs_n / best(walls),
             "evals_per_s_net": runs_n / max(best(walls) - start, 1e-9)}
    if all(stats):
        ev = [s["evaluating_s"] for s in stats]
        i = ev.index(min(ev))
        entry.update({"stats": stats, "evaluating_s": ev, "best_evaluating_s": min(ev),
                      "evals_per_s_evaluating": runs_n / min(ev), "best_stats": stats[i]})
    evaluate.append(entry)
by_label = {e["label"]: e for e in evaluate}
base_rank = by_label["np1"]["evals_per_s_net"]
base_thread = by_label["threads1"]["evals_per_s_net"] if "threads1" in by_label else None
for e in evaluate:
    base = base_rank if e["mpi"] else base_thread
    if base:
        e["efficiency_net"] = e["evals_per_s_net"] / (e["width"] * base)
        if "evals_per_s_evaluating" in e:
            e["efficiency_evaluating"] = e["evals_per_s_evaluating"] / (e["width"] * base)
scores_identical = len({s for v in outputs.values() for s in v}) == 1

# b. Designs.
designs = []
for r in ranks:
    row = next(x for x in rows if x["kind"] == "design" and x["label"] == f"np{r}")
    report = json.loads(read(row["stdout"]))
    designs.append({"ranks": r, "oversubscribed": r > cores, "wall_s": float(row["wall_s"]),
                    "startup_s": startup_s[f"np{r}"], "net_wall_s": float(row["wall_s"]) - startup_s[f"np{r}"],
                    "timing": report.get("timing"), "experiments_used": report["experiments_used"],
                    "iterations": report.get("iterations"), "best": report["best"],
                    "stats": stats_of(read(row["stderr"])), "folder": report.get("folder")})
canon = lambda d: json.dumps(d["best"], sort_keys=True)
best_identical = len({canon(d) for d in designs}) == 1

def experiments(folder):
    c = sqlite3.connect(f"file:{folder}/design.db?mode=ro", uri=True)
    try:
        return c.execute("SELECT seq, iteration, position, seed, configuration_id, cost FROM experiments ORDER BY seq").fetchall()
    finally:
        c.close()
tables = {d["ranks"]: experiments(d["folder"]) for d in designs}
experiments_identical = len({json.dumps(t) for t in tables.values()}) == 1

# c. Race steps of the 1-rank design: runs per (iteration, position), in the order they ran.
groups = {}
for seq, iteration, position, *_ in tables[1]:
    g = groups.setdefault((iteration, position), {"iteration": iteration, "position": position, "first_seq": seq, "width": 0})
    g["width"] += 1
    g["first_seq"] = min(g["first_seq"], seq)
steps = sorted(groups.values(), key=lambda g: (g["iteration"], g["first_seq"]))
step_in_race = {}
for g in steps:
    step_in_race[g["iteration"]] = step_in_race.get(g["iteration"], 0) + 1
    g["step"] = step_in_race[g["iteration"]]
    del g["first_seq"]
widths = [g["width"] for g in steps]
total_runs = sum(widths)
def share_below(limit):
    return sum(w for w in widths if w < limit) / total_runs
def run_weighted_median(ws):
    acc, half = 0, sum(ws) / 2
    for w in sorted(ws):
        acc += w
        if acc >= half:
            return w
# Since 73b3384 a race's first 5 steps (up to irace's first test) go out as one batch; the stats
# line's batch count tells which way the measured binary evaluates.
FIRST_TEST = 5
merged_batches = len({g["iteration"] for g in steps}) + sum(1 for g in steps if g["step"] > FIRST_TEST)
def batching_of(batches):
    return {len(steps): "step by step", merged_batches: f"first {FIRST_TEST} steps of each race merged"}.get(
        batches, f"other ({batches} batches)")
batching = {d["ranks"]: batching_of(d["stats"]["batches"]) for d in designs if d["stats"]}
width_stats = {"steps": len(widths), "runs": total_runs, "min": min(widths), "median": statistics.median(widths),
               "mean": total_runs / len(widths), "max": max(widths), "run_weighted_median": run_weighted_median(widths),
               "share_of_runs_in_steps_below_64": share_below(64), "share_of_runs_in_steps_below_256": share_below(256)}

# Costs. t: per run (one thread, no messages); o: rank 0's time per race step outside
# evaluation; m: per chunk, what a batch on 2 ranks costs beyond its runs.
d1 = designs[0]
costs = {"notes": []}
if d1["timing"]:
    costs["per_run_s_design"] = d1["timing"]["evaluation_s"] / d1["experiments_used"]
    costs["per_step_overhead_s"] = (d1["timing"]["wall_s"] - d1["timing"]["evaluation_s"]) / len(widths)
    costs["notes"].append("per_run_s_design and per_step_overhead_s: the 1-rank design's own timing "
                          "(evaluation_s / runs; (wall_s - evaluation_s) / race steps)")
costs["per_run_s_evaluate"] = by_label["np1"]["net_wall_s"] / runs_n
if "threads1" in by_label:
    costs["per_run_s_evaluate_threads1"] = by_label["threads1"]["net_wall_s"] / runs_n
costs["notes"].append("per_run_s_evaluate: evaluate's FSM on mpirun -np 1, (wall - start-up) / runs; "
                      "per_run_s_evaluate_threads1: the same without mpirun")
overheads = {}
for d in designs:
    if d["stats"] and d["timing"]:
        s = d["stats"]
        overheads[d["ranks"]] = {
            "steps": len(widths),
            "from_design_timing_s": (d["timing"]["wall_s"] - s["evaluating_s"]) / len(widths),
            "from_mpirun_wall_s": (d["net_wall_s"] - s["evaluating_s"]) / len(widths)}
costs["per_step_overhead_by_ranks"] = overheads
costs["notes"].append("per_step_overhead_by_ranks: (design's wall_s - stats 's evaluating') / race steps, and the same "
                      "from mpirun's wall minus its start-up (that one also holds the program's set-up and final report)")
FLOOR = 50e-6
if "np2" in by_label and "best_stats" in by_label["np2"]:
    e2 = by_label["np2"]
    s2 = e2["best_stats"]
    r_eff = min(2, cores)
    # The per-run cost of the same run (rank 0's own runs): no start-up to subtract, same load.
    t_same = s2["rank0_evaluating_s"] / s2["runs_by_rank"][0] if s2["runs_by_rank"][0] else costs["per_run_s_evaluate"]
    costs["per_run_s_evaluate_rank0_at_2"] = t_same
    costs["per_chunk_estimate_s"] = (s2["evaluating_s"] - runs_n * t_same / r_eff) / s2["chunks"]
    costs["per_chunk_estimate_startup_s"] = (s2["evaluating_s"] - runs_n * costs["per_run_s_evaluate"] / r_eff) / s2["chunks"]
    costs["notes"].append("per_chunk_estimate_s: (evaluate's 's evaluating' at 2 ranks - runs x t / 2) / chunks, t = rank 0's "
                          "own seconds per run in that run ('s on rank 0' / its runs); per_chunk_estimate_startup_s: the "
                          "same with t = per_run_s_evaluate (mpirun -np 1, start-up subtracted: noisier)")
else:
    costs["per_chunk_estimate_s"] = None
    costs["notes"].append("per_chunk_estimate_s: no 2-rank evaluate run: the floor is used")
costs["per_chunk_floor_s"] = FLOOR
costs["per_chunk_s"] = max(FLOOR, costs["per_chunk_estimate_s"] or 0.0)

result = {
    "benchmark": "mpi-scaling",
    "date": env["MS_DATE"],
    "machine": {"cores": cores, "load_before": env["MS_LOAD_BEFORE"], "load_after": env["MS_LOAD_AFTER"],
                "openmpi": env["MS_OPENMPI"], "swarmdesign": env["MS_VERSION"], "mpirun_args": env["MS_MPIRUN_ARGS"],
                "binary": env["MS_BINARY"], "binary_sha256_16": env["MS_SUM"],
                "binary_rebuilt_during_run": env["MS_SUM"] != env["MS_SUM_AFTER"]},
    "options": {"runs": runs_n, "budget": budget, "ranks": ranks, "threads": thread_counts, "mission": mission,
                "mission_arg": env["MS_MISSION_ARG"], "duration": duration, "seed": seed, "reps": nreps},
    "raw": env["MS_RAW"],
    "startup_s": {"plain": startup_s["plain"], **{k[2:]: v for k, v in startup_s.items() if k.startswith("np")}},
    "startup_all_s": startup,
    "evaluate": {"runs": runs_n, "scores_identical": scores_identical, "rows": evaluate},
    "design": {"best_identical": best_identical, "experiments_identical": experiments_identical, "runs": designs},
    "steps": {"source": "design-np1/design.db", "first_test": FIRST_TEST, "stats": width_stats,
              "merged_batches": merged_batches, "batching_by_ranks": batching, "list": steps},
    "costs": costs,
    "stderr_other": warnings,
}
with open(out_path, "w") as f:
    json.dump(result, f, indent=1)

# ---- The table.
ms = lambda s: "%.2f" % (s * 1e3)
print()
print(f"a. evaluate --seeds 1-{runs_n}: one batch; fastest of {nreps}; {cores} cores")
print("   start-up: plain %.3f s; " % startup_s["plain"] +
      ", ".join("mpirun -np %s %.3f s" % (k[2:], v) for k, v in sorted(startup_s.items()) if k.startswith("np")))
head = "   %-14s %8s %8s %9s %9s %9s %6s %6s %5s  %s"
print(head % ("setup", "wall s", "net s", "eval s", "evals/s", "(eval)", "eff", "(eval)", "ceil", "runs by rank"))
for e in evaluate:
    ev = e.get("best_evaluating_s")
    print(head % (e["setup"], "%.3f" % e["best_wall_s"], "%.3f" % e["net_wall_s"], "%.3f" % ev if ev else "-",
                  "%.1f" % e["evals_per_s_net"], "%.1f" % e["evals_per_s_evaluating"] if ev else "-",
                  "%.2f" % e["efficiency_net"] if "efficiency_net" in e else "-",
                  "%.2f" % e["efficiency_evaluating"] if "efficiency_evaluating" in e else "-",
                  "%.2f" % e["ceiling"],
                  " ".join(map(str, e["best_stats"]["runs_by_rank"])) + (" (oversubscribed)" if e["oversubscribed"] else "")
                  if "best_stats" in e else ("(oversubscribed)" if e["oversubscribed"] else "")))
print("   net = wall - start-up; eval = rank 0's 's evaluating' (no start-up; none on 1 rank, which runs threaded);")
print("   eff = evals/s / (R x evals/s on 1 rank; threads: on 1 thread); ceil = min(1, cores/R)")
print("   scores of all setups identical: %s" % ("OK" if scores_identical else "MISMATCH"))
print()
print(f"b. design --mission {mission}{' (%s s)' % duration if duration else ''} --budget {budget} --seed {seed} --fsm --chocolate --threads 1")
head = "   %-6s %8s %8s %9s %8s %8s %8s %8s %7s %7s  %s"
print(head % ("ranks", "wall s", "net s", "design s", "eval s", "core-ms", "r0-ms", "speed-up", "batches", "chunks", "runs by rank"))
for d in designs:
    s, t = d["stats"], d["timing"] or {}
    print(head % (d["ranks"], "%.2f" % d["wall_s"], "%.2f" % d["net_wall_s"], "%.2f" % t.get("wall_s", float("nan")),
                  "%.2f" % (s["evaluating_s"] if s else t.get("evaluation_s", float("nan"))),
                  ms((s["evaluating_s"] if s else t.get("evaluation_s", float("nan"))) * min(d["ranks"], cores) / d["experiments_used"]),
                  ms(s["rank0_evaluating_s"] / s["runs_by_rank"][0] if s and s["runs_by_rank"][0]
                     else t.get("evaluation_s", float("nan")) / d["experiments_used"]),
                  "%.2f" % (designs[0]["net_wall_s"] / d["net_wall_s"]),
                  s["batches"] if s else len(widths), s["chunks"] if s else "-",
                  (" ".join(map(str, s["runs_by_rank"])) if s else "-") + (" (oversubscribed)" if d["oversubscribed"] else "")))
print("   design s = the design's own wall_s; eval s on 1 rank = its evaluation_s (no stats line: threaded);")
print("   core-ms = eval s x min(R, cores) / runs: core time per run, messages and idle included; r0-ms = rank 0's")
print("   own seconds per run ('s on rank 0' / its runs): above the 1-rank figure, the simulations themselves ran slower")
print("   (cores shared with another process, or oversubscribed), whatever MPI does; speed-up on net s")
print("   batches on ranks (%d race steps; %d if the first %d of each race are merged): %s" % (
    len(widths), merged_batches, FIRST_TEST, "; ".join("%d: %s" % kv for kv in batching.items()) or "-"))
print("   best identical on all rank counts: %s (%s); experiments tables identical: %s" % (
    "OK" if best_identical else "MISMATCH", "id %s, mean %s" % (designs[0]["best"]["id"], designs[0]["best"]["mean_score"]),
    "OK" if experiments_identical else "MISMATCH"))
print()
w = width_stats
print(f"c. race steps of the design: {w['steps']} steps, {w['runs']} runs; width min {w['min']}, median {w['median']:g}, "
      f"mean {w['mean']:.1f}, max {w['max']}; run-weighted median {w['run_weighted_median']}")
print("   share of runs in steps narrower than 64: %.0f %%, than 256: %.0f %%" % (
    100 * w["share_of_runs_in_steps_below_64"], 100 * w["share_of_runs_in_steps_below_256"]))
if "per_run_s_design" in costs:
    print("   per run t: %s ms (design mix, 1 rank); evaluate's FSM: %s ms (1 rank), %s ms (1 thread)%s" % (
        ms(costs["per_run_s_design"]), ms(costs["per_run_s_evaluate"]),
        ms(costs["per_run_s_evaluate_threads1"]) if "per_run_s_evaluate_threads1" in costs else "-",
        ", %s ms (rank 0 at 2 ranks)" % ms(costs["per_run_s_evaluate_rank0_at_2"]) if "per_run_s_evaluate_rank0_at_2" in costs else ""))
    print("   per step o (rank 0 outside evaluation): %s ms on 1 rank; " % ms(costs["per_step_overhead_s"]) +
          "; ".join("%s ms on %d ranks (%s ms from mpirun's wall)" % (ms(v["from_design_timing_s"]), r, ms(v["from_mpirun_wall_s"]))
                    for r, v in overheads.items()))
est = costs["per_chunk_estimate_s"]
print("   per chunk m: estimate %s ms at 2 ranks (%s ms with mpirun -np 1's t); used %s ms (floor %s ms)" % (
    ms(est) if est is not None else "-",
    ms(costs["per_chunk_estimate_startup_s"]) if "per_chunk_estimate_startup_s" in costs else "-",
    ms(costs["per_chunk_s"]), ms(FLOOR)))
if result["machine"]["binary_rebuilt_during_run"]:
    print()
    print("note: the binary was rebuilt during the run; its copy (taken at the start) ran every measurement")
if warnings:
    print()
    print("other stderr lines (OpenMPI and the like):")
    for line in warnings[:20]:
        print("   " + line)
EOF

rm -f "$raw/swarmdesign" # its hash is in the results
log "wrote $out"
echo
# The model of 64 and 256 ranks; its figures join the results under "model".
python3 "$SCRIPT_DIR/mpi_model.py" "$out" --json "$raw/model.json"
python3 - "$out" "$raw/model.json" <<'EOF'
import json, sys
with open(sys.argv[1]) as f:
    results = json.load(f)
with open(sys.argv[2]) as f:
    results["model"] = json.load(f)
with open(sys.argv[1], "w") as f:
    json.dump(results, f, indent=1)
EOF
log "done"
