#!/usr/bin/env python3
"""Compare SwarmDesign's per-tick traces with ARGoS' (../shared/calibration/traces/set4) as
distributions over seeds, tick by tick: robots in a target, FSM state / tree action occupancy,
running module, filtered floor and LED colour. Seeds differ between the simulators, so the
runs are compared as two samples, never seed by seed.

Both sides use the set-4 columns (tick,robot,x,y,yaw,v_left,v_right,state,behaviour,ground,led);
`swarmdesign evaluate --trace` writes them. Our traces can be given as files or made here:

  bench/trace_compare.py --argos '../shared/calibration/traces/set4/tutti_agg_T10_seed*.csv.gz' \\
      --swarmdesign build/swarmdesign --mission tutti-aggregation --seeds 200 \\
      --flavour tuttifrutti --config "$(cat t10.txt)" --target 'y>=0.465' --ticks 0:30

Per tick (or per --window of ticks) it prints the mean count of robots in the target on each
side with Welch's t over runs, then the share of robot-ticks in each value of state, behaviour,
ground and led, side by side. --start first compares the tick-0 poses (the start
distribution): robots in the target per run, and per robot its distance from --centre, polar
angle, x, y, yaw and nearest neighbour, as means and two-sample Kolmogorov-Smirnov D and p.
ARGoS runs of one seed start alike whatever the controller (set 4's T10 and T14 seed S have
the same tick 0), so give one controller's files for the start, or the placements count twice.
Only the standard library is used.
"""
import argparse
import collections
import csv
import glob
import gzip
import math
import os
import subprocess
import sys
import tempfile

COLUMNS = ("state", "behaviour", "ground", "led")


def open_text(path):
    return gzip.open(path, "rt") if path.endswith(".gz") else open(path, newline="")


def parse_target(spec):
    """'y>=0.465', 'y<0.5', 'x>=0', or 'disc:cx,cy,r' (centre within r)."""
    if spec.startswith("disc:"):
        cx, cy, r = (float(v) for v in spec[5:].split(","))
        return lambda x, y: (x - cx) ** 2 + (y - cy) ** 2 <= r * r
    for op in (">=", "<=", ">", "<"):
        if op in spec:
            axis, value = spec.split(op)
            value = float(value)
            pick = (lambda x, y: x) if axis.strip() == "x" else (lambda x, y: y)
            return {">=": lambda x, y: pick(x, y) >= value, "<=": lambda x, y: pick(x, y) <= value,
                    ">": lambda x, y: pick(x, y) > value, "<": lambda x, y: pick(x, y) < value}[op]
    raise SystemExit("bad --target: " + spec)


class Side:
    """One simulator's runs: per window, the in-target count of every run and value tallies."""

    def __init__(self):
        self.in_target = collections.defaultdict(list)  # window -> [mean count per run]
        self.tally = {c: collections.defaultdict(collections.Counter) for c in COLUMNS}
        self.runs = 0
        self.start = []  # per run, the tick-0 poses (x, y, yaw)

    def add_run(self, path, target, first, last, window):
        counts = collections.defaultdict(lambda: [0, 0])  # window -> [robots in target, ticks seen]
        ticks_seen = collections.defaultdict(set)
        poses = []
        with open_text(path) as f:
            for row in csv.DictReader(f):
                tick = int(row["tick"])
                if tick == 0:
                    if not poses:
                        self.start.append(poses)
                    poses.append((float(row["x"]), float(row["y"]), float(row["yaw"])))
                if tick < first or tick > last:
                    continue
                w = (tick - first) // window
                ticks_seen[w].add(tick)
                if target(float(row["x"]), float(row["y"])):
                    counts[w][0] += 1
                for c in COLUMNS:
                    value = row.get(c, "")
                    if value != "":
                        if c == "ground":
                            value = "%g" % float(value)
                        self.tally[c][w][value] += 1
        for w, seen in ticks_seen.items():
            self.in_target[w].append(counts[w][0] / len(seen))
        self.runs += 1


