#!/usr/bin/env python3
"""Which knobs of the robot model move each mission's scores (issue #55: pseudo-realities that bite).

For each mission, a few designs are made in the design model (FSM, Chocolate; kept in --out and
reused); then each knob of the robot model alone is set to 0.5x, 2x and 4x its design value
(a knob whose design value is 0 is set to 0.5, 2 and 4 times a base value, listed below; values
are capped to the knob's domain), as a one-model pseudo-reality, and the designs are assessed
(sd.assess: the same seeds in the design model and in the changed model, paired by seed). The
figure per cell is the median relative drop over the designs (positive: worse), and how many
designs lose significantly (paired Wilcoxon p < 0.05).

    PYTHONPATH=build/python python3 bench/knob_sensitivity.py [--missions aac,foraging,aggregation,lcn]
        [--designs 3] [--budget 5000] [--seeds 1-20] [--threads 0] [--out knob-sensitivity]
        [--json FILE]

Prints one table per mission; --json writes every cell."""

import argparse
import json
import os
import statistics
import sys
from pathlib import Path

import swarmdesign as sd

# A knob at 0 in the design model is varied around this value instead.
BASE_WHEN_ZERO = {"rab_noise": 0.02, "camera_noise": 0.02, "wheel_deviation": 0.05, "proximity_deviation": 0.05,
                  "light_deviation": 0.05, "rab_range_deviation": 0.05}
FACTORS = (0.5, 2.0, 4.0)
CAPS = {"rab_loss": 1.0}  # a probability
DEVIATION_CAP = 0.95      # deviations are in [0, 1)


def design_model(mission):
    """The mission's robot model as pseudo_reality_samples reports it (every knob by name)."""
    return sd.pseudo_reality_samples("iridia-transfer", "1", mission=mission)["design_model"]


def varied(knob, design_value, factor):
    base = design_value if design_value > 0 else BASE_WHEN_ZERO.get(knob, 0.0)
    value = base * factor
    if knob in CAPS:
        value = min(value, CAPS[knob])
    if knob.endswith("_deviation"):
        value = min(value, DEVIATION_CAP)
    return value


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--missions", default="aac,foraging,aggregation,lcn")
    parser.add_argument("--designs", type=int, default=3)
    parser.add_argument("--budget", type=int, default=5000)
    parser.add_argument("--seeds", default="1-20")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--out", default="knob-sensitivity")
    parser.add_argument("--json")
    args = parser.parse_args()
    out = Path(args.out)
    (out / "specs").mkdir(parents=True, exist_ok=True)
    cells = []
    for mission in args.missions.split(","):
        software = {}
        for seed in range(1, args.designs + 1):
            result = sd.design(mission, args.budget, architectures="fsm", flavours="chocolate", seed=seed,
                               folder=out / f"{mission}-design-{seed}", threads=args.threads)
            software[f"design {seed}"] = result.best
        model = design_model(mission)
        print(f"\n{mission}: {args.designs} designs of {args.budget} runs, seeds {args.seeds}; median relative drop "
              f"over the designs (designs losing at p < 0.05)", flush=True)
        print(f"  {'knob':<22}{'design':>8}  " + "".join(f"{f'x{f:g}':>20}" for f in FACTORS))
        for knob, design_value in model.items():
            row = []
            for factor in FACTORS:
                value = varied(knob, design_value, factor)
                spec = out / "specs" / f"{knob}-{value:g}.json"
                spec.write_text(json.dumps({"name": f"{knob}-{value:g}", "description": f"{knob} at {value:g} alone",
                                            "source": "bench/knob_sensitivity.py", "knobs": {knob: value}}))
                a = sd.assess(mission, software, pseudo_reality=spec, samples="1", seeds=args.seeds,
                              threads=args.threads)
                drops = [s["relative_drop"] for s in a.document["software"] if s["relative_drop"] is not None]
                losing = sum(1 for s in a.document["software"] if s["drop"] > 0 and s["p_value"] < 0.05)
                median = statistics.median(drops) if drops else float("nan")
                cells.append({"mission": mission, "knob": knob, "design_value": design_value, "factor": factor,
                              "value": value, "median_relative_drop": median, "designs_losing": losing,
                              "designs": len(software)})
                row.append(f"{value:>7.3g}: {100 * median:+6.1f}% ({losing})")
            print(f"  {knob:<22}{design_value:>8.3g}  " + "".join(f"{c:>20}" for c in row), flush=True)
    if args.json:
        Path(args.json).write_text(json.dumps(cells, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
