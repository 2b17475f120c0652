#!/usr/bin/env python3
"""The Python module's overheads, measured on AAC (20 robots, 120 s):

  1. evaluate() from Python against `swarmdesign evaluate --seeds A-B --json` (the CLI process
     included), per run, on the same seeds and threads: the ratio Python / CLI (about 1 means
     the binding costs nothing; the scores are checked to be the same bits);
  2. trace() of a run against the run itself (its share of a one-thread batch, and a one-seed
     evaluate() call): what recording every tick of every robot into NumPy arrays costs (the
     target: < 2).

    PYTHONPATH=build/python python3 bench/python_vs_cli.py [--binary build/swarmdesign] [--runs 2000]

Each figure is the best of --repeats tries, so that other load on the machine counts least."""

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import swarmdesign as sd

ROOT = Path(__file__).resolve().parents[1]
# Attraction then stop on the black spot: the calibration set's AAC controller (the robots
# meet and stop, so a run does the work a designed one does).
SOFTWARE = ("--fsm-config --nstates 2 --s0 14 --att0 5 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1 "
            "--s1 11 --n1 1 --n1x0 0 --c1x0 11 --p1x0 0.1")


def best_of(repeats, work):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = work()
        times.append(time.perf_counter() - start)
    return min(times), result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default=str(ROOT / "build" / "swarmdesign"))
    parser.add_argument("--runs", type=int, default=2000, help="seeds per evaluation (default 2000)")
    parser.add_argument("--threads", type=int, default=1, help="threads of both evaluations (default 1)")
    parser.add_argument("--traces", type=int, default=100, help="runs traced (default 100)")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    aac = sd.Mission.builtin("aac")
    software = sd.ControlSoftware.parse(SOFTWARE)
    seeds = f"1-{args.runs}"
    command = [args.binary, "evaluate", "--mission", "aac", "--seeds", seeds, "--threads", str(args.threads), "--json",
               *SOFTWARE.split()]

    cli_seconds, cli_out = best_of(args.repeats, lambda: subprocess.run(command, check=True, capture_output=True).stdout)
    py_seconds, py_scores = best_of(args.repeats, lambda: sd.evaluate(aac, software, seeds, threads=args.threads))
    cli_scores = np.array([run["score"] for run in json.loads(cli_out)["runs"]], dtype=np.float64)
    if cli_scores.tobytes() != py_scores.tobytes():
        sys.exit("python_vs_cli: the scores differ from the CLI's")
    print(f"evaluate, {args.runs} AAC runs on {args.threads} thread(s):")
    print(f"  CLI     {cli_seconds / args.runs * 1e3:8.3f} ms per run (process included)")
    print(f"  Python  {py_seconds / args.runs * 1e3:8.3f} ms per run")
    print(f"  ratio Python / CLI = {py_seconds / cli_seconds:.3f} (same bits)")

    trace_seeds = range(1, args.traces + 1)
    run_seconds, _ = best_of(args.repeats, lambda: [sd.evaluate(aac, software, s, threads=1) for s in trace_seeds])
    trace_seconds, traces = best_of(args.repeats, lambda: [sd.trace(aac, software, s) for s in trace_seeds])
    if any(t.score != sd.evaluate(aac, software, t.seed, threads=1)[0] for t in traces[:5]):
        sys.exit("python_vs_cli: a trace's score differs from its run's")
    per_run = py_seconds / args.runs if args.threads == 1 else None
    per_trace = trace_seconds / args.traces
    print(f"trace of a 20-robot AAC run ({args.traces} runs, one at a time):")
    print(f"  trace                       {per_trace * 1e3:8.3f} ms ({traces[0].x.shape[0]} ticks x {traces[0].robots} robots)")
    print(f"  run alone, one evaluate()   {run_seconds / args.traces * 1e3:8.3f} ms per call (a Simulation built per call)")
    if per_run:
        print(f"  run inside a batch          {per_run * 1e3:8.3f} ms (the simulation's own cost)")
        print(f"  ratio trace / run = {per_trace / per_run:.3f} against the batch's run, "
              f"{trace_seconds / run_seconds:.3f} against a one-seed evaluate() (target < 2)")
    else:
        print(f"  ratio trace / run = {trace_seconds / run_seconds:.3f} against a one-seed evaluate() (target < 2)")


if __name__ == "__main__":
    main()
