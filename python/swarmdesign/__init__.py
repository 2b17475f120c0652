"""SwarmDesign from Python: the same engine as the ``swarmdesign`` command, in-process.

Missions and control software::

    import swarmdesign as sd
    aac = sd.Mission.builtin("aac")
    walk = sd.ControlSoftware.parse("--fsm-config --nstates 1 --s0 10 --rwm0 50")

Scores (a NumPy array, the very bits ``swarmdesign evaluate`` prints), a run tick by tick, a
design by Iterated F-Race and any design folder read back::

    scores = sd.evaluate(aac, walk, seeds=range(1, 21))
    run = sd.trace(aac, walk, seed=1)            # run.x[tick, robot], run.objective[tick], ...
    result = sd.design("aac", budget=2000, architectures="fsm", flavours="chocolate", seed=1,
                       folder="aac-design")      # resumable: call it again after Ctrl-C
    sd.Design.open("aac-design").convergence     # a pandas DataFrame (list of dicts without pandas)
    sd.assess("aac", result.best, "iridia-transfer", samples="1-20").summary   # the reality gap

Long calls release the GIL (other Python threads run meanwhile) and stop on Ctrl-C with
KeyboardInterrupt (a design then resumes from its folder). Errors are SwarmDesignError
subclasses carrying the CLI's one-line messages.
"""

from __future__ import annotations

import itertools
import json
import math
import operator
import os
import stat
from typing import Any, Callable, Iterable, Optional, Sequence, Union

import numpy as np

from . import _core
from ._core import (
    AccessDeniedError,
    ConfigError,
    ConflictError,
    ControlSoftware,
    DesignFolderError,
    ExportError,
    InvalidRequestError,
    Mission,
    MissionError,
    NotFoundError,
    QuotaExceededError,
    SwarmDesignError,
)

__version__: str = _core.__version__

__all__ = [
    "AccessDeniedError", "Account", "Assessment", "assess", "ConfigError", "ConflictError", "ControlSoftware", "Design",
    "DesignFolderError", "DesignResult", "ExperimentReport", "ExportError", "FLAVOURS",
    "InvalidRequestError", "MAX_SEEDS", "MAX_SEED_BOUND", "MAX_THREADS", "Mission", "MissionError", "NotFoundError",
    "QuotaExceededError", "SwarmDesignError", "Trace", "design", "design_methods", "evaluate", "missions", "module_catalogue", "pseudo_realities",
    "pseudo_reality_samples",
    "resume_design", "trace",
]

#: The most seeds one evaluate() takes, as ``evaluate --seeds A-B`` does.
MAX_SEEDS = 1_000_000
#: The most worker threads one call may ask for.
MAX_THREADS = 1024
#: Seeds are below this bound, as ``--seed`` reads them (at most 19 decimal digits).
MAX_SEED_BOUND = 10**19
#: The five AutoMoDe flavours, as ``--legacy-flavour`` and the design flags name them.
FLAVOURS = ("chocolate", "tuttifrutti", "coconut", "maple", "arlequin")

MissionLike = Union[Mission, str, "os.PathLike[str]"]
SoftwareLike = Union[ControlSoftware, str]
SeedsLike = Union[int, str, Iterable[int]]


def _table(rows: list[dict[str, Any]], columns: Optional[Sequence[str]] = None) -> Any:
    """A pandas DataFrame when pandas is installed, else the list of dicts itself."""
    try:
        import pandas as pd
    except ImportError:
        return rows
    return pd.DataFrame(rows, columns=list(columns) if columns is not None else None)


# ---- missions and control software -----------------------------------------------------

def missions() -> list[dict[str, Any]]:
    """The mission catalogue, as ``swarmdesign missions --json`` lists it: one dict per mission
    (name, title, origin, robots, duration_s, direction, source)."""
    return _core.missions()


def design_methods() -> list[dict[str, Any]]:
    """The design methods, one dict each (name, title, summary, has_design_space); those with a
    design space are what design(method=...) and ``swarmdesign design --method`` take."""
    return _core.design_methods()


def module_catalogue() -> dict[str, Any]:
    """Every module of the five flavours: ids, names, flavours and parameter domains."""
    return _core.module_catalogue()


def _mission(mission: MissionLike) -> Mission:
    if isinstance(mission, Mission):
        return mission
    if isinstance(mission, (str, os.PathLike)):
        return Mission.named(os.fspath(mission))
    raise TypeError(f"mission: expected a swarmdesign.Mission, a catalogue name or a path, not {type(mission).__name__}")


