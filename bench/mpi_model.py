#!/usr/bin/python3
"""Model of a design's wall time on R MPI ranks, from bench/mpi_scaling.sh's measurements.

Usage: bench/mpi_model.py RESULTS.json [--ranks 1,2,4,16,64,256] [--first-test 5]
                          [--widths-from DESIGN.db] [--per-run S] [--per-step S] [--per-chunk S]
                          [--json OUT]

Inputs (measured by mpi_scaling.sh unless overridden):
  t  per-run cost: the 1-rank design's evaluation seconds / its runs (one thread, no messages);
  o  per-step overhead: rank 0's time per race step outside evaluation (racing statistics,
     sampling, the checkpoint): (design wall - evaluation seconds) / steps, on 1 rank;
  m  per-chunk message cost: ("s evaluating" of evaluate on 2 ranks - runs x t / 2) / chunks,
     never below 50 us;
  w  the width of every race step: runs per (iteration, position) of the design's experiments
     table, in the order the race ran them.

A design's wall on R ranks (threads 1 per rank, dedicated cores, every run costing t) is
  steps x o + the sum over its evaluation batches of a batch's time,
a batch of width W taking, in two models:
  formula    ceil(W / R) x t + chunks(W, R) x m / R: perfect balance, to the run;
  schedule   a replay of MpiEvaluator's dispatch: chunks of chunk_size(W) runs (min(2,
             ceil(W / 3R)), at least 1), a round handed to ranks 1..R-1 first and a second one while
             more than rank 0's share (ceil(W / R)) is left, then rank 0
             evaluates one run at a time while no answer is waiting, every answer refilled with
             one chunk; a message takes m each way. It shows what the scheduler loses on narrow
             batches (rank 0 idle while a rank works off its second chunk, say).
Speed-up is against the 1-rank wall (threaded, no messages); efficiency is speed-up / R.

Batches, both modelled: "step by step", one batch per race step; "merged", the remedy of
evaluating several instances ahead: a race eliminates nothing before its first test (irace's
firstTest, 5 instances), so its first 5 steps go out as one batch (width = the sum of their
widths; o is still paid per step). Commit 73b3384 made the design do so; the results say which
way the measured binary went (its stats line's batch count).

Python 3 standard library only.
"""

import argparse
import heapq
import json
import math
import sqlite3
import statistics
import sys

FLOOR_M = 50e-6


def chunk_size(tasks, ranks):
    """MpiEvaluator's chunk_size(tasks, width=1, total_width=ranks)."""
    share = (tasks + 3 * ranks - 1) // (3 * ranks)
    return max(1, min(2, share))


def chunks(width, ranks):
    return 0 if ranks < 2 else math.ceil(width / chunk_size(width, ranks))


def formula_batch(width, ranks, t, m):
    return math.ceil(width / ranks) * t + chunks(width, ranks) * m / ranks


def schedule_batch(width, ranks, t, m):
    """A replay of MpiEvaluator::evaluate with threads 1 per rank (all runs cost t)."""
    if ranks < 2:
        return width * t
    size = chunk_size(width, ranks)
    state = {"next": 0}
    free = [0.0] * ranks     # when each rank is done with the chunks it was given
    answers = []             # (arrival at rank 0, rank, runs)

    def hand_out(rank, now):
        count = min(size, width - state["next"])
        start = max(free[rank], now + m)
        free[rank] = start + count * t
        heapq.heappush(answers, (free[rank] + m, rank, count))
        state["next"] += count

    now = 0.0
    share_here = math.ceil(width / ranks)  # rank 0's own share: no second chunk eats into it
    for round_ in range(2):  # kChunksInFlight
        for rank in range(1, ranks):
            if state["next"] < width and (round_ == 0 or width - state["next"] > share_here):
                hand_out(rank, now)
    finished = 0
    while finished < width:
        if answers and answers[0][0] <= now:
            _, rank, count = heapq.heappop(answers)
            finished += count
            if state["next"] < width:
                hand_out(rank, now)
        elif state["next"] < width:  # nothing to collect: rank 0 runs one of its own
            now += t
            state["next"] += 1
            finished += 1
        else:
            now = answers[0][0]
    return now


def design_time(steps, batches, ranks, t, o, m, batch=formula_batch):
    """steps x o + the batches' times."""
    return steps * o + sum(batch(w, ranks, t, m) for w in batches)


def merge_first(steps, first_test):
    """Steps of each race with the first `first_test` merged into one batch."""
    merged, by_iteration = [], {}
    for s in steps:
        by_iteration.setdefault(s["iteration"], []).append(s)
    for iteration in sorted(by_iteration):
        race = sorted(by_iteration[iteration], key=lambda s: s["step"])
        head = [s for s in race if s["step"] <= first_test]
        if head:
            merged.append({"iteration": iteration, "step": 1, "width": sum(s["width"] for s in head),
                           "merged": len(head)})
        merged.extend(dict(s, merged=1) for s in race if s["step"] > first_test)
    return merged


