#!/usr/bin/env python3
"""A short design with Iterated F-Race, then its convergence plotted to a PNG.

    PYTHONPATH=build/python python3 examples/design_convergence.py --budget 2000 --out convergence.png

The design keeps its folder (--folder): run the script again after Ctrl-C and it resumes."""

import argparse

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402

import swarmdesign as sd  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mission", default="aac")
    parser.add_argument("--budget", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--folder", default="design-convergence-example")
    parser.add_argument("--out", default="convergence.png")
    args = parser.parse_args()

    def progress(step):
        print(f"\r{step['experiments_used']}/{step['budget']} runs, iteration {step['iteration']}   ", end="", flush=True)

    result = sd.design(args.mission, args.budget, architectures="fsm", flavours="chocolate", seed=args.seed,
                       folder=args.folder, progress=progress)
    print(f"\nbest (mean {result.score:g} over its runs): {result.best}")

    convergence = sd.Design.open(result.folder).convergence  # a DataFrame: iteration, runs_used, best_score
    fresh = sd.evaluate(args.mission, result.best, range(10**6, 10**6 + 20))
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.step(convergence["runs_used"], convergence["best_score"], where="post", marker="o", label="best elite (design runs)")
    ax.axhline(fresh.mean(), color="tab:orange", linestyle="--", label=f"best on 20 fresh seeds ({fresh.mean():g})")
    ax.set_xlabel("simulation runs used")
    ax.set_ylabel(f"score ({sd.Mission.named(args.mission).direction})")
    ax.set_title(f"Iterated F-Race on {args.mission}, budget {args.budget}")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