def _mission_reference(mission: MissionLike) -> str:
    """What a design stores: a catalogue name, or a mission file's path."""
    if isinstance(mission, Mission):
        return mission.name if mission.source == "built-in" else mission.source
    if isinstance(mission, (str, os.PathLike)):
        return os.fspath(mission)
    raise TypeError(f"mission: expected a swarmdesign.Mission, a catalogue name or a path, not {type(mission).__name__}")


def _software(software: SoftwareLike) -> ControlSoftware:
    if isinstance(software, ControlSoftware):
        return software
    if isinstance(software, str):
        return ControlSoftware.parse(software)
    raise TypeError(f"software: expected a swarmdesign.ControlSoftware or a configuration string, not {type(software).__name__}")


def _integer(value: Any, what: str) -> int:
    if isinstance(value, bool):
        raise TypeError(f"{what}: expected an integer, not bool")
    try:
        return operator.index(value)
    except TypeError:
        raise TypeError(f"{what}: expected an integer, not {type(value).__name__}") from None


def _seed(value: Any) -> int:
    seed = _integer(value, "seed")
    if not 0 <= seed < MAX_SEED_BOUND:  # the CLI's one reading of a seed (app/inputs.hpp): 19 digits at most
        raise InvalidRequestError(f"seed '{seed}': expected a non-negative integer")
    return seed


def _seeds(seeds: SeedsLike) -> list[int]:
    if isinstance(seeds, str):
        return _core.parse_seed_range(seeds)
    if isinstance(seeds, (int, np.integer)) and not isinstance(seeds, bool):
        return [_seed(seeds)]
    try:
        count = len(seeds)  # type: ignore[arg-type]
    except TypeError:
        count = None
    if count is not None and count > MAX_SEEDS:
        raise InvalidRequestError(f"seeds: at most 1,000,000 seeds (got {count})")
    try:
        iterator = iter(seeds)  # type: ignore[arg-type]
    except TypeError:
        raise TypeError(f"seeds: expected an integer, 'A-B' or an iterable of integers, not {type(seeds).__name__}") from None
    out = [_seed(s) for s in itertools.islice(iterator, MAX_SEEDS + 1)]
    if len(out) > MAX_SEEDS:
        raise InvalidRequestError("seeds: at most 1,000,000 seeds")
    if not out:
        raise InvalidRequestError("seeds: expected at least one seed")
    return out


def _threads(threads: Any) -> int:
    value = _integer(threads, "threads")
    if value < 0:
        raise InvalidRequestError("threads: expected a non-negative integer (0: all cores)")
    if value > MAX_THREADS:  # each is a thread and a cached simulation: a typo must not exhaust the machine
        raise InvalidRequestError(f"threads: at most {MAX_THREADS}")
    return value


# The engine's worker pool is threads of this process: a child made by fork() has none of them,
# and a job there would wait for them for ever. Such a child is told so instead (use the
# "spawn" or "forkserver" start method of multiprocessing, or evaluate before any fork).
_fork = {"pool": 0, "orphaned": False}


def _before_fork() -> None:
    _fork["pool"] = _core.pool_threads()


def _after_fork_in_child() -> None:
    _fork["orphaned"] = _fork["orphaned"] or _fork["pool"] > 0


os.register_at_fork(before=_before_fork, after_in_child=_after_fork_in_child)


def _check_fork() -> None:
    if _fork["orphaned"]:
        raise SwarmDesignError("this process was forked after SwarmDesign's worker threads started, and a fork has none "
                               "of them: use multiprocessing's 'spawn' or 'forkserver' start method")


def _callback(progress: Any) -> Any:
    if progress is not None and not callable(progress):
        raise TypeError("progress: expected a callable or None")
    return progress


# ---- evaluations and traces ------------------------------------------------------------

def evaluate(mission: MissionLike, software: SoftwareLike, seeds: SeedsLike = 1, threads: int = 0,
             progress: Optional[Callable[[int, int], Any]] = None) -> np.ndarray:
    """Scores of ``software`` on ``mission``, one per seed in seed order: exactly the bits
    ``swarmdesign evaluate --mission M --seeds ... --json`` prints.

    seeds: an integer, a range or any iterable of integers in [0, 10**19), or the CLI's "A-B";
    at most 1,000,000. threads: workers (0: one per core); scores never depend on it.
    progress(done, total) is called from this thread as batches finish. The GIL is released
    while the runs go on; Ctrl-C raises KeyboardInterrupt within a batch."""
    _check_fork()
    return _core.evaluate(_mission(mission), _software(software), _seeds(seeds), _threads(threads), _callback(progress))


