"""The engine of bench/calibration_wide.sh (see there): runs `swarmdesign evaluate` for every
controller of the ARGoS calibration set on seeds 1..N and prints the comparison. Standard
library only."""
import argparse
import csv
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

# The calibration test's groups (tests/evaluation/calibration_test.cpp): name, file, the
# file's mission, its architecture ("" for the first file, which has no such column), the
# catalogue mission, and a duration in seconds when ARGoS' run differs from the catalogue's.
GROUPS = [
    ("aac", "argos-reference.csv", "aac", "", "aac", None),
    ("foraging", "argos-reference.csv", "foraging", "", "foraging", None),
    ("sca", "argos-reference-2.csv", "sca", "fsm", "sca", None),
    ("lcn", "argos-reference-2.csv", "lcn", "fsm", "lcn", None),
    ("aggregation180", "argos-reference-2.csv", "aggregation180", "fsm", "aggregation", 180),
    ("aac_bt", "argos-reference-2.csv", "aac", "bt", "aac", None),
    ("foraging_bt", "argos-reference-2.csv", "foraging", "bt", "foraging", None),
    ("tutti_aggregation", "argos-reference-3.csv", "tutti-aggregation", "fsm", "tutti-aggregation", None),
    ("tutti_stop", "argos-reference-3.csv", "tutti-stop", "fsm", "tutti-stop", None),
    ("tutti_foraging", "argos-reference-3.csv", "tutti-foraging", "fsm", "tutti-foraging", None),
]


def fail(message):
    print(f"calibration_wide: error: {message}", file=sys.stderr)
    sys.exit(1)


def controllers(data, file, mission, architecture):
    """{name: (config, legacy flavour, ARGoS scores in seed order)} of one group."""
    found = {}
    with open(os.path.join(data, file), newline="") as f:
        for row in csv.DictReader(f):
            if row["mission"] != mission or row.get("architecture", "") != architecture:
                continue
            entry = found.setdefault(row["controller"], (row["config"], row.get("legacy_flavour") or "chocolate", []))
            entry[2].append((int(row["seed"]), float(row["argos_score"])))
    return {name: (cfg, flavour, [s for _, s in sorted(scores)]) for name, (cfg, flavour, scores) in found.items()}


def mission_with_duration(missions, name, seconds, folder):
    """A copy of the catalogue's mission file with another duration (ARGoS' 180-s aggregation)."""
    with open(os.path.join(missions, name + ".json")) as f:
        text = f.read()
    text, count = re.subn(r'"duration"\s*:\s*[0-9.]+', f'"duration": {seconds}', text)
    if count != 1:
        fail(f"cannot set the duration of missions/{name}.json")
    path = os.path.join(folder, f"{name}-{seconds}s.json")
    with open(path, "w") as f:
        f.write(text)
    return path


def evaluate(binary, mission, config, flavour, seeds, threads):
    command = [binary, "evaluate", "--mission", mission, "--seeds", f"1-{seeds}", "--threads", str(threads),
               "--json", "--legacy-flavour", flavour] + config.split()
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail(done.stderr.strip() or f"evaluate exited with {done.returncode}")
    return [run["score"] for run in json.loads(done.stdout)["runs"]]


def ranks(values):
    order = sorted(range(len(values)), key=lambda i: values[i])
    r = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            r[order[k]] = (i + j) / 2.0
        i = j + 1
    return r


def spearman(a, b):
    ra, rb = ranks(a), ranks(b)
    ma, mb = statistics.mean(ra), statistics.mean(rb)
    num = sum((x - ma) * (y - mb) for x, y in zip(ra, rb))
    den = math.sqrt(sum((x - ma) ** 2 for x in ra) * sum((y - mb) ** 2 for y in rb))
    return num / den if den > 0 else float("nan")


def compare(argos, ours):
    ma, sa = statistics.mean(argos), statistics.stdev(argos)
    mo, so = statistics.mean(ours), statistics.stdev(ours)
    se = math.sqrt(sa * sa / len(argos) + so * so / len(ours))
    return {
        "argos_mean": ma, "argos_sd": sa, "ours_mean": mo, "ours_sd": so,
        "ratio": mo / ma if ma != 0 else None,
        "deviation_sd": (mo - ma) / sa if sa > 0 else (0.0 if mo == ma else None),
        "welch_z": (mo - ma) / se if se > 0 else 0.0,
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--missions", required=True)
    parser.add_argument("--seeds", type=int, required=True)
    parser.add_argument("--threads", type=int, required=True)
    parser.add_argument("--json", default="")
    parser.add_argument("groups", nargs="*")
    args = parser.parse_args()
    known = [g[0] for g in GROUPS]
    for g in args.groups:
        if g not in known:
            fail(f"--group: unknown group '{g}' ({', '.join(known)})")
    report = {"seeds": args.seeds, "groups": []}
    with tempfile.TemporaryDirectory() as folder:
        for name, file, mission, architecture, catalogue, seconds in GROUPS:
            if args.groups and name not in args.groups:
                continue
            target = mission_with_duration(args.missions, catalogue, seconds, folder) if seconds else catalogue
            rows = []
            for controller, (config, flavour, argos) in sorted(controllers(args.data, file, mission, architecture).items()):
                ours = evaluate(args.binary, target, config, flavour, args.seeds, args.threads)
                row = {"controller": controller, **compare(argos, ours)}
                rows.append(row)
                ratio = "   -  " if row["ratio"] is None else f"{row['ratio']:6.2f}"
                dev = "   -  " if row["deviation_sd"] is None else f"{row['deviation_sd']:+6.2f}"
                print(f"{name:18s} {controller:4s} argos {row['argos_mean']:10.2f} (sd {row['argos_sd']:9.2f})  "
                      f"ours {row['ours_mean']:10.2f} (sd {row['ours_sd']:9.2f})  ratio {ratio}  dev {dev} sd  "
                      f"z {row['welch_z']:+6.2f}", flush=True)
            zs = [r["welch_z"] for r in rows]
            ratios = [r["ratio"] for r in rows if r["ratio"] is not None]
            summary = {
                "group": name, "controllers": len(rows),
                "spearman_rho": spearman([r["argos_mean"] for r in rows], [r["ours_mean"] for r in rows]),
                "median_ratio": statistics.median(ratios) if ratios else None,
                "max_abs_deviation_sd": max((abs(r["deviation_sd"]) for r in rows if r["deviation_sd"] is not None), default=0.0),
                "above": sum(1 for r in rows if r["ours_mean"] > r["argos_mean"]),
                "below": sum(1 for r in rows if r["ours_mean"] < r["argos_mean"]),
                "stouffer_z": sum(zs) / math.sqrt(len(zs)),
                "rows": rows,
            }
            summary["stouffer_p"] = math.erfc(abs(summary["stouffer_z"]) / math.sqrt(2.0))
            report["groups"].append(summary)
            median = "-" if summary["median_ratio"] is None else f"{summary['median_ratio']:.3f}"
            print(f"== {name}: {len(rows)} controllers, seeds 1-{args.seeds}: rho {summary['spearman_rho']:.3f}  "
                  f"median ratio {median}  max |dev| {summary['max_abs_deviation_sd']:.2f} sd  "
                  f"above {summary['above']} below {summary['below']}  "
                  f"Stouffer z {summary['stouffer_z']:+.2f} (p {summary['stouffer_p']:.4f})", flush=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(report, f, indent=1)


if __name__ == "__main__":
    main()
