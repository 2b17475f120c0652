"""One core, three thin front ends (issue #54): Python's Account answers test_design,
compare_designs, argos_files and collect with the very documents the CLI's --json prints (the
web's API gives them too: tests/workflow/front_ends_test.cpp), because all three call the same
application service."""

import json
import os
import re
import subprocess
from pathlib import Path

import pytest

import swarmdesign as sd
from conftest import BINARY, run_cli


def cli_with_input(*args, text):
    process = subprocess.run([str(BINARY), *map(str, args)], input=text, capture_output=True, text=True, timeout=120)
    assert process.returncode == 0, process.stderr
    return process.stdout


@pytest.fixture(scope="module")
def account(isolated_home):
    """A signed-in user whose project holds two finished designs of a 2-second mission."""
    if not BINARY.exists():
        pytest.skip(f"no swarmdesign binary at {BINARY}")
    cli_with_input("sign-up", "py-front", "--password-stdin", text="py-front-secret\n")
    cli_with_input("sign-in", "py-front", "--password-stdin", text="py-front-secret\n")
    run_cli("new-project", "fe")
    run_cli("select-project", "fe")
    folder = isolated_home / "users" / "py-front" / "projects" / "fe"
    mission = folder / "aac-short.json"
    mission.write_text(re.sub(r'"duration": *[0-9.]+', '"duration": 2', sd.Mission.builtin("aac").text))
    run_cli("set-mission", mission)
    run_cli("set-budget", "1100")
    for seed in (1, 2):
        run_cli("run-design", "--fsm", "--chocolate", "--seed", seed, "--threads", "2")
    return sd.Account()


def test_testing_a_design_is_the_clis_document(account):
    assert account.test_design(1, seeds="3-6") == json.loads(run_cli("test-design", "--design", 1, "--seeds", "3-6", "--json"))
    given = "--fsm-config --nstates 1 --s0 10 --rwm0 50"
    assert account.test_design(software=given, seeds="1-2") == json.loads(
        run_cli("test-design", "--seeds", "1-2", "--json", *given.split()))
    with pytest.raises(sd.InvalidRequestError):
        account.test_design(1, software=given)


def test_comparing_two_designs_is_the_clis_document(account):
    document = account.compare_designs(1, 2, seeds="1-8")
    assert document == json.loads(run_cli("compare-designs", 1, 2, "--seeds", "1-8", "--json"))
    assert [side["design"] for side in document["designs"]] == [1, 2]
    with pytest.raises(sd.NotFoundError):
        account.compare_designs(1, 9)


def test_a_design_for_argos_is_the_clis_document(account, tmp_path):
    document = account.argos_files(2, pseudo_reality="sampled-around", sample=3)
    assert document == json.loads(run_cli("export-argos", "--design", 2, "--pseudo-reality", "sampled-around",
                                          "--sample", 3, "--out", tmp_path / "x.argos", "--json"))
    assert document["pseudo_reality"] == {"reference": "sampled-around", "sample": "3"}


def test_collecting_a_local_project_brings_nothing_and_lists_its_experiments(account):
    document = account.collect()
    assert document == json.loads(run_cli("collect", "--json"))
    assert document["experiments"] == 0 and document["designs_home"] == 0
    assert document["progress"] == account.experiments()


RANDOM_WALK = "--fsm-config --nstates 1 --s0 10 --rwm0 50"


def test_one_run_in_a_pseudo_reality_sample_is_the_clis(account):
    mission = sd.Mission.builtin("aac").in_pseudo_reality("sampled-around", 3)
    cli = json.loads(run_cli("evaluate", "--mission", "aac", "--pseudo-reality", "sampled-around", "--sample", 3,
                             "--seeds", "1-2", "--json", *RANDOM_WALK.split()))
    assert list(sd.evaluate(mission, RANDOM_WALK, "1-2")) == [run["score"] for run in cli["runs"]]
    assert cli["robot"] != json.loads(run_cli("evaluate", "--mission", "aac", "--json", *RANDOM_WALK.split()))["robot"]
    with pytest.raises(sd.InvalidRequestError):
        sd.Mission.builtin("aac").in_pseudo_reality("no-such-world", 1)