class Trace:
    """One run tick by tick, as ``evaluate --trace FILE`` writes it (its columns, its ticks):
    arrays of shape (ticks + 1, robots), row 0 being the placement.

    x, y (m), yaw (rad): the pose after the physics of the tick; v_left, v_right (m/s) and
    led (0xRRGGBB) are what was applied and shown during it (commanded at the tick before);
    state: the FSM state after the transition check, or the tree's action counted depth-first
    (-1: none); module: the two-digit id of the behaviour that ran (-1: none; the CSV's
    ``behaviour`` column is module % 10); ground: the floor its conditions read (NaN at tick 0);
    objective: the running objective per tick (shape ticks + 1); score: the run's score."""

    __slots__ = ("mission", "software", "seed", "score", "x", "y", "yaw", "v_left", "v_right",
                 "led", "state", "module", "ground", "objective")

    def __init__(self, mission: Mission, software: ControlSoftware, seed: int, data: dict[str, Any]):
        self.mission = mission
        self.software = software
        self.seed = seed
        self.score: float = data["score"]
        self.x: np.ndarray = data["x"]
        self.y: np.ndarray = data["y"]
        self.yaw: np.ndarray = data["yaw"]
        self.v_left: np.ndarray = data["v_left"]
        self.v_right: np.ndarray = data["v_right"]
        self.led: np.ndarray = data["led"]
        self.state: np.ndarray = data["state"]
        self.module: np.ndarray = data["module"]
        self.ground: np.ndarray = data["ground"]
        self.objective: np.ndarray = data["objective"]

    @property
    def ticks(self) -> int:
        """Ticks simulated (rows less the placement)."""
        return int(self.x.shape[0]) - 1

    @property
    def robots(self) -> int:
        return int(self.x.shape[1])

    def to_pandas(self) -> Any:
        """The trace in long format, one row per tick and robot (the CSV's rows): tick, robot,
        x, y, yaw, v_left, v_right, state, module, ground, led, objective. Needs pandas."""
        import pandas as pd
        ticks, robots = self.x.shape
        return pd.DataFrame({
            "tick": np.repeat(np.arange(ticks), robots),
            "robot": np.tile(np.arange(robots), ticks),
            "x": self.x.ravel(), "y": self.y.ravel(), "yaw": self.yaw.ravel(),
            "v_left": self.v_left.ravel(), "v_right": self.v_right.ravel(),
            "state": self.state.ravel(), "module": self.module.ravel(), "ground": self.ground.ravel(),
            "led": self.led.ravel(), "objective": np.repeat(self.objective, robots),
        })

    def __repr__(self) -> str:
        return f"<swarmdesign.Trace {self.mission.name} seed {self.seed}: {self.ticks} ticks, {self.robots} robots, score {self.score!r}>"


def trace(mission: MissionLike, software: SoftwareLike, seed: int = 1) -> Trace:
    """One run recorded tick by tick: the run, and the score, of ``evaluate --seed S --trace``."""
    m, s, seed = _mission(mission), _software(software), _seed(seed)
    return Trace(m, s, seed, _core.trace(m, s, seed))


# ---- designs ---------------------------------------------------------------------------

def _names(value: Union[None, str, Iterable[str]], what: str) -> list[str]:
    if value is None:
        return []
    if isinstance(value, str):
        return [v for v in value.replace(",", " ").split() if v]
    out = list(value)
    for v in out:
        if not isinstance(v, str):
            raise TypeError(f"{what}: expected names, not {type(v).__name__}")
    return out


def _budget(budget: Any) -> int:
    if isinstance(budget, bool):
        raise TypeError("budget: expected an integer, not bool")
    if isinstance(budget, (int, np.integer)):
        return _core.parse_budget(str(int(budget)))
    if isinstance(budget, (float, str)):  # "2000" as the CLI reads it; 2000.5, nan, inf refused in its words
        return _core.parse_budget(str(budget))
    raise TypeError(f"budget: expected an integer, not {type(budget).__name__}")


class DesignResult:
    """A finished design: ``best`` (ControlSoftware), ``score`` (its mean over every run it had,
    the mission's units), ``folder`` and the whole ``report`` (as ``design --json`` prints it)."""

    __slots__ = ("best", "score", "folder", "report")

    def __init__(self, report: dict[str, Any]):
        self.report = report
        elites = report.get("elites") or []
        self.best = ControlSoftware.parse(report["best"]["configuration"] if isinstance(report.get("best"), dict)
                                          else elites[0]["configuration"])
        self.score: float = elites[0]["mean_score"] if elites else math.nan
        self.folder: str = report.get("folder", "")

    def __repr__(self) -> str:
        return f"<swarmdesign.DesignResult score {self.score!r} in {self.folder}: {self.best}>"