def fill_ahead(steps, first_test, ranks, max_ahead=8):
    """The design's batching since a race fills idle workers: a batch takes the steps up to the
    first test, then the next steps of the same race while it is narrower than the ranks (at most
    max_ahead steps past the one it serves). Only runs the race used are counted: a run made
    ahead for a configuration eliminated first sits on a rank that would have idled."""
    out, by_iteration = [], {}
    for s in steps:
        by_iteration.setdefault(s["iteration"], []).append(s)
    for iteration in sorted(by_iteration):
        race = sorted(by_iteration[iteration], key=lambda s: s["step"])
        i = 0
        while i < len(race):
            k, width, j = race[i]["step"], race[i]["width"], i + 1
            while j < len(race) and race[j]["step"] <= k + max_ahead and (race[j]["step"] <= first_test or width < ranks):
                width += race[j]["width"]
                j += 1
            out.append(width)
            i = j
    return out


def steps_from_db(path):
    """Race steps of a design.db: runs per (iteration, position), in the order they ran."""
    c = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    try:
        rows = c.execute("SELECT iteration, position, COUNT(*), MIN(seq) FROM experiments "
                         "GROUP BY iteration, position ORDER BY iteration, MIN(seq)").fetchall()
    finally:
        c.close()
    steps, count = [], {}
    for iteration, position, width, _ in rows:
        count[iteration] = count.get(iteration, 0) + 1
        steps.append({"iteration": iteration, "position": position, "width": width, "step": count[iteration]})
    return steps


def first_below_half(efficiency, limit=1 << 14):
    """Smallest R whose efficiency is below 50 % (doubling, then bisection), or None."""
    r = 1
    while r <= limit:
        if efficiency(r) < 0.5:
            lo, hi = r // 2 + 1, r  # efficiency(lo - 1) >= 0.5
            while lo < hi:
                mid = (lo + hi) // 2
                if efficiency(mid) < 0.5:
                    hi = mid
                else:
                    lo = mid + 1
            return lo
        r *= 2
    return None


def run_weighted_median(widths):
    acc, half = 0, sum(widths) / 2
    for w in sorted(widths):
        acc += w
        if acc >= half:
            return w
    return None