def test_a_robust_design_is_the_clis(account, tmp_path):
    mission = next((account_folder(account) / "fe").glob("aac-short.json"))
    here = sd.design(mission, 1100, architectures="fsm", flavours="chocolate", seed=4, folder=tmp_path / "py",
                     pseudo_reality="sampled-around", pseudo_reality_samples="101-103")
    cli = json.loads(run_cli("design", "--mission", mission, "--budget", 1100, "--fsm", "--chocolate", "--seed", 4,
                             "--pseudo-reality", "sampled-around", "--pseudo-reality-samples", "101-103",
                             "--out", tmp_path / "cli", "--json"))
    assert here.report["best"] == cli["best"]
    assert here.report["pseudo_reality"] == cli["pseudo_reality"]
    # Asked again, the folder's design is the one asked for: its result, not a second run.
    again = sd.design(mission, 1100, architectures="fsm", flavours="chocolate", seed=4, folder=tmp_path / "py",
                      pseudo_reality="sampled-around", pseudo_reality_samples="101-103")
    assert again.report["best"] == here.report["best"]
    with pytest.raises(sd.DesignFolderError, match="other settings"):
        sd.design(mission, 1100, architectures="fsm", flavours="chocolate", seed=4, folder=tmp_path / "py")


def test_a_design_by_another_method_is_the_clis(account, tmp_path):
    searches = [m["name"] for m in sd.design_methods() if m["has_design_space"]]
    assert searches == ["automode", "random-search", "local-search"]
    mission = next((account_folder(account) / "fe").glob("aac-short.json"))
    here = sd.design(mission, 1100, architectures="fsm", flavours="chocolate", seed=4, folder=tmp_path / "py",
                     method="local-search")
    cli = json.loads(run_cli("design", "--mission", mission, "--budget", 1100, "--fsm", "--chocolate", "--seed", 4,
                             "--method", "local-search", "--out", tmp_path / "cli", "--json"))
    assert here.report["best"] == cli["best"]
    assert here.report["method"] == cli["method"] == "local-search"
    assert sd.Design.open(tmp_path / "py").method == "local-search"
    with pytest.raises(sd.InvalidRequestError, match="unknown design method 'evostick'"):
        sd.design(mission, 1100, architectures="fsm", flavours="chocolate", seed=4, folder=tmp_path / "evo",
                  method="evostick")


def test_projects_are_made_configured_and_deleted_as_the_cli_does(account):
    try:
        made = account.new_project("py-made", "aac", 1500)
        assert made["name"] == "py-made" and made["mission"] == "aac" and made["budget"] == 1500
        listed = {p["name"]: p for p in json.loads(run_cli("show-projects", "--json"))["projects"]}
        # The listing's entry is the project's document, plus what only a listing knows: which
        # other projects use its mission files.
        assert {key: listed["py-made"][key] for key in made} == made
        assert listed["py-made"]["mission_used_by"] == []
        # Refused before anything is written: a bad budget, a taken name, a mission that is not one.
        with pytest.raises(sd.InvalidRequestError, match="budget"):
            account.new_project("py-bad", "aac", "lots")
        with pytest.raises(sd.ConflictError):
            account.new_project("py-made", "aac", 1500)
        with pytest.raises(sd.SwarmDesignError, match="no-such-mission"):
            account.configure_project("py-made", mission="no-such-mission")
        assert "py-bad" not in {p["name"] for p in account.projects()["projects"]}
        changed = account.configure_project("py-made", budget=3000)
        assert changed["budget"] == 3000 and changed["mission"] == "aac"
        with pytest.raises(sd.InvalidRequestError):
            account.delete_project("py-made", "py-mad")
        account.delete_project("py-made", "py-made")
        assert "py-made" not in {p["name"] for p in json.loads(run_cli("show-projects", "--json"))["projects"]}
    finally:
        run_cli("select-project", "fe")  # the module's other tests use the active project


def account_folder(account):
    return Path(os.environ["SWARMDESIGN_HOME"]) / "users" / "py-front" / "projects"


