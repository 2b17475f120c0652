#!/usr/bin/env python3
"""One run traced tick by tick, plotted to a PNG: the robots' paths over the arena, coloured by
the FSM state they were in, and the objective over time.

    PYTHONPATH=build/python python3 examples/trace_plot.py --mission aac --seed 1 --out trace.png"""

import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import swarmdesign as sd  # noqa: E402

# Two states: explore, and stop once on the black floor (for a while).
DEFAULT = ("--fsm-config --nstates 2 --s0 10 --rwm0 50 --n0 1 --n0x0 0 --c0x0 10 --p0x0 0.9 "
           "--s1 11 --n1 1 --n1x0 0 --c1x0 15 --p1x0 0.01")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mission", default="aac")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--software", default=DEFAULT, help="a configuration string")
    parser.add_argument("--out", default="trace.png")
    args = parser.parse_args()

    run = sd.trace(args.mission, args.software, seed=args.seed)
    mission = run.mission
    print(f"{mission.name}, seed {run.seed}: score {run.score:g} ({run.ticks} ticks, {run.robots} robots)")

    fig, (arena, objective) = plt.subplots(1, 2, figsize=(11, 5))
    states = np.unique(run.state[1:])
    colours = plt.get_cmap("tab10")
    for robot in range(run.robots):
        arena.plot(run.x[:, robot], run.y[:, robot], color="0.8", linewidth=0.5, zorder=1)
    for i, state in enumerate(states):
        where = run.state[1:] == state
        arena.scatter(run.x[1:][where][::25], run.y[1:][where][::25], s=3, color=colours(i % 10), label=f"state {state}")
    arena.scatter(run.x[-1], run.y[-1], s=30, color="black", marker="o", label="end", zorder=3)
    arena.set_aspect("equal")
    arena.set_title("paths (grey) and states")
    arena.legend(loc="upper right", fontsize=8)
    seconds = np.arange(run.ticks + 1) * mission.duration_s / mission.ticks
    objective.plot(seconds, run.objective)
    objective.set_xlabel("time (s)")
    objective.set_ylabel("running objective")
    objective.set_title(f"{mission.title}: score {run.score:g}")
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
