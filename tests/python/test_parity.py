"""Scores from Python are the CLI's to the bit: every catalogue mission, every flavour."""

import numpy as np
import pytest

import swarmdesign as sd
from conftest import RANDOM_WALK, cli_scores
from flavours import FLAVOUR_MISSION, FLAVOUR_SOFTWARE


def same_bits(a, b):
    return np.asarray(a, dtype=np.float64).tobytes() == np.asarray(b, dtype=np.float64).tobytes()


@pytest.mark.parametrize("mission", [m["name"] for m in sd.missions()])
def test_every_catalogue_mission(mission):
    scores = sd.evaluate(mission, RANDOM_WALK, seeds=2)
    assert scores.dtype == np.float64 and scores.shape == (1,)
    assert same_bits(scores, cli_scores(mission, RANDOM_WALK, 2))


@pytest.mark.parametrize("flavour", sorted(FLAVOUR_SOFTWARE))
def test_every_flavour(flavour):
    software = FLAVOUR_SOFTWARE[flavour]
    for mission in sorted({"aac", FLAVOUR_MISSION[flavour]}):
        assert same_bits(sd.evaluate(mission, software, "1-3"), cli_scores(mission, software, "1-3"))


def test_seed_forms_and_threads_give_the_same_bits():
    expected = cli_scores("aac", RANDOM_WALK, "7-30")
    aac = sd.Mission.builtin("aac")
    walk = sd.ControlSoftware.parse(RANDOM_WALK)
    assert same_bits(sd.evaluate(aac, walk, range(7, 31)), expected)
    assert same_bits(sd.evaluate(aac, walk, np.arange(7, 31, dtype=np.uint64), threads=1), expected)
    assert same_bits(sd.evaluate("aac", RANDOM_WALK, "7-30", threads=3), expected)
    assert same_bits(sd.evaluate(aac, walk, [30, 7]), [expected[-1], expected[0]])


def test_mission_files_and_large_seeds(tmp_path):
    source = tmp_path / "copy.json"
    source.write_text(sd.Mission.builtin("aac").text)
    seed = 10**19 - 1  # the largest seed --seed reads
    assert same_bits(sd.evaluate(sd.Mission.load(str(source)), RANDOM_WALK, seed), cli_scores(str(source), RANDOM_WALK, seed))


def test_progress_is_reported():
    seen = []
    sd.evaluate("aac", RANDOM_WALK, range(1, 41), threads=2, progress=lambda done, total: seen.append((done, total)))
    assert seen and seen[-1] == (40, 40)
    assert [d for d, _ in seen] == sorted(d for d, _ in seen)