def design(mission: MissionLike, budget: Union[int, str], *, architectures: Union[None, str, Iterable[str]] = None,
           flavours: Union[None, str, Iterable[str]] = None, seed: Optional[int] = None,
           folder: Union[None, str, "os.PathLike[str]"] = None, threads: int = 0,
           progress: Optional[Callable[[dict[str, Any]], Any]] = None,
           pseudo_reality: Union[None, str, "os.PathLike[str]"] = None,
           pseudo_reality_samples: Optional[str] = None, method: str = "automode") -> DesignResult:
    """Designs control software, as ``swarmdesign design`` does, in-process.

    method: the optimiser over the design space (design_methods(): "automode", Iterated F-Race;
    "random-search"; "local-search").

    architectures: "fsm", "bt" or both (None: all); flavours: any of FLAVOURS (None: all);
    seed: the design's seed (None: a random one, in the report); same seed, same result, on any
    number of threads. folder keeps the design (design.db after every race step; None:
    ./design-<mission>-seed<S>). A folder that already holds this design is resumed: after
    Ctrl-C (KeyboardInterrupt) or a kill, the same call ends exactly as an uninterrupted one.
    progress(dict) is called from this thread after race steps (iteration, runs used, best).
    pseudo_reality: a robust design, as ``run-design --pseudo-reality``: the race's instances
    are samples of this specification (a shipped name or a file), pseudo_reality_samples "A-B"
    (default 101-120, so that assess's default samples 1-20 stay unseen)."""
    _check_fork()
    seed_value = _core.random_seed() if seed is None else _seed(seed)
    report = _core.design(_mission_reference(mission), _budget(budget), _names(architectures, "architectures"),
                          _names(flavours, "flavours"), seed_value, "" if folder is None else os.fspath(folder),
                          _threads(threads), _callback(progress),
                          "" if pseudo_reality is None else os.fspath(pseudo_reality),
                          "" if pseudo_reality_samples is None else str(pseudo_reality_samples), str(method))
    return DesignResult(report)


def resume_design(folder: Union[str, "os.PathLike[str]"], threads: int = 0,
                  progress: Optional[Callable[[dict[str, Any]], Any]] = None) -> DesignResult:
    """Continues the design kept in ``folder`` with the settings it was started with, as
    ``design --resume DIR`` does (DesignFolderError, in its words, when it cannot)."""
    _check_fork()
    return DesignResult(_core.resume_design(os.fspath(folder), _threads(threads), _callback(progress)))


class Design:
    """A design folder read back (``Design.open(folder)``), made by ``design``, ``run-design``,
    an experiment or this module, finished or still running.

    progress: dict as ``design-status --json`` prints it; elites, race_log and convergence:
    DataFrames (lists of dicts without pandas); best / best_score: the best elite so far."""

    def __init__(self, data: dict[str, Any]):
        self._data = data
        self.folder: str = data["folder"]
        self.method: str = data["method"]
        self.progress: dict[str, Any] = data.get("progress") or data.get("document") or {}

    @classmethod
    def open(cls, folder: Union[str, "os.PathLike[str]"]) -> "Design":
        """Reads the design in ``folder``; DesignFolderError when it holds none."""
        return cls(_core.read_design(os.fspath(folder)))

    @property
    def convergence(self) -> Any:
        """One row per finished iteration: iteration, runs_used, best_id, best_score (the best
        elite's mean over every run it had so far, the mission's units)."""
        return _table(list(self._data.get("convergence", [])), ["iteration", "runs_used", "best_id", "best_score"])

    @property
    def elites(self) -> Any:
        """The current elites, best first: id, configuration, mean_score (over all its runs), runs."""
        return _table(list(self.progress.get("elites", [])), ["id", "configuration", "mean_score", "runs"])

    @property
    def race_log(self) -> Any:
        """Every race: one row per (iteration, configuration) with its mean and runs in that race,
        whether it was an elite before (elite), when it was dropped (eliminated_after: instances
        seen, None if never) and whether it ended among the iteration's elites (survived)."""
        rows = []
        for race in self._data.get("race_log", []):
            elites = race.get("elites") or []
            for member in race.get("configurations", []):
                rows.append({"iteration": race.get("iteration"), "race_budget": race.get("race_budget"),
                             "instances": len(race.get("instances", [])), "id": member.get("id"),
                             "configuration": member.get("configuration"), "mean_score": member.get("mean_score"),
                             "runs": member.get("runs"), "elite": member.get("elite"),
                             "eliminated_after": member.get("eliminated_after"), "survived": member.get("id") in elites})
        return _table(rows)

    @property
    def race_log_document(self) -> list[dict[str, Any]]:
        """The race log as ``status --json`` gives it."""
        return list(self._data.get("race_log", []))

    @property
    def best(self) -> Optional[ControlSoftware]:
        best = self.progress.get("best")
        if isinstance(best, dict) and best.get("configuration"):
            return ControlSoftware.parse(best["configuration"])
        text = self.progress.get("control_software") or self.progress.get("best_configuration")
        return ControlSoftware.parse(text) if isinstance(text, str) else None

    @property
    def best_score(self) -> Optional[float]:
        best = self.progress.get("best")
        return best.get("mean_score") if isinstance(best, dict) else None

    def __repr__(self) -> str:
        return f"<swarmdesign.Design {self.method} in {self.folder}>"


