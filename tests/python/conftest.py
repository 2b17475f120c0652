"""Shared fixtures of the Python module's tests (tests/python, CTest label `python`).

CTest runs them with PYTHONPATH=build/python and SWARMDESIGN_BINARY set to the CLI built beside
the module; by hand: PYTHONPATH=build/python python3 -m pytest tests/python."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

# The CLI tests compare against, and a home of their own so nothing of the user's is read.
BINARY = Path(os.environ.get("SWARMDESIGN_BINARY", ROOT / "build" / "swarmdesign"))

RANDOM_WALK = "--fsm-config --nstates 1 --s0 10 --rwm0 50"


@pytest.fixture(autouse=True, scope="session")
def isolated_home(tmp_path_factory):
    home = tmp_path_factory.mktemp("home")
    previous = os.environ.get("SWARMDESIGN_HOME")
    os.environ["SWARMDESIGN_HOME"] = str(home)
    yield home
    if previous is None:
        os.environ.pop("SWARMDESIGN_HOME", None)
    else:
        os.environ["SWARMDESIGN_HOME"] = previous


def run_cli(*args, check=True, timeout=120):
    """The CLI's stdout (check) or the finished process."""
    if not BINARY.exists():
        pytest.skip(f"no swarmdesign binary at {BINARY}")
    process = subprocess.run([str(BINARY), *map(str, args)], capture_output=True, text=True, timeout=timeout)
    if check and process.returncode != 0:
        raise AssertionError(f"swarmdesign {' '.join(map(str, args))} failed: {process.stderr}")
    return process if not check else process.stdout


def cli_error(*args):
    """The one line the CLI prints after 'swarmdesign: error: ' for a refused command."""
    process = run_cli(*args, check=False)
    assert process.returncode != 0, process.stdout
    prefix = "swarmdesign: error: "
    lines = [line for line in process.stderr.splitlines() if line.startswith(prefix)]
    assert lines, process.stderr
    return lines[-1][len(prefix):], process.returncode


def cli_scores(mission, software, seeds):
    """Scores `evaluate --json` prints, parsed exactly (JSON doubles round-trip)."""
    seed_args = ["--seed", str(seeds)] if isinstance(seeds, int) else ["--seeds", seeds]
    document = json.loads(run_cli("evaluate", "--mission", mission, *seed_args, "--json", *software.split()))
    return [run["score"] for run in document["runs"]]


def python_env(**extra):
    """The environment for a child Python that imports this very module."""
    env = dict(os.environ)
    import swarmdesign

    env["PYTHONPATH"] = str(Path(swarmdesign.__file__).resolve().parents[1]) + os.pathsep + env.get("PYTHONPATH", "")
    env.update(extra)
    return env


PYTHON = sys.executable

# The smallest design the tests make (the least budget Iterated F-Race accepts for it).
DESIGN_ARGS = dict(mission="aac", budget=1008, architectures="fsm", flavours="chocolate", seed=3)


@pytest.fixture(scope="session")
def cli_design(tmp_path_factory):
    """A design made by the CLI: its folder and its --json report."""
    folder = tmp_path_factory.mktemp("cli-design") / "aac"
    report = json.loads(run_cli("design", "--mission", DESIGN_ARGS["mission"], "--budget", DESIGN_ARGS["budget"],
                                "--fsm", "--chocolate", "--seed", DESIGN_ARGS["seed"], "--out", folder, "--json",
                                timeout=300))
    return folder, report
