"""A trace from Python holds the run `evaluate --trace` writes, tick for tick."""

import csv

import numpy as np
import pytest

import swarmdesign as sd
from conftest import RANDOM_WALK, cli_scores, run_cli
from flavours import FLAVOUR_SOFTWARE

LED_NAMES = {"off": 0x000000, "green": 0x00FF00, "blue": 0x0000FF, "red": 0xFF0000, "yellow": 0xFFFF00,
             "magenta": 0xFF00FF, "cyan": 0x00FFFF}


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.mark.parametrize("mission,software", [("aac", FLAVOUR_SOFTWARE["chocolate"]),
                                              ("tutti-foraging", FLAVOUR_SOFTWARE["tuttifrutti"]),
                                              ("foraging", FLAVOUR_SOFTWARE["maple"])])
def test_trace_matches_the_cli_trace(tmp_path, mission, software):
    path = tmp_path / "trace.csv"
    run_cli("evaluate", "--mission", mission, "--seed", "4", "--trace", path, *software.split())
    rows = read_csv(path)
    run = sd.trace(mission, software, seed=4)
    assert run.score == cli_scores(mission, software, 4)[0]
    ticks, robots = run.x.shape
    assert len(rows) == ticks * robots and run.ticks == ticks - 1
    frame = run.to_pandas()
    assert len(frame) == len(rows)
    for name in ("x", "y", "yaw", "v_left", "v_right"):
        cli = np.array([float(r[name]) for r in rows]).reshape(ticks, robots)
        np.testing.assert_allclose(getattr(run, name), cli, rtol=1e-8, atol=0)  # the CSV prints %.9g: 9 digits
    objective = np.array([float(r["objective"]) for r in rows]).reshape(ticks, robots)
    assert (objective == run.objective[:, None]).all()  # %.17g: exact
    state = np.array([int(r["state"]) if r["state"] else -1 for r in rows]).reshape(ticks, robots)
    assert (state == run.state).all()
    behaviour = np.array([int(r["behaviour"]) if r["behaviour"] else -1 for r in rows]).reshape(ticks, robots)
    assert (behaviour == np.where(run.module < 0, -1, run.module % 10)).all()
    led = np.array([LED_NAMES[r["led"]] if r["led"] in LED_NAMES else int(r["led"][1:], 16) for r in rows])
    assert (led.reshape(ticks, robots) == run.led).all()
    ground = np.array([float(r["ground"]) if r["ground"] else np.nan for r in rows]).reshape(ticks, robots)
    np.testing.assert_allclose(run.ground, ground, rtol=1e-8, equal_nan=True)
    assert run.objective[-1] == run.score


def test_trace_score_is_evaluate_score():
    run = sd.trace("aac", RANDOM_WALK, seed=9)
    assert run.score == sd.evaluate("aac", RANDOM_WALK, 9)[0]
    assert run.x.shape == (1201, 20) and run.state.dtype == np.int32 and run.led.dtype == np.uint32
