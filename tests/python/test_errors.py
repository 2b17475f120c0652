"""Bad input from Python ends in a Python exception, in the CLI's words, never in a crash or a hang."""

import math
import os
import threading

import pytest

import swarmdesign as sd
from conftest import RANDOM_WALK, cli_error


def test_exception_classes():
    assert issubclass(sd.MissionError, sd.InvalidRequestError)
    assert issubclass(sd.ConfigError, sd.InvalidRequestError)
    assert issubclass(sd.InvalidRequestError, sd.SwarmDesignError)
    assert issubclass(sd.InvalidRequestError, ValueError)
    assert issubclass(sd.DesignFolderError, sd.SwarmDesignError)


def test_unknown_mission_in_the_cli_words():
    words, status = cli_error("evaluate", "--mission", "no-such-mission", *RANDOM_WALK.split())
    assert status == 2
    with pytest.raises(sd.MissionError) as error:
        sd.Mission.builtin("no-such-mission")
    assert str(error.value) == words
    with pytest.raises(sd.MissionError):
        sd.evaluate("no-such-mission", RANDOM_WALK, 1)


def test_malformed_mission_file_in_the_cli_words(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"name": "bad", "robots": -3}')
    words, _ = cli_error("evaluate", "--mission", bad, *RANDOM_WALK.split())
    with pytest.raises(sd.MissionError) as error:
        sd.Mission.load(str(bad))
    assert str(error.value) == words


def test_missing_mission_file_in_the_cli_words(tmp_path):
    missing = tmp_path / "missing.json"
    words, _ = cli_error("evaluate", "--mission", missing, *RANDOM_WALK.split())
    with pytest.raises(sd.MissionError) as error:
        sd.Mission.load(str(missing))
    assert str(error.value) == words


def test_devices_and_fifos_are_refused_without_reading(tmp_path):
    with pytest.raises(sd.MissionError):
        sd.Mission.load("/dev/zero")
    fifo = tmp_path / "mission.json"
    os.mkfifo(fifo)
    # No writer ever opens the FIFO: a reader that blocked would hang the test (the timer
    # opens it for writing to unblock such a reader, so the test fails instead of hanging).
    rescue = threading.Timer(10, lambda: open(fifo, "w").close())
    rescue.start()
    try:
        with pytest.raises(sd.MissionError):
            sd.Mission.load(str(fifo))
    finally:
        rescue.cancel()


def test_malformed_configuration_in_the_cli_words():
    bad = "--fsm-config --nstates 1 --s0 10 --rwm0 500"
    words, status = cli_error("evaluate", "--mission", "aac", *bad.split())
    assert status == 2
    with pytest.raises(sd.ConfigError) as error:
        sd.ControlSoftware.parse(bad)
    assert str(error.value) == words
    with pytest.raises(sd.ConfigError):
        sd.ControlSoftware.parse("")
    with pytest.raises(sd.InvalidRequestError):
        sd.ControlSoftware.parse(RANDOM_WALK, legacy_flavour="vanilla")


def test_bad_seeds():
    words, _ = cli_error("evaluate", "--mission", "aac", "--seed", "-1", *RANDOM_WALK.split())
    with pytest.raises(sd.InvalidRequestError) as error:
        sd.evaluate("aac", RANDOM_WALK, -1)
    assert str(error.value) == words
    with pytest.raises(sd.InvalidRequestError):
        sd.evaluate("aac", RANDOM_WALK, [1, 10**19])
    with pytest.raises(sd.InvalidRequestError):
        sd.evaluate("aac", RANDOM_WALK, [])
    with pytest.raises(TypeError):
        sd.evaluate("aac", RANDOM_WALK, 1.5)
    with pytest.raises(TypeError):
        sd.evaluate("aac", RANDOM_WALK, [1, "2"])
    with pytest.raises(TypeError):
        sd.evaluate("aac", RANDOM_WALK, True)
    words, _ = cli_error("evaluate", "--mission", "aac", "--seeds", "5-1", *RANDOM_WALK.split())
    with pytest.raises(sd.InvalidRequestError) as error:
        sd.evaluate("aac", RANDOM_WALK, "5-1")
    assert str(error.value) == words


def test_huge_seed_lists_are_refused_at_once():
    with pytest.raises(sd.InvalidRequestError, match="at most 1,000,000 seeds"):
        sd.evaluate("aac", RANDOM_WALK, range(10**12))

    def endless():
        n = 0
        while True:
            yield n
            n += 1

    with pytest.raises(sd.InvalidRequestError, match="at most 1,000,000 seeds"):
        sd.evaluate("aac", RANDOM_WALK, endless())
    with pytest.raises(sd.InvalidRequestError):
        sd.evaluate("aac", RANDOM_WALK, "1-2000000")


def test_wrong_types():
    with pytest.raises(TypeError):
        sd.evaluate(42, RANDOM_WALK, 1)
    with pytest.raises(TypeError):
        sd.evaluate("aac", 42, 1)
    with pytest.raises(TypeError):
        sd.evaluate("aac", RANDOM_WALK, 1, threads="many")
    with pytest.raises(sd.InvalidRequestError):
        sd.evaluate("aac", RANDOM_WALK, 1, threads=-1)
    with pytest.raises(sd.InvalidRequestError, match="at most 1024"):
        sd.evaluate("aac", RANDOM_WALK, range(10**6), threads=10**6)
    with pytest.raises(sd.InvalidRequestError, match="at most 1024"):
        sd._core.evaluate(sd.Mission.builtin("aac"), sd.ControlSoftware.parse(RANDOM_WALK), [1], 10**6)
    with pytest.raises(sd.MissionError):
        sd.Mission.load("/tmp")  # a folder
    with pytest.raises(TypeError):
        sd.evaluate("aac", RANDOM_WALK, 1, progress=3)
    with pytest.raises(TypeError):
        sd.trace("aac", RANDOM_WALK, seed=None)


@pytest.mark.parametrize("budget", [math.nan, math.inf, -5, 0, 2000.5, "lots"])
def test_bad_budgets_in_the_cli_words(tmp_path, budget):
    with pytest.raises(sd.InvalidRequestError, match="expected a positive integer"):
        sd.design("aac", budget, architectures="fsm", flavours="chocolate", seed=1, folder=tmp_path / "d")
    assert not (tmp_path / "d").exists()


def test_bad_design_requests(tmp_path):
    with pytest.raises(TypeError):
        sd.design("aac", True, seed=1, folder=tmp_path / "d")
    with pytest.raises(sd.InvalidRequestError):
        sd.design("aac", 2000, flavours="vanilla", seed=1, folder=tmp_path / "d")
    with pytest.raises(sd.InvalidRequestError):
        sd.design("aac", 2000, architectures="mlp", seed=1, folder=tmp_path / "d")
    words, _ = cli_error("design", "--mission", "aac", "--budget", "10", "--fsm", "--chocolate", "--seed", "1",
                         "--out", tmp_path / "cli")
    with pytest.raises(sd.InvalidRequestError) as error:
        sd.design("aac", 10, architectures="fsm", flavours="chocolate", seed=1, folder=tmp_path / "d")
    assert str(error.value) == words
    with pytest.raises(sd.DesignFolderError):
        sd.Design.open(tmp_path)
    with pytest.raises(sd.DesignFolderError):
        sd.resume_design(tmp_path)
