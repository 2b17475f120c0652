"""The examples run (matplotlib's Agg backend, a tiny budget) and write their PNGs."""

import subprocess

from conftest import DESIGN_ARGS, PYTHON, ROOT, python_env


def run_example(name, *args):
    process = subprocess.run([PYTHON, str(ROOT / "examples" / name), *map(str, args)], capture_output=True, text=True,
                             timeout=120, env=python_env(MPLBACKEND="Agg"))
    assert process.returncode == 0, process.stderr
    return process.stdout


def is_png(path):
    return path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_trace_plot(tmp_path):
    out = tmp_path / "trace.png"
    assert "wrote" in run_example("trace_plot.py", "--seed", 2, "--out", out)
    assert is_png(out)


def test_design_convergence(cli_design, tmp_path):
    # On the folder of a design made with these settings: the script resumes it (finished, so
    # nothing runs again) and plots it; the script's own design path is test_design's.
    folder, _ = cli_design
    out = tmp_path / "convergence.png"
    stdout = run_example("design_convergence.py", "--mission", DESIGN_ARGS["mission"], "--budget", DESIGN_ARGS["budget"],
                         "--seed", DESIGN_ARGS["seed"], "--folder", folder, "--out", out)
    assert "best" in stdout and is_png(out)
