"""Designs from Python are the CLI's designs; any design folder reads back."""

import json

import swarmdesign as sd
from conftest import DESIGN_ARGS, run_cli


def test_design_folder_made_by_the_cli_reads_back(cli_design):
    folder, report = cli_design
    design = sd.Design.open(folder)
    status = json.loads(run_cli("design-status", folder, "--json"))
    assert design.progress == status
    assert design.method == "automode"
    elites = design.elites
    assert list(elites["id"]) == [e["id"] for e in report["elites"]]
    assert list(elites["mean_score"]) == [e["mean_score"] for e in report["elites"]]
    assert design.best == sd.ControlSoftware.parse(report["best"]["configuration"])
    assert design.best_score == report["best"]["mean_score"]
    convergence = design.convergence
    assert len(convergence) == report["iterations"]
    assert list(convergence.columns) == ["iteration", "runs_used", "best_id", "best_score"]
    assert convergence["runs_used"].is_monotonic_increasing and convergence["runs_used"].iloc[-1] <= DESIGN_ARGS["budget"]
    log = design.race_log
    assert set(log["iteration"]) == set(range(1, report["iterations"] + 1))
    assert {"id", "mean_score", "survived"} <= set(log.columns)


def test_python_design_is_the_cli_design(cli_design, tmp_path):
    _, report = cli_design
    steps = []
    result = sd.design(**DESIGN_ARGS, folder=tmp_path / "py", threads=2, progress=steps.append)
    assert result.best == sd.ControlSoftware.parse(report["best"]["configuration"])
    assert result.score == report["best"]["mean_score"]
    assert [e["mean_score"] for e in result.report["elites"]] == [e["mean_score"] for e in report["elites"]]
    assert steps and steps[-1]["experiments_used"] <= DESIGN_ARGS["budget"]
    # Called again on its folder, it is the same finished design (nothing is run again).
    again = sd.design(**DESIGN_ARGS, folder=tmp_path / "py")
    assert again.best == result.best and again.score == result.score
    # Another design in that folder is refused.
    try:
        sd.design(**{**DESIGN_ARGS, "seed": 4}, folder=tmp_path / "py")
    except sd.DesignFolderError as error:
        assert "other settings" in str(error)
    else:
        raise AssertionError("a design with other settings was run in a taken folder")
