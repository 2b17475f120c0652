"""Long calls release the GIL (two threads evaluate at once) and stop on Ctrl-C."""

import subprocess
import textwrap
import threading
import time

import swarmdesign as sd
from conftest import DESIGN_ARGS, PYTHON, RANDOM_WALK, python_env

# A child Python that starts a long call, sends itself SIGINT from a timer thread, and prints
# how long the call took to end, and how.
INTERRUPTED = textwrap.dedent("""
    import os, signal, sys, threading, time
    import swarmdesign as sd
    threading.Timer(DELAY, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    start = time.monotonic()
    try:
        CALL
        print("finished")
    except KeyboardInterrupt:
        print("interrupted", time.monotonic() - start - DELAY)
""")


def run_interrupted(call, delay, timeout=60):
    code = INTERRUPTED.replace("CALL", call).replace("DELAY", repr(delay))
    process = subprocess.run([PYTHON, "-c", code], capture_output=True, text=True, timeout=timeout, env=python_env())
    assert process.returncode == 0, process.stderr
    return process.stdout.split()


def test_ctrl_c_stops_a_long_evaluation_promptly():
    # 200,000 runs would take minutes: the interrupt must end it within a batch.
    out = run_interrupted(f"sd.evaluate('aac', {RANDOM_WALK!r}, range(1, 200001), threads=2)", delay=1.0)
    assert out[0] == "interrupted", out
    assert float(out[1]) < 2.0, out


def test_ctrl_c_stops_a_trace():
    out = run_interrupted(f"[sd.trace('aac', {RANDOM_WALK!r}, seed=s) for s in range(1, 100000)]", delay=0.5)
    assert out[0] == "interrupted" and float(out[1]) < 2.0, out


def test_a_design_stopped_by_ctrl_c_resumes_to_the_same_result(cli_design, tmp_path):
    _, report = cli_design
    folder = tmp_path / "stopped"
    call = f"sd.design(**{DESIGN_ARGS!r}, folder={str(folder)!r})"
    out = run_interrupted(call, delay=1.5)
    assert out[0] == "interrupted", out
    assert float(out[1]) < 5.0, out
    assert sd.Design.open(folder).progress["phase"] != "finished"
    result = sd.design(**DESIGN_ARGS, folder=folder)
    assert result.score == report["best"]["mean_score"]
    assert result.best == sd.ControlSoftware.parse(report["best"]["configuration"])


def test_two_threads_evaluate_at_once():
    # Each thread records, from its progress callbacks, whether the other was inside evaluate
    # and had made progress but not finished: only possible if the GIL is released meanwhile.
    state = {"a": (False, 0), "b": (False, 0)}  # (inside, runs done)
    saw_other_running = {"a": False, "b": False}
    lock = threading.Lock()

    def work(me, other):
        def progress(done, total):
            with lock:
                state[me] = (True, done)
                inside, other_done = state[other]
                if inside and 0 < other_done < total:
                    saw_other_running[me] = True
            time.sleep(0.01)

        with lock:
            state[me] = (True, 0)
        sd.evaluate("aac", RANDOM_WALK, range(1, 161), threads=1, progress=progress)
        with lock:
            state[me] = (False, 160)

    threads = [threading.Thread(target=work, args=("a", "b")), threading.Thread(target=work, args=("b", "a"))]
    for t in threads:
        t.start()
    for t in threads:
        t.join(60)
    assert any(saw_other_running.values()), saw_other_running
    # And the scores do not depend on it.
    assert (sd.evaluate("aac", RANDOM_WALK, range(1, 161), threads=1) ==
            sd.evaluate("aac", RANDOM_WALK, range(1, 161))).all()


def test_a_forked_child_is_told_rather_than_left_waiting():
    code = textwrap.dedent(f"""
        import os, sys
        import swarmdesign as sd
        sd.evaluate('aac', {RANDOM_WALK!r}, '1-4', threads=2)   # the pool's threads start
        pid = os.fork()
        if pid == 0:
            try:
                sd.evaluate('aac', {RANDOM_WALK!r}, '1-4', threads=2)
                os._exit(3)
            except sd.SwarmDesignError as error:
                os._exit(0 if "spawn" in str(error) else 4)
        _, status = os.waitpid(pid, 0)
        print(os.waitstatus_to_exitcode(status))
    """)
    process = subprocess.run([PYTHON, "-c", code], capture_output=True, text=True, timeout=60, env=python_env())
    assert process.stdout.split() == ["0"], process.stderr