# ---- the reality gap -------------------------------------------------------------------

class Assessment:
    """An assessment across the reality gap (``swarmdesign assess --json``): each piece of
    control software on the same seeds in the design model and in pseudo-reality samples.

    document: the whole dict; summary: one row per software (design and pseudo-reality means,
    drop with its 95 % interval, relative drop, paired Wilcoxon p, ranks in each world);
    scores: one row per run (software, world, sample, seed, score), as ``assess --csv``."""

    def __init__(self, document: dict[str, Any]):
        self.document = document

    @property
    def summary(self) -> Any:
        rows = []
        for s in self.document.get("software", []):
            low, high = s.get("drop_ci95") or (None, None)
            rows.append({"label": s["label"], "design_mean": s["design_mean"], "pseudo_reality_mean": s["pseudo_reality_mean"],
                         "drop": s["drop"], "drop_low": low, "drop_high": high, "relative_drop": s["relative_drop"],
                         "p_value": s["p_value"], "design_rank": s["design_rank"],
                         "pseudo_reality_rank": s["pseudo_reality_rank"], "control_software": s["control_software"]})
        return _table(rows)

    @property
    def scores(self) -> Any:
        rows = [{"software": s["label"], "world": "design" if r["sample"] == 0 else "pseudo-reality",
                 "sample": r["sample"], "seed": r["seed"], "score": r["score"]}
                for s in self.document.get("software", []) for r in s.get("runs", [])]
        return _table(rows, ["software", "world", "sample", "seed", "score"])

    @property
    def rank_correlation(self) -> Optional[float]:
        return self.document.get("rank_correlation")

    def __repr__(self) -> str:
        d = self.document
        return (f"<swarmdesign.Assessment {d.get('mission')}: {len(d.get('software', []))} software, "
                f"{len(d.get('samples', []))} samples of {d.get('pseudo_reality', {}).get('reference')}>")


def _samples(samples: Union[int, str, Iterable[int]]) -> list[int]:
    if isinstance(samples, str):
        return _core.parse_sample_range(samples)
    if isinstance(samples, (int, np.integer)) and not isinstance(samples, bool):
        return _core.parse_sample_range(str(int(samples)))
    values = [_integer(k, "samples") for k in itertools.islice(iter(samples), 10_001)]
    if not values or len(values) > 10_000 or any(k < 1 or k >= MAX_SEED_BOUND for k in values):
        raise InvalidRequestError("samples: expected 1 to 10,000 sample numbers, each at least 1")
    return values


def _labelled(software: Any) -> list[tuple[str, ControlSoftware]]:
    if isinstance(software, (ControlSoftware, str)):
        return [("software", _software(software))]
    if isinstance(software, Design):
        best = software.best
        if best is None:
            raise InvalidRequestError(f"the design in {software.folder} has no result yet")
        return [(f"{software.folder} best", best)]
    if isinstance(software, dict):
        return [(str(label), _software(s)) for label, s in software.items()]
    out: list[tuple[str, ControlSoftware]] = []
    for i, s in enumerate(software):
        out.extend((f"software {i + 1}" if label == "software" else label, cs) for label, cs in _labelled(s))
    if not out:
        raise InvalidRequestError("nothing to assess: give control software")
    return out