def pct(x):
    return "%.0f%%" % (100 * x)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n", 2)[2])
    ap.add_argument("results", help="JSON written by bench/mpi_scaling.sh")
    ap.add_argument("--ranks", default="1,2,4,16,64,256", help="rank counts to model (default 1,2,4,16,64,256)")
    ap.add_argument("--first-test", type=int, default=5, help="instances before a race's first test (irace's firstTest, 5)")
    ap.add_argument("--widths-from", metavar="DB", help="take the step widths from this design.db instead "
                    "(e.g. a design at the real budget: widths grow with the budget)")
    ap.add_argument("--per-run", type=float, metavar="S", help="t in seconds instead of the measured one")
    ap.add_argument("--per-step", type=float, metavar="S", help="o in seconds instead of the measured one")
    ap.add_argument("--per-chunk", type=float, metavar="S", help="m in seconds instead of the measured one")
    ap.add_argument("--json", metavar="OUT", help="also write the model's figures to OUT")
    args = ap.parse_args()

    with open(args.results) as f:
        res = json.load(f)
    costs = res["costs"]
    ranks = sorted({int(r) for r in args.ranks.replace(" ", ",").split(",") if r} | {1})

    source = {}
    t = args.per_run if args.per_run is not None else costs.get("per_run_s_design", costs.get("per_run_s_evaluate"))
    source["t"] = "given" if args.per_run is not None else (
        "1-rank design: evaluation s / runs" if "per_run_s_design" in costs else "evaluate on 1 rank")
    o = args.per_step if args.per_step is not None else costs.get("per_step_overhead_s")
    source["o"] = "given" if args.per_step is not None else "1-rank design: (wall - evaluation s) / steps"
    if o is None:
        sys.exit("mpi_model: no per-step overhead in the results: give --per-step")
    if args.per_chunk is not None:
        m, source["m"] = args.per_chunk, "given"
    else:
        est = costs.get("per_chunk_estimate_s")
        m = max(FLOOR_M, est or 0.0)
        source["m"] = ("estimated on 2 ranks: %.0f us" % (est * 1e6) if est is not None else "no 2-rank estimate") + (
            ", so the 50 us floor" if m == FLOOR_M else "")

    steps = steps_from_db(args.widths_from) if args.widths_from else res["steps"]["list"]
    widths = [s["width"] for s in steps]
    mwidths = [s["width"] for s in merge_first(steps, args.first_test)]
    n = len(widths)
    batchings = {"step": widths, "merged": mwidths}
    measured_batching = None
    if not args.widths_from:
        seen = set(res["steps"].get("batching_by_ranks", {}).values())
        if len(seen) == 1:
            measured_batching = seen.pop()

    base = design_time(n, widths, 1, t, o, m)  # the same for all: threaded, no messages
    models = {"formula": formula_batch, "schedule": schedule_batch}
    rows = []
    for r in ranks:
        row = {"ranks": r, "chunks": {b: sum(chunks(w, r) for w in ws) for b, ws in batchings.items()}}
        for name, batch in models.items():
            for b, ws in batchings.items():
                wall = design_time(n, ws, r, t, o, m, batch)
                row[f"{name}_{b}"] = {"wall_s": wall, "speed_up": base / wall, "efficiency": base / wall / r}
        rows.append(row)
    r50 = {}
    for name, batch in models.items():
        for b, ws in batchings.items():
            r50[f"{name}_{b}"] = first_below_half(lambda r: base / design_time(n, ws, r, t, o, m, batch) / r)
    for row in rows:
        fw = fill_ahead(steps, args.first_test, row["ranks"])
        wall = design_time(n, fw, row["ranks"], t, o, m)
        row["formula_filled"] = {"wall_s": wall, "speed_up": base / wall, "efficiency": base / wall / row["ranks"],
                                 "batches": len(fw)}
    r50["formula_filled"] = first_below_half(
        lambda r: base / design_time(n, fill_ahead(steps, args.first_test, r), r, t, o, m) / r)
    # With unlimited ranks every batch still takes t, every step o: the ceiling of speed-up.
    ceiling = {b: base / (n * o + len(ws) * t) for b, ws in batchings.items()}

    opts = res.get("options", {})
    print("Model of a design on R ranks (threads 1 each, dedicated cores) -- bench/mpi_model.py")
    print("  measured (%s, %s cores):" % (res.get("date", "?"), res.get("machine", {}).get("cores", "?")))
    print("    t = %.3f ms per run       [%s]" % (t * 1e3, source["t"]))
    print("    o = %.3f ms per race step [%s]" % (o * 1e3, source["o"]))
    print("    m = %.0f us per chunk       [%s]" % (m * 1e6, source["m"]))
    print("    widths: %d steps, %d runs (%s); median %g, run-weighted median %s, max %d" % (
        n, sum(widths),
        args.widths_from or "design of %s%s, budget %s, seed %s" % (
            opts.get("mission", "?"), " at %s s" % opts["duration"] if opts.get("duration") else "",
            opts.get("budget", "?"), opts.get("seed", "?")),
        statistics.median(widths), run_weighted_median(widths), max(widths)))
    if measured_batching:
        print("    the measured binary evaluated %s" % measured_batching)
    print("  modelled below, all of it: wall = steps x o + its batches; a batch of W runs takes ceil(W/R) t + chunks m / R")
    print("  (formula) or a replay of MpiEvaluator's dispatch (schedule); step by step: %d batches; merged (the first %d"
          % (n, args.first_test))
    print("  steps of each race as one batch, as the design does since 73b3384): %d batches" % len(mwidths))
    print()
    head = "  %5s | %8s %8s %5s | %8s %8s %5s | %9s %5s | %9s %5s"
    print(head % ("", "formula", "merged", "", "schedule", "merged", "", "formula", "step", "schedule", "step"))
    print(head % ("R", "wall s", "speed-up", "eff", "wall s", "speed-up", "eff", "speed-up", "eff", "speed-up", "eff"))
    for row in rows:
        fm, sm, fs, ss = row["formula_merged"], row["schedule_merged"], row["formula_step"], row["schedule_step"]
        print(head % (row["ranks"], "%.2f" % fm["wall_s"], "%.1f" % fm["speed_up"], pct(fm["efficiency"]),
                      "%.2f" % sm["wall_s"], "%.1f" % sm["speed_up"], pct(sm["efficiency"]),
                      "%.1f" % fs["speed_up"], pct(fs["efficiency"]), "%.1f" % ss["speed_up"], pct(ss["efficiency"])))
    print("  speed-up and efficiency against the 1-rank wall (%.2f s); \"step\": one batch per race step (before 73b3384)" % base)
    print()
    print("  racing stops scaling (efficiency < 50 %%): step by step from R = %s (formula) / %s (schedule): the typical"
          % (r50["formula_step"], r50["schedule_step"]))
    print("    step is %g runs wide (median; half the runs sit in steps of <= %s), ranks beyond a batch's width idle"
          % (statistics.median(widths), run_weighted_median(widths)))
    print("  merged: from R = %s (formula) / %s (schedule); merged batches: median %g runs, run-weighted median %s"
          % (r50["formula_merged"], r50["schedule_merged"], statistics.median(mwidths), run_weighted_median(mwidths)))
    for r in (64, 256):
        row = next((x for x in rows if x["ranks"] == r), None)
        if row:
            print("  at %d ranks: efficiency %s step by step, %s merged (formula); %s and %s (schedule)" % (
                r, pct(row["formula_step"]["efficiency"]), pct(row["formula_merged"]["efficiency"]),
                pct(row["schedule_step"]["efficiency"]), pct(row["schedule_merged"]["efficiency"])))
    print("  ceiling with unlimited ranks (every step >= o, every batch >= t): speed-up %.1f step by step, %.1f merged"
          % (ceiling["step"], ceiling["merged"]))
    print()
    print("  filled (the design now): after the first test too, a batch narrower than the ranks takes the same")
    print("  configurations' runs on the next instances (up to 8 ahead); formula, runs the race used only:")
    print("  %5s | %8s %8s %5s %8s" % ("R", "wall s", "speed-up", "eff", "batches"))
    for row in rows:
        f = row["formula_filled"]
        print("  %5d | %8.2f %8.1f %5s %8d" % (row["ranks"], f["wall_s"], f["speed_up"], pct(f["efficiency"]), f["batches"]))
    print("  filled: racing stops scaling from R = %s; what remains is o, paid by rank 0 at every step (%d steps x %.2f ms"
          " = %.1f s)" % (r50["formula_filled"], n, o * 1e3, n * o))
    top = rows[-1]
    if top["ranks"] > 1:
        c = top["chunks"]["merged"]
        print("  rank 0 handles every chunk itself: at %d ranks %d chunks x m = %.2f s if one by one (the formula"
              " spreads them: %.3f s)" % (top["ranks"], c, c * m, c * m / top["ranks"]))

    # The models against this machine's designs (rank counts up to its cores only), in the
    # batching the binary used.
    checks = []
    if not args.widths_from and args.per_run is None and args.per_step is None:
        cores = res.get("machine", {}).get("cores", 1)
        for d in res.get("design", {}).get("runs", []):
            if 1 < d["ranks"] <= cores and d.get("timing") and d.get("stats"):
                ws = mwidths if d["stats"]["batches"] == len(mwidths) else widths
                st = d["stats"]
                t0 = st["rank0_evaluating_s"] / st["runs_by_rank"][0] if st["runs_by_rank"][0] else t
                checks.append({"ranks": d["ranks"], "measured_s": d["timing"]["wall_s"],
                               "measured_evaluating_s": st["evaluating_s"], "batches": len(ws),
                               "formula_s": design_time(n, ws, d["ranks"], t, o, m),
                               "schedule_s": design_time(n, ws, d["ranks"], t, o, m, schedule_batch),
                               "rank0_per_run_s": t0,
                               "schedule_rank0_t_s": design_time(n, ws, d["ranks"], t0, o, m, schedule_batch)})
    for c in checks:
        excess = (c["measured_s"] - c["schedule_s"]) / c["batches"]
        c["excess_per_batch_s"] = excess
        print("  check, measured on this machine: the design on %d ranks took %.2f s (its own wall); modelled: formula"
              " %.2f s, schedule %.2f s;" % (c["ranks"], c["measured_s"], c["formula_s"], c["schedule_s"]))
        print("    measured - schedule = %+.1f ms per batch (%+.1f runs' time); rank 0's own runs took %.2f ms there"
              " (%+.0f %% on t):" % (excess * 1e3, excess / t, c["rank0_per_run_s"] * 1e3, 100 * (c["rank0_per_run_s"] / t - 1)))
        print("    the schedule with that t: %.2f s, so %+.1f ms per batch are left to MPI (messages, waiting, polling)"
              % (c["schedule_rank0_t_s"], (c["measured_s"] - c["schedule_rank0_t_s"]) / c["batches"] * 1e3))

    if args.json:
        with open(args.json, "w") as f:
            json.dump({"inputs": {"t_s": t, "o_s": o, "m_s": m, "source": source, "first_test": args.first_test,
                                  "steps": n, "merged_batches": len(mwidths), "runs": sum(widths),
                                  "widths_from": args.widths_from, "measured_batching": measured_batching},
                       "base_wall_s": base, "rows": rows, "efficiency_below_half_from": r50,
                       "ceiling_speed_up": ceiling, "checks": checks}, f, indent=1)


if __name__ == "__main__":
    main()