def mean_sd(values):
    n = len(values)
    m = sum(values) / n
    v = sum((x - m) ** 2 for x in values) / (n - 1) if n > 1 else 0.0
    return m, math.sqrt(v)


def welch_t(a, b):
    (ma, sa), (mb, sb) = mean_sd(a), mean_sd(b)
    se = math.sqrt(sa * sa / len(a) + sb * sb / len(b))
    return (mb - ma) / se if se > 0 else 0.0


def ks_two_sample(a, b):
    """Kolmogorov-Smirnov D of two samples and its asymptotic p (Stephens' correction)."""
    a, b = sorted(a), sorted(b)
    i = j = 0
    d = 0.0
    while i < len(a) and j < len(b):
        x = min(a[i], b[j])
        while i < len(a) and a[i] == x:
            i += 1
        while j < len(b) and b[j] == x:
            j += 1
        d = max(d, abs(i / len(a) - j / len(b)))
    ne = len(a) * len(b) / (len(a) + len(b))
    lam = (math.sqrt(ne) + 0.12 + 0.11 / math.sqrt(ne)) * d
    if lam < 0.2:
        return d, 1.0
    p = 2.0 * sum((-1) ** (k - 1) * math.exp(-2.0 * k * k * lam * lam) for k in range(1, 101))
    return d, min(1.0, max(0.0, p))


def start_features(side, centre):
    """Per robot at tick 0: distance from centre, polar angle about it, x, y, yaw, nearest robot."""
    f = collections.defaultdict(list)
    for poses in side.start:
        for k, (x, y, yaw) in enumerate(poses):
            f["radius"].append(math.hypot(x - centre[0], y - centre[1]))
            f["angle"].append(math.atan2(y - centre[1], x - centre[0]))
            f["x"].append(x)
            f["y"].append(y)
            f["yaw"].append(yaw)
            f["nearest"].append(min((math.hypot(x - u, y - v) for m, (u, v, _) in enumerate(poses) if m != k),
                                    default=float("nan")))
    return f


def print_start(argos, ours, target, centre):
    print("tick 0 (start): ARGoS %d runs / %d robots, SwarmDesign %d runs / %d robots" %
          (len(argos.start), sum(map(len, argos.start)), len(ours.start), sum(map(len, ours.start))))
    if not argos.start or not ours.start:
        return
    for name, side in (("ARGoS", argos), ("SwarmDesign", ours)):
        counts = [sum(1 for x, y, _ in poses if target(x, y)) for poses in side.start]
        robots = sum(map(len, side.start))
        print("  in target at tick 0, %-11s %5d robots of %6d: %.3f per run, runs with one %.3f" %
              (name, sum(counts), robots, sum(counts) / len(counts), sum(1 for c in counts if c) / len(counts)))
    fa, fo = start_features(argos, centre), start_features(ours, centre)
    print("  %-8s %10s %10s %10s %10s %7s %9s" % ("", "ARGoS mean", "sd", "ours mean", "sd", "KS D", "KS p"))
    for name in fa:
        (ma, sa), (mo, so) = mean_sd(fa[name]), mean_sd(fo[name])
        d, pv = ks_two_sample(fa[name], fo[name])
        print("  %-8s %10.4f %10.4f %10.4f %10.4f %7.3f %9.3g" % (name, ma, sa, mo, so, d, pv))
    print()


def make_ours(args, folder):
    paths = []
    for seed in range(1, args.seeds + 1):
        path = os.path.join(folder, "seed%d.csv" % seed)
        command = [args.swarmdesign, "evaluate", "--mission", args.mission, "--seed", str(seed), "--trace", path]
        if args.flavour:
            command += ["--legacy-flavour", args.flavour]
        subprocess.run(command + args.config.split(), check=True, stdout=subprocess.DEVNULL)
        paths.append(path)
    return paths