def assess(mission: MissionLike, software: Any, pseudo_reality: str = "sampled-around",
           samples: Union[int, str, Iterable[int]] = "1-20", seeds: SeedsLike = "1-10", threads: int = 0,
           progress: Optional[Callable[[int, int], Any]] = None) -> Assessment:
    """Assesses control software across the reality gap, as ``swarmdesign assess`` does: in the
    design model and in pseudo-reality samples (Ligot & Birattari 2020), on the same seeds.

    software: a ControlSoftware or configuration string, a Design (its best), a list of them,
    or a dict label -> software. pseudo_reality: a shipped name (iridia-transfer,
    tuttifrutti-transfer, sampled-around) or a specification file. samples: "K", "A-B" or
    sample numbers (1 to 10,000 of them). Same errors, limits and Ctrl-C as evaluate()."""
    _check_fork()
    if not isinstance(pseudo_reality, (str, os.PathLike)):
        raise TypeError("pseudo_reality: expected a name or a path")
    document = _core.assess(_mission(mission), _labelled(software), os.fspath(pseudo_reality), _samples(samples),
                            _seeds(seeds), _threads(threads), _callback(progress))
    return Assessment(document)


def pseudo_realities() -> list[dict[str, Any]]:
    """The shipped pseudo-reality specifications (name, description, source, digest, the knobs
    each varies): ``swarmdesign pseudo-realities --json`` and the page's list."""
    return _core.pseudo_realities()


def pseudo_reality_samples(pseudo_reality: Union[str, "os.PathLike[str]"], samples: str = "1-5",
                           mission: Union[str, "os.PathLike[str]"] = "aac") -> dict[str, Any]:
    """A specification's samples as robot models (every knob by its file name) beside the
    design model of ``mission``'s robot: ``swarmdesign pseudo-realities NAME --json``."""
    return _core.pseudo_reality_samples(os.fspath(pseudo_reality), os.fspath(mission), str(samples))


# ---- experiments and accounts ----------------------------------------------------------

class ExperimentReport:
    """An experiment's report document (src/experiments/REPORT_FORMAT.md): the numbers and
    statistics ``swarmdesign report`` computes, as tables. ``document`` is the whole dict."""

    def __init__(self, document: dict[str, Any]):
        self.document = document

    @classmethod
    def open(cls, path: Union[str, "os.PathLike[str]"]) -> "ExperimentReport":
        """Reads a report.json (or the folder ``report --out DIR`` wrote), at most 64 MiB."""
        path = os.fspath(path)
        if os.path.isdir(path):
            path = os.path.join(path, "report.json")
        limit = 64 << 20
        # Opened without blocking and checked on what was opened: a FIFO or a device is refused.
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
        with os.fdopen(fd, "rb") as f:
            if not stat.S_ISREG(os.fstat(fd).st_mode):
                raise InvalidRequestError(f"report '{path}': not a regular file")
            text = f.read(limit + 1)
        if len(text) > limit:
            raise InvalidRequestError(f"report '{path}': larger than 64 MiB")
        return cls(json.loads(text))

    def _rows(self, key: str) -> Any:
        return _table(list(self.document.get(key) or []))

    @property
    def designs(self) -> Any:
        """One row per design: mission, condition, replicate, seed, budget, score, design_score, ..."""
        rows = [{k: v for k, v in d.items() if not isinstance(v, (dict, list))} for d in self.document.get("designs", [])]
        return _table(rows)

    @property
    def runs(self) -> Any:
        """One row per assessment run: design id, mission, condition, replicate, seed, score."""
        rows = []
        for d in self.document.get("designs", []):
            for seed, score in zip(d.get("assessment_seeds", []), d.get("scores", [])):
                rows.append({"design": d.get("id"), "mission": d.get("mission"), "condition": d.get("condition"),
                             "replicate": d.get("replicate"), "seed": seed, "score": score})
        return _table(rows, ["design", "mission", "condition", "replicate", "seed", "score"])

    @property
    def boxes(self) -> Any:
        return self._rows("boxes")

    @property
    def wilcoxon(self) -> Any:
        return self._rows("wilcoxon")

    @property
    def friedman(self) -> Optional[dict[str, Any]]:
        return self.document.get("friedman")

    @property
    def module_frequency(self) -> Any:
        return self._rows("module_frequency")

    @property
    def architectures(self) -> Any:
        return self._rows("architectures")


_EXPERIMENT_CHOICES = ("missions", "designs", "assessment_seeds", "budget_scale", "seed", "name", "evostick",
                       "pseudo_reality", "pseudo_reality_samples")