def mini_protocol(account, name):
    mission = next((account_folder(account) / "fe").glob("aac-short.json"))
    return json.dumps({"name": name, "designs": 2, "assessment_seeds": 3, "missions": [
        {"mission": str(mission), "budget": 1008,
         "conditions": [{"name": "alone", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})


def test_the_quota_is_the_clis_document_with_the_designs_runs_reserved(account):
    quota = account.quota()
    assert quota == json.loads(run_cli("quota", "--json"))
    assert quota["runs_today"] >= 2 * 1100, "the fixture's two designs reserved their budgets"
    assert quota["disk_bytes"] > 0 and quota["disk_from_default"] and quota["runs_from_default"]
    # Past it, work is refused with the quota named, as the page's 409 names it ("quota": "runs").
    run_cli("admin", "quota", "py-front", "--runs-per-day", quota["runs_today"])  # the first account: its administrator
    try:
        with pytest.raises(sd.QuotaExceededError, match="^runs quota: this experiment needs") as refused:
            account.run_experiment(text=mini_protocol(account, "py-over-quota"))
        assert refused.value.quota == "runs" and isinstance(refused.value, sd.ConflictError)
        assert account.quota()["runs_today"] == quota["runs_today"], "a refused start counts nothing"
    finally:
        run_cli("admin", "quota", "py-front", "--runs-per-day", "default")


def test_an_experiments_plan_is_the_clis_document(account, tmp_path):
    planned = account.plan_experiment("validation", missions=["aac"], designs=3, seed=5, budget_scale=0.01)
    cli = json.loads(run_cli("experiment", "validation", "--missions", "aac", "--designs", 3, "--seed", 5,
                             "--budget-scale", 0.01, "--dry-run", "--json", "--threads", 1))
    assert "estimate" not in planned
    cli_estimate = cli.pop("estimate")  # measured now: the rest is the same bit for bit
    assert planned == cli
    assert len(planned["designs"]) == 3 * len({d["condition"] for d in planned["designs"]})
    estimated = account.plan_experiment("validation", missions=["aac"], designs=3, seed=5, budget_scale=0.01,
                                        estimate=True, threads=1)
    assert estimated.pop("estimate")["missions"][0]["runs"] == cli_estimate["missions"][0]["runs"]
    assert estimated == planned
    own = tmp_path / "mini.json"
    own.write_text(mini_protocol(account, "from-file"))
    assert account.plan_experiment(file=own) == account.plan_experiment(text=own.read_text())
    with pytest.raises(sd.InvalidRequestError, match="not both"):
        account.plan_experiment("validation", text=own.read_text())
    # A protocol's own error, said once (the page showed "protocol: protocol: ...").
    with pytest.raises(sd.InvalidRequestError) as refused:
        account.plan_experiment(text='{"name": 3}')
    assert str(refused.value) == "protocol: name: must be a non-empty string"
    with pytest.raises(sd.InvalidRequestError, match="designs must be a whole number"):
        account.plan_experiment("validation", designs="many")
    with pytest.raises(TypeError, match="unknown experiment choice 'budget'"):
        account.plan_experiment("validation", budget=10)


def test_an_experiment_runs_from_python_reports_as_the_clis_and_resumes(account, tmp_path):
    steps = []
    started = account.run_experiment(text=mini_protocol(account, "py-mini"), threads=2, progress=steps.append)
    assert started["where"] == "process" and not started["resumed"] and not started["already_finished"]
    assert started["experiment"]["state"] == "finished" and started["experiment"]["designs_done"] == 2
    assert steps and steps[-1]["mission"] == "aac-short" and steps[-1]["condition"] == "alone"
    # The same request again: it had finished, so it is answered, not run twice.
    again = account.run_experiment(text=mini_protocol(account, "py-mini"))
    assert again["already_finished"] and again["experiment"] == started["experiment"]
    report = account.experiment_report("py-mini")
    # (its files into the test's own folder, never the working directory)
    assert report.document == json.loads(run_cli("report", "py-mini", "--json", "--out", tmp_path / "report"))
    # Nothing runs it now: stopping says so, as the page's Stop does.
    with pytest.raises(sd.ConflictError):
        account.stop_experiment("py-mini")
    with pytest.raises(sd.NotFoundError):
        account.stop_experiment("no-such-experiment")


def test_the_pseudo_realities_are_the_clis_documents(account):
    listed = sd.pseudo_realities()
    assert listed == json.loads(run_cli("pseudo-realities", "--json"))
    assert {"iridia-transfer", "tuttifrutti-transfer", "sampled-around"} <= {row["name"] for row in listed}
    varies = {row["name"]: row["varies"] for row in listed if row["digest"]}
    assert varies["sampled-around"] and not varies["iridia-transfer"]  # one fixed model, every sample alike
    samples = sd.pseudo_reality_samples("sampled-around", "2-3", mission="foraging")
    assert samples == json.loads(run_cli("pseudo-realities", "sampled-around", "--samples", "2-3", "--mission", "foraging", "--json"))
    assert [s["sample"] for s in samples["samples"]] == [2, 3]
    with pytest.raises(sd.InvalidRequestError):
        sd.pseudo_reality_samples("sampled-around", "3-1")


def test_assessing_a_projects_designs_is_the_clis_document(account):
    here = account.assess(designs=[1, 2], pseudo_reality="sampled-around", samples="1-2", seeds="1-3", threads=2)
    cli = json.loads(run_cli("assess", "--project-design", 1, "--project-design", 2, "--pseudo-reality", "sampled-around",
                             "--samples", "1-2", "--seeds", "1-3", "--json", "--threads", 2))
    for document in (here.document, cli):
        document.pop("seconds")  # each one's own wall time
    assert here.document == cli
    assert [s["label"] for s in cli["software"]] == ["design 1 best", "design 2 best"]
    with pytest.raises(sd.NotFoundError):
        account.assess(designs=9)
    with pytest.raises(sd.InvalidRequestError, match="nothing to assess"):
        account.assess()