def shares(counter):
    total = sum(counter.values())
    return {k: v / total for k, v in counter.items()} if total else {}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--argos", required=True, help="glob of ARGoS trace files (.csv or .csv.gz)")
    p.add_argument("--ours", help="glob of SwarmDesign trace files")
    p.add_argument("--swarmdesign", help="the swarmdesign binary, to make our traces for --seeds")
    p.add_argument("--mission")
    p.add_argument("--config", help="the controller string")
    p.add_argument("--flavour", help="flavour of a one-digit legacy string: tuttifrutti, maple")
    p.add_argument("--seeds", type=int, default=100)
    p.add_argument("--keep", help="write our traces to this folder (to reuse with --ours)")
    p.add_argument("--target", required=True, help="'y>=0.465' or 'disc:0,0.6,0.3'")
    p.add_argument("--ticks", default="0:1200", help="first:last tick")
    p.add_argument("--window", type=int, default=1, help="ticks per printed row")
    p.add_argument("--min-share", type=float, default=0.01, help="hide values below this share on both sides")
    p.add_argument("--start", action="store_true", help="first compare the tick-0 poses (start distribution)")
    p.add_argument("--centre", default="0,0", help="x,y that --start measures radius and angle from")
    args = p.parse_args()
    first, last = (int(v) for v in args.ticks.split(":"))
    target = parse_target(args.target)
    argos_paths = sorted(p for p in glob.glob(args.argos) if "_objective" not in p)
    if not argos_paths:
        sys.exit("no ARGoS trace matches " + args.argos)
    with tempfile.TemporaryDirectory() as temporary:
        folder = args.keep or temporary
        if args.keep:
            os.makedirs(folder, exist_ok=True)
        if args.ours:
            our_paths = sorted(p for p in glob.glob(args.ours) if "_objective" not in p)
        elif args.swarmdesign and args.mission and args.config:
            our_paths = make_ours(args, folder)
        else:
            sys.exit("give --ours, or --swarmdesign, --mission and --config")
        argos, ours = Side(), Side()
        for path in argos_paths:
            argos.add_run(path, target, first, last, args.window)
        for path in our_paths:
            ours.add_run(path, target, first, last, args.window)
    if args.start:
        print_start(argos, ours, target, tuple(float(v) for v in args.centre.split(",")))
    print("ARGoS %d runs, SwarmDesign %d runs; target %s; ticks %d-%d by %d" %
          (argos.runs, ours.runs, args.target, first, last, args.window))
    print("%-11s %20s %20s %7s" % ("ticks", "in target ARGoS", "SwarmDesign", "t"))
    for w in sorted(argos.in_target):
        a, o = argos.in_target[w], ours.in_target.get(w, [])
        if not o:
            continue
        lo = first + w * args.window
        (ma, sa), (mo, so) = mean_sd(a), mean_sd(o)
        print("%-11s %11.3f ± %6.3f %11.3f ± %6.3f %7.2f" %
              ("%d-%d" % (lo, min(last, lo + args.window - 1)), ma, sa / math.sqrt(len(a)), mo,
               so / math.sqrt(len(o)), welch_t(a, o)))
    for c in COLUMNS:
        print("\n%s: share of robot-ticks, ARGoS | SwarmDesign" % c)
        for w in sorted(argos.tally[c]):
            sa, so = shares(argos.tally[c][w]), shares(ours.tally[c].get(w, collections.Counter()))
            keys = sorted(k for k in set(sa) | set(so) if max(sa.get(k, 0), so.get(k, 0)) >= args.min_share)
            lo = first + w * args.window
            cells = ["%s %.3f|%.3f" % (k, sa.get(k, 0.0), so.get(k, 0.0)) for k in keys]
            print("%-11s %s" % ("%d-%d" % (lo, min(last, lo + args.window - 1)), "  ".join(cells)))


if __name__ == "__main__":
    main()