def _experiment_request(protocol: Optional[str], file: Any, text: Optional[str], choices: dict[str, Any]) -> str:
    """The request as the web's JSON body (app::protocol_request_from_json reads both)."""
    unknown = sorted(set(choices) - set(_EXPERIMENT_CHOICES))
    if unknown:
        raise TypeError(f"unknown experiment choice {unknown[0]!r} (choices: {', '.join(_EXPERIMENT_CHOICES)})")
    body: dict[str, Any] = {k: v for k, v in choices.items() if v is not None}
    if "missions" in body:
        body["missions"] = _names(body["missions"], "missions")
    if body.get("pseudo_reality") is not None:
        body["pseudo_reality"] = os.fspath(body["pseudo_reality"])
    if protocol is not None:
        body["protocol"] = protocol
    if file is not None:
        body["file"] = os.fspath(file)
    if text is not None:
        body["text"] = text
    return json.dumps(body)


class Account:
    """A SwarmDesign home as the signed-in user sees it (``swarmdesign sign-in`` made the
    session): projects, their designs and experiments, reports, through the store every CLI
    command opens. Reads start nothing; test_design, compare_designs and collect run
    simulations (collect also reaches the cluster); plan_experiment, run_experiment and
    stop_experiment drive experiments through the backend the CLI and the page use.
    home: the SwarmDesign home (None: $SWARMDESIGN_HOME or the
    default)."""

    def __init__(self, home: Union[None, str, "os.PathLike[str]"] = None):
        self.home: Optional[str] = None if home is None else os.fspath(home)

    def projects(self) -> Any:
        return _core.account_projects(self.home)

    def quota(self) -> Any:
        """What the account uses of the quotas an administrator set (``quota --json``): disk
        bytes and the runs of work started today (UTC), each with its limit (None: no limit)."""
        return _core.account_quota(self.home)

    def new_project(self, name: str, mission: MissionLike, budget: Union[int, str]) -> Any:
        """Makes a project with its mission (a catalogue name or a mission file) and budget, and
        makes it the active one, as ``new-project``, ``set-mission`` and ``set-budget`` do; every
        value is checked before anything is written. The project's document."""
        return _core.account_new_project(self.home, str(name), _mission_reference(mission), str(budget))

    def configure_project(self, name: str, *, mission: Optional[MissionLike] = None,
                          budget: Union[None, int, str] = None) -> Any:
        """Sets a project's mission and/or budget (``set-mission``, ``set-budget``); the project
        becomes the active one, as the page's budget field makes it. The project's document."""
        return _core.account_configure_project(self.home, str(name),
                                               None if mission is None else _mission_reference(mission),
                                               None if budget is None else str(budget))

    def delete_project(self, name: str, confirm: str) -> None:
        """Deletes a project with its designs, experiments and files, as ``delete-project``
        does: ``confirm`` must repeat the name (InvalidRequestError otherwise); ConflictError
        while one of its designs or experiments runs."""
        _core.account_delete_project(self.home, str(name), str(confirm))

    def designs(self, project: Optional[str] = None) -> Any:
        """The project's designs (the active project when None), one row each."""
        return _table(_core.account_designs(self.home, project))

    def design(self, design_id: int, project: Optional[str] = None) -> Design:
        """A design of the project opened from its folder."""
        for row in _core.account_designs(self.home, project):
            if row.get("id") == design_id:
                return Design.open(row["folder"])
        raise NotFoundError(f"design {design_id}: no such design in the project")

    def experiments(self, project: Optional[str] = None) -> Any:
        """The project's experiments and how far each is: a read, it starts nothing (a cluster
        experiment shows what :meth:`collect` last brought home)."""
        return _core.account_experiments(self.home, project)

    def collect(self, project: Optional[str] = None, threads: int = 0) -> Any:
        """Brings a cluster project's finished experiment designs home and assesses them, as
        ``swarmdesign collect --json`` does: what came home, and the experiments' progress."""
        return _core.account_collect(self.home, project, threads)

    def test_design(self, design: Optional[int] = None, software: Optional[SoftwareLike] = None,
                    seeds: str = "1-10", project: Optional[str] = None, threads: int = 0) -> Any:
        """A design's best on its own mission (design None: the project's last design with a
        best), or ``software`` on the project's mission, on fresh seeds: the document
        ``swarmdesign test-design --json`` prints and the web's Test answers."""
        if design is not None and software is not None:
            raise InvalidRequestError("give design or software to test, not both")
        return _core.account_test_design(self.home, project, None if design is None else _integer(design, "design"),
                                         None if software is None else _software(software), seeds, threads)

    def compare_designs(self, a: int, b: int, seeds: str = "1-20", project: Optional[str] = None,
                        threads: int = 0) -> Any:
        """Two designs' bests on the same seeds with the Wilcoxon signed-rank test paired by
        seed: ``swarmdesign compare-designs A B --json``'s document (the web's Compare)."""
        return _core.account_compare_designs(self.home, project, _integer(a, "a"), _integer(b, "b"), seeds, threads)

    def argos_files(self, design: Optional[int] = None, pseudo_reality: Optional[str] = None,
                    sample: Optional[int] = None, project: Optional[str] = None) -> Any:
        """A design's mission as an ARGoS experiment file (``experiment``: its text) and the
        line that runs its best: ``swarmdesign export-argos --json``'s document. With
        pseudo_reality and sample, the mission in that pseudo-reality sample."""
        return _core.account_argos_files(self.home, project, None if design is None else _integer(design, "design"),
                                         "" if pseudo_reality is None else os.fspath(pseudo_reality),
                                         "" if sample is None else str(_integer(sample, "sample")))

    def assess(self, designs: Union[int, Iterable[int]] = (), saved: Union[str, Iterable[str]] = (),
               pseudo_reality: Union[str, "os.PathLike[str]"] = "sampled-around",
               samples: Union[int, str, Iterable[int]] = "1-20", seeds: SeedsLike = "1-10", elites: bool = False,
               mission: Optional[MissionLike] = None, project: Optional[str] = None, threads: int = 0,
               progress: Optional[Callable[[int, int], Any]] = None) -> Assessment:
        """The project's designs (their bests; every final elite with ``elites``) and saved
        software across the reality gap, as ``swarmdesign assess --project-design N --saved
        NAME --json`` does, in the project's mission unless ``mission`` is given."""
        _check_fork()
        numbers = [designs] if isinstance(designs, int) else list(designs)
        names = [saved] if isinstance(saved, str) else list(saved)
        document = _core.account_assess(self.home, project, [_integer(d, "designs") for d in numbers], names, bool(elites),
                                        "" if mission is None else _mission_reference(mission),
                                        os.fspath(pseudo_reality), _samples(samples), _seeds(seeds), _threads(threads),
                                        _callback(progress))
        return Assessment(document)

    def plan_experiment(self, protocol: Optional[str] = None, *, file: Union[None, str, "os.PathLike[str]"] = None,
                        text: Optional[str] = None, estimate: bool = False, threads: int = 0,
                        **choices: Any) -> Any:
        """An experiment's plan, nothing started: ``swarmdesign experiment --dry-run --json``'s
        document and the page's Plan. ``protocol`` names a built-in one (validation,
        combination, architecture, methods), or give ``file`` (a protocol file) or ``text`` (its JSON).
        ``choices`` are the CLI's flags and the page's fields: missions, designs,
        assessment_seeds, budget_scale, seed, name, evostick, pseudo_reality,
        pseudo_reality_samples. With estimate=True, also how long it would take here with
        ``threads`` (0: all cores), its speed measured now."""
        request = _experiment_request(protocol, file, text, choices)
        return _core.account_plan_experiment(request, _threads(threads) if estimate else None)

    def run_experiment(self, protocol: Optional[str] = None, *, file: Union[None, str, "os.PathLike[str]"] = None,
                       text: Optional[str] = None, project: Optional[str] = None, threads: int = 0,
                       progress: Optional[Callable[[dict[str, Any]], Any]] = None, **choices: Any) -> Any:
        """Starts an experiment in the project (the active one when None) where its experiments
        run, as ``swarmdesign experiment`` does: here, to its end (``progress`` is called with
        the design being made), or for a cluster project as a Slurm job array (it returns once
        submitted; :meth:`collect` brings the designs home). The same request again resumes an
        interrupted one: Ctrl-C stops it between race steps. Returns the page's Start answer:
        the experiment's row, resumed, already_finished, notes and where ("process" or
        "slurm")."""
        request = _experiment_request(protocol, file, text, choices)
        return _core.account_run_experiment(self.home, project, request, _threads(threads), _callback(progress))

    def stop_experiment(self, experiment: str, project: Optional[str] = None) -> Any:
        """Stops a running experiment through whoever runs it (a CLI process of this machine,
        a web server's thread, or scancel for a Slurm array); it resumes with
        :meth:`run_experiment`."""
        return _core.account_stop_experiment(self.home, project, experiment)

    def experiment_report(self, experiment: str, project: Optional[str] = None) -> ExperimentReport:
        """The experiment's report as ``swarmdesign report --json`` computes it."""
        return ExperimentReport(_core.experiment_report(experiment, self.home, project))
