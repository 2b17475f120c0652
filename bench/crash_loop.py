#!/usr/bin/env python3
"""Crash loop: kill SwarmDesign's jobs at random moments and check that they resume exactly.

For each kind of job -- a design run by the CLI (run-design), an experiment (experiment --file)
and a design started through the web server (POST /api/projects/NAME/designs) -- the script
runs it once uninterrupted (the reference), then runs it again and kills it KILLS times,
resuming it after every kill the way a user would (run-design again, the same experiment command
again, a restarted server and the same POST), until it finishes. Two modes:

  kill       SIGKILL from outside after a delay drawn from a seeded RNG, so kills land anywhere
             in a race step, not only at checkpoints; the delays are spread so that the kills
             cover the whole run (each one draws from the remaining run's estimated length).
  power-cut  the process kills itself inside a checkpoint's write: SWARMDESIGN_POWER_CUT=N:K
             (src/storage/power_cut.hpp) tears the K-th file write of its N-th checkpoint in
             half and SIGKILLs there (N and K drawn from the same RNG).

After every kill, each SQLite database of the home (swarmdesign.db and every design.db) is
copied with its WAL and checked on the copy (the live files stay as the kill left them):
PRAGMA integrity_check must say ok and foreign_key_check nothing. The copies must also be on
the reference's path: every design.db's configurations and experiments a prefix of the
reference's, every finished experiment design and assessment as in the reference. At the end
the job's result (the design rows, every design.db's tables, the experiment's designs,
progress and assessments) must be identical to the reference's.

A resume counts as identical when the state seen at the next kill (or the final result, for the
last one) is on the reference's path. Every design chain ends with a late re-run: the same
run-design command once more after the design finished, as after a kill that came too late
(a check kept apart found that it designed again, as design 2); the result must stay the
reference's, with no second design. Exit status 0 only when, for every kind and mode, all
KILLS kills happened, every database was intact after each, and every resume was identical.
Standard library only.
"""
import abc
import argparse
import contextlib
import http.client
import json
import os
import random
import shutil
import signal
import socket
import sqlite3
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
USER, PASSWORD, PROJECT = "bench", "crash-loop-password", "crash"
DESIGN_FLAGS = ["--bt", "--maple", "--seed", "7"]
WEB_DESIGN = {"architectures": "bt", "flavours": "maple", "seed": 7}


def fail(message):
    print(f"crash_loop.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def short_mission(duration, robots):
    """AAC cut down: the crash loop needs many short race steps, not realistic scores."""
    text = "\n".join(line for line in (REPO / "missions/aac.json").read_text().splitlines()
                     if not line.lstrip().startswith("//"))
    mission = json.loads(text)
    mission.update(name="crash-loop-aac", duration=duration, robots=robots)
    mission.pop("argos", None)
    return mission


# ---------------------------------------------------------------------------------------------
# The databases of a home, read on copies.

def databases(home):
    """swarmdesign.db and every design.db under the home, as paths relative to it."""
    found = [Path("swarmdesign.db")] if (home / "swarmdesign.db").exists() else []
    found += sorted(p.relative_to(home) for p in home.rglob("design.db"))
    return found


def snapshot(home, scratch):
    """Copies every database with its journal files into scratch; returns {relative path: copy}."""
    if scratch.exists():
        shutil.rmtree(scratch)
    copies = {}
    for rel in databases(home):
        target = scratch / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        for suffix in ("", "-wal", "-journal"):
            source = home / (str(rel) + suffix)
            try:
                shutil.copyfile(source, str(target) + suffix)
            except FileNotFoundError:
                pass
        copies[str(rel)] = target
    return copies


def intact(copy):
    """None when PRAGMA integrity_check is ok and no foreign key dangles; else what is wrong."""
    try:
        with contextlib.closing(sqlite3.connect(copy)) as db:
            check = [r[0] for r in db.execute("PRAGMA integrity_check")]
            if check != ["ok"]:
                return "integrity_check: " + "; ".join(check[:3])
            dangling = db.execute("PRAGMA foreign_key_check").fetchall()
            if dangling:
                return f"foreign_key_check: {dangling[:3]}"
    except sqlite3.Error as e:
        return f"cannot be read: {e}"
    return None


def rows(db, sql):
    try:
        return [tuple(r) for r in db.execute(sql)]
    except sqlite3.OperationalError:  # a table not there yet (killed before the schema was written)
        return []


def design_tables(path):
    """A design.db's whole content but its wall-clock times."""
    with contextlib.closing(sqlite3.connect(path)) as db:
        return {
            "meta": rows(db, "SELECT key, value FROM meta WHERE key <> 'created_at' ORDER BY key"),
            "configurations": rows(db, "SELECT * FROM configurations ORDER BY id"),
            "experiments": rows(db, "SELECT * FROM experiments ORDER BY seq"),
            "races": rows(db, "SELECT * FROM races ORDER BY iteration"),
            "race_configurations": rows(db, "SELECT * FROM race_configurations ORDER BY iteration, configuration_id"),
            "elites": rows(db, "SELECT * FROM elites ORDER BY iteration, rank"),
            "checkpoint": rows(db, "SELECT step, phase, state FROM checkpoint"),
        }


def home_tables(path):
    """What swarmdesign.db says of the jobs' results (no times, owners or pids)."""
    with contextlib.closing(sqlite3.connect(path)) as db:
        return {
            "designs": rows(db, "SELECT id, project_id, architectures, flavours, mission, budget, seed, state, path, "
                                "best_config, best_score FROM designs ORDER BY id"),
            "experiments": rows(db, "SELECT id, name, protocol, state, path FROM experiments ORDER BY id"),
            "experiment_designs": rows(db, "SELECT id, experiment_id, mission, condition, replicate, method, "
                                           "architectures, flavours, budget, seed, stage, configuration, design_score, "
                                           "runs_used, reused_from FROM experiment_designs ORDER BY id"),
            "experiment_progress": rows(db, "SELECT * FROM experiment_progress ORDER BY design_id, runs_used"),
            "experiment_assessments": rows(db, "SELECT * FROM experiment_assessments ORDER BY design_id, seed"),
        }


def result(copies):
    return {rel: (home_tables(p) if rel == "swarmdesign.db" else design_tables(p)) for rel, p in copies.items()}


def progress(res):
    """(simulation runs, design-database writes) so far: runs over every design and assessment
    measure how far the job is in time; writes count the checkpoints a power cut can fall in."""
    designs = [t for rel, t in res.items() if rel != "swarmdesign.db"]
    runs = sum(len(t["experiments"]) for t in designs)
    writes = sum((1 if t["meta"] else 0) + (t["checkpoint"][0][0] if t["checkpoint"] else 0) for t in designs)
    if "swarmdesign.db" in res:
        runs += len(res["swarmdesign.db"]["experiment_assessments"])
    return runs, writes


def on_path(res, ref):
    """None when the state after a kill is a prefix of the reference's run; else the first difference."""
    for rel, tables in res.items():
        if rel not in ref:
            return f"{rel} is not in the reference"
        want = ref[rel]
        if rel == "swarmdesign.db":
            done = {r[0]: r for r in tables["experiment_designs"] if r[10] == "done"}
            for r in want["experiment_designs"]:
                if r[0] in done and done[r[0]] != r:
                    return f"experiment design {r[0]} ended otherwise: {done[r[0]]} vs {r}"
            extra = set(tables["experiment_assessments"]) - set(want["experiment_assessments"])
            if extra:
                return f"assessments the reference lacks: {sorted(extra)[:2]}"
            for d in tables["designs"]:
                if d[7] == "finished" and d not in want["designs"]:
                    return f"design row {d} is not the reference's"
            continue
        if tables["meta"] and tables["meta"] != want["meta"]:
            return f"{rel}: meta differs"
        for name in ("configurations", "experiments"):
            got = tables[name]
            if got != want[name][:len(got)]:
                first = next(i for i, (a, b) in enumerate(zip(got, want[name] + [None] * len(got))) if a != b)
                return f"{rel}: {name} row {first + 1} differs from the reference's"
        for name in ("races", "elites"):
            if not set(tables[name]) <= set(want[name]):
                return f"{rel}: {name} rows the reference lacks"
    return None


def first_difference(res, ref):
    if set(res) != set(ref):
        return f"databases {sorted(res)} vs {sorted(ref)}"
    for rel in ref:
        for table in ref[rel]:
            if res[rel][table] != ref[rel][table]:
                return f"{rel}: table {table} differs"
    return None


# ---------------------------------------------------------------------------------------------
# Running the jobs.

class Job(abc.ABC):
    """One kind of job in one home: set up, started or resumed, watched, killed."""

    def __init__(self, binary, home, args):
        self.binary, self.home, self.args = binary, home, args
        self.project = home / "users" / USER / "projects" / PROJECT
        self.mission = self.project / "crash-loop-aac.json"
        self.env = dict(os.environ, SWARMDESIGN_HOME=str(home))
        self.env.pop("SWARMDESIGN_POWER_CUT", None)
        self.env.pop("SWARMDESIGN_KILL_AT_CHECKPOINT", None)

    def cli(self, *argv, stdin=None):
        done = subprocess.run([str(self.binary), *argv], env=self.env, input=stdin, capture_output=True, text=True)
        if done.returncode != 0:
            fail(f"swarmdesign {' '.join(argv)}: {done.stderr.strip()}")
        return done.stdout

    def set_up(self):
        if self.home.exists():
            shutil.rmtree(self.home)
        self.home.mkdir(parents=True)
        self.cli("sign-up", USER, "--password-stdin", stdin=PASSWORD + "\n")
        self.cli("sign-in", USER, "--password-stdin", stdin=PASSWORD + "\n")
        self.cli("new-project", PROJECT)
        self.cli("select-project", PROJECT)
        self.mission.write_text(json.dumps(short_mission(self.args.duration, self.args.robots), indent=1))
        self.cli("set-mission", str(self.mission))
        self.cli("set-budget", str(self.args.budget))

    # start() launches (or resumes) the job; returns when it runs. finished() is None while
    # it runs, True when it ended well; kill() SIGKILLs everything it started.
    @abc.abstractmethod
    def start(self, extra_env):
        """Each kind of job (CliDesign, Experiment, WebDesign) says how it starts."""

    def finished(self):
        code = self.process.poll()
        if code is None:
            return None
        if code == 0:
            return True
        if code == -signal.SIGKILL:
            return False
        fail(f"{self.name} exited with status {code}: {self.log.read_text()[-2000:]}")

    def recorded_finished(self, res):
        """Whether the home records the job as finished (a kill may come after that)."""
        return any(d[7] == "finished" for d in res.get("swarmdesign.db", {}).get("designs", []))

    def kill(self):
        try:
            os.killpg(self.process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        self.process.wait()

    def spawn(self, argv, extra_env):
        self.log = self.home / "job.log"
        with open(self.log, "a") as log:
            self.process = subprocess.Popen([str(self.binary), *argv], env=dict(self.env, **extra_env),
                                            stdin=subprocess.DEVNULL, stdout=log, stderr=log, start_new_session=True)


class CliDesign(Job):
    name = "design"

    def start(self, extra_env):
        self.spawn(["run-design", *DESIGN_FLAGS, "--threads", str(self.args.threads)], extra_env)


class Experiment(Job):
    name = "experiment"

    def set_up(self):
        super().set_up()
        protocol = {"name": "crash-loop", "designs": 2, "assessment_seeds": self.args.assessment_seeds, "seed": 3,
                    "missions": [{"mission": str(self.mission), "budget": self.args.budget, "conditions": [
                        {"name": "maple", "architectures": ["bt"], "flavours": ["maple"]},
                        {"name": "maple-2", "architectures": ["bt"], "flavours": ["maple"]}]}]}
        self.protocol = self.project / "crash-loop.json"
        self.protocol.write_text(json.dumps(protocol, indent=1))

    def recorded_finished(self, res):
        return any(e[3] == "finished" for e in res.get("swarmdesign.db", {}).get("experiments", []))

    def start(self, extra_env):
        self.spawn(["experiment", "--file", str(self.protocol), "--threads", str(self.args.threads)], extra_env)


class WebDesign(Job):
    """The server is the process killed; the design runs on its thread."""
    name = "web"

    def start(self, extra_env):
        with socket.socket() as s:  # a free loopback port for this server
            s.bind(("127.0.0.1", 0))
            self.port = s.getsockname()[1]
        self.spawn(["run-exp", "--port", str(self.port), "--host", "127.0.0.1"], extra_env)
        self.cookie = self.csrf = None  # signed in anew each time, as a user whose server restarted
        deadline = time.monotonic() + 30
        while True:
            try:
                if self.request("GET", "/api/session")[0] == 401:
                    break
            except OSError:  # not listening yet
                pass
            if self.process.poll() is not None or time.monotonic() > deadline:
                fail(f"the web server did not start: {self.log.read_text()[-2000:]}")
            time.sleep(0.02)
        status, body, headers = self.request("POST", "/api/sign-in", {"name": USER, "password": PASSWORD})
        if status != 200:
            fail(f"sign-in answered {status}: {body}")
        self.cookie = next(v.split(";")[0] for k, v in headers if k.lower() == "set-cookie" and "sd_session=" in v)
        self.csrf = body["csrf"]
        try:
            status, body, _ = self.request("POST", f"/api/projects/{PROJECT}/designs", WEB_DESIGN)
        except (OSError, http.client.HTTPException):
            if self.process.wait(timeout=10) == -signal.SIGKILL:
                return  # the power cut came while the design started: finished() tells
            raise
        if status != 200 or body.get("state") != "running":
            fail(f"starting the design answered {status}: {body}")

    def request(self, method, path, body=None):
        connection = http.client.HTTPConnection("127.0.0.1", self.port, timeout=30)
        headers = {"Host": f"127.0.0.1:{self.port}"}
        if getattr(self, "cookie", None):
            headers["Cookie"] = self.cookie
        if method == "POST":
            headers["Content-Type"] = "application/json"
            if getattr(self, "csrf", None):
                headers["X-CSRF-Token"] = self.csrf
        connection.request(method, path, json.dumps(body) if body is not None else None, headers)
        answer = connection.getresponse()
        data = answer.read()
        connection.close()
        try:
            parsed = json.loads(data) if data else None
        except ValueError:
            parsed = data.decode(errors="replace")
        return answer.status, parsed, answer.getheaders()

    def finished(self):
        code = self.process.poll()
        if code is not None:
            if code == -signal.SIGKILL:
                return False
            fail(f"the web server exited with status {code}: {self.log.read_text()[-2000:]}")
        try:
            status, body, _ = self.request("GET", f"/api/projects/{PROJECT}/designs")
        except (OSError, http.client.HTTPException):  # the server cut its own power under us
            self.process.wait(timeout=10)
            return self.finished()
        state = body[0]["state"] if status == 200 and body else None
        if state == "finished":
            return True
        if state in ("failed", "interrupted"):
            fail(f"the web design became {state}: {self.log.read_text()[-2000:]}")
        return None

    def stop_server(self):
        self.process.send_signal(signal.SIGTERM)
        self.process.wait()


KINDS = {"design": CliDesign, "experiment": Experiment, "web": WebDesign}


def wait_until(job, moment):
    """Polls the job until the moment; returns what finished() said last."""
    while True:
        state = job.finished()
        if state is not None or time.monotonic() >= moment:
            return state
        time.sleep(0.05 if isinstance(job, WebDesign) else 0.01)


def reference(job, scratch):
    job.set_up()
    began = time.monotonic()
    job.start({})
    while (state := wait_until(job, float("inf"))) is None:
        pass
    seconds = time.monotonic() - began
    if not state:
        fail(f"the reference {job.name} was killed")
    if isinstance(job, WebDesign):
        job.stop_server()
    return result(snapshot(job.home, scratch)), seconds


def crash_loop(job, mode, ref, ref_seconds, rng, scratch, kills):
    """Kills the job `kills` times; returns the figures."""
    total, total_writes = progress(ref)
    figures = {"kind": job.name, "mode": mode, "kills": 0, "intact": 0, "identical": 0, "chains": 0,
               "late_reruns": 0, "at": [], "problems": []}
    pending_resume = False  # a resume whose outcome the next look decides
    overhead = 0.1  # seconds a start costs before the job progresses (learnt as the kills go)
    seen = 0
    began = time.monotonic()
    while figures["kills"] < kills:
        figures["chains"] += 1
        job.set_up()
        done = writes = 0
        broken = False
        while figures["kills"] < kills:
            left = kills - figures["kills"]
            extra = {}
            moment = float("inf")
            # Each kill draws from the rest of the run, so that the kills cover all of it; on
            # average a cycle moves the job on by the remaining run over the kills left.
            remaining = ref_seconds * max(0.02, 1 - done / total)
            if mode == "kill":
                if rng.random() < 0.2:  # one kill in five while it starts up (opens, reads, resumes)
                    delay = rng.uniform(0, overhead)
                else:
                    delay = overhead + min(rng.uniform(0, 2.2 * remaining / (left + 1)), 0.9 * remaining)
                moment = time.monotonic() + delay
            else:
                writes_left = max(1, total_writes - writes)
                cut_at = rng.randint(1, max(1, min(writes_left - 1, round(2 * writes_left / (left + 1)))))
                extra = {"SWARMDESIGN_POWER_CUT": f"{cut_at}:{rng.randint(1, 24)}"}
            started = time.monotonic()
            job.start(extra)
            if mode == "kill":
                state = wait_until(job, moment)
                if state is None:
                    job.kill()
                    state = False
            else:
                while (state := wait_until(job, float("inf"))) is None:
                    pass
            ended = time.monotonic()
            if job.args.verbose:
                print(f"    {job.name} {mode}: chain {figures['chains']}, kill {figures['kills'] + 1}: "
                      f"{'finished first' if state else 'killed'} after {ended - started:.2f} s "
                      f"({'delay %.2f' % delay if mode == 'kill' else extra['SWARMDESIGN_POWER_CUT']}, "
                      f"start-up {overhead:.2f} s, at {done / total:.2f})", flush=True)
            if state:  # it finished before the kill: judged at the end of the chain
                break
            copies = snapshot(job.home, scratch)
            figures["kills"] += 1
            problems = [f"{rel}: {p}" for rel, c in copies.items() if (p := intact(c))]
            if not problems:
                figures["intact"] += 1
                res = result(copies)
                off = on_path(res, ref)
                if off:
                    problems.append(off)
                elif pending_resume:
                    figures["identical"] += 1
                runs, writes = progress(res)
                if mode == "kill":  # what the start cost: the time that moved the job on nothing
                    sample = ended - started - (runs - done) * ref_seconds / total
                    seen += 1
                    overhead += (max(0.0, sample) - overhead) / seen
                done = runs
                figures["at"].append(done / total)
            figures["problems"] += [f"kill {figures['kills']}: {p}" for p in problems]
            if problems:
                pending_resume, broken = False, True
                job.kill()
                break  # a broken chain is not resumed: start a fresh one
            pending_resume = True
            if job.recorded_finished(res):  # killed after it recorded its end: nothing to resume
                break
        if broken:
            continue
        if job.finished() is False and not job.recorded_finished(result(snapshot(job.home, scratch))):
            # the last kill of the loop: resume once more and let it finish
            job.start({})
            while (state := wait_until(job, float("inf"))) is None:
                pass
        if isinstance(job, WebDesign) and job.process.poll() is None:
            job.stop_server()
        if isinstance(job, CliDesign):
            # A kill that came after the design had ended, and the same command run again as a
            # resume: it must find the result, not design it a second time.
            job.start({})
            while (state := wait_until(job, float("inf"))) is None:
                pass
            figures["late_reruns"] += 1
        difference = first_difference(result(snapshot(job.home, scratch)), ref)
        if difference:
            figures["problems"].append(f"chain {figures['chains']} ended otherwise than the reference: {difference}")
        elif pending_resume:
            figures["identical"] += 1
        pending_resume = False
    figures["seconds"] = time.monotonic() - began
    return figures


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default=str(REPO / "build/swarmdesign"), help="swarmdesign (default build/swarmdesign)")
    parser.add_argument("--kills", type=int, default=50, help="kills per kind and mode (50)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the kill moments (1)")
    parser.add_argument("--kinds", default="design,experiment,web", help="comma-separated: design, experiment, web")
    parser.add_argument("--modes", default="kill,power-cut", help="comma-separated: kill, power-cut")
    parser.add_argument("--budget", type=int, default=1500, help="design budget (1500; 728 is the least for BT + Maple)")
    parser.add_argument("--duration", type=int, default=30, help="seconds of the short mission (30)")
    parser.add_argument("--robots", type=int, default=6, help="robots of the short mission (6)")
    parser.add_argument("--assessment-seeds", type=int, default=20, help="the experiment's assessment seeds (20)")
    parser.add_argument("--threads", type=int, default=1, help="threads of the CLI jobs (1; the web's use all cores)")
    parser.add_argument("--verbose", action="store_true", help="one line per kill")
    parser.add_argument("--out", help="work folder (default: a temporary one, removed at the end)")
    args = parser.parse_args()
    binary = Path(args.binary).resolve()
    if not os.access(binary, os.X_OK):
        fail(f"no swarmdesign at {binary} (build it, or give --binary)")
    kinds = args.kinds.split(",")
    modes = args.modes.split(",")
    if not set(kinds) <= set(KINDS) or not set(modes) <= {"kill", "power-cut"} or args.kills < 1:
        fail("--kinds takes design, experiment, web; --modes kill, power-cut; --kills at least 1")
    out = Path(args.out).resolve() if args.out else Path(tempfile.mkdtemp(prefix="crash-loop-"))
    rng = random.Random(args.seed)
    all_good = True
    print(f"{'kind':<11}{'mode':<10}{'kills':>6}{'intact':>9}{'identical':>11}{'chains':>7}"
          f"{'kill at (min/med/max of run)':>30}{'ref s':>8}{'loop s':>8}", flush=True)
    try:
        for kind in kinds:
            job = KINDS[kind](binary, out / kind / "home", args)
            ref, ref_seconds = reference(job, out / kind / "reference")
            for mode in modes:
                f = crash_loop(job, mode, ref, ref_seconds, rng, out / kind / "after-kill", args.kills)
                at = sorted(f["at"]) or [0]
                good = f["kills"] == args.kills and f["intact"] == args.kills and f["identical"] == args.kills \
                    and not f["problems"]
                all_good &= good
                spread = f"{at[0]:.2f}/{at[len(at) // 2]:.2f}/{at[-1]:.2f}"
                print(f"{kind:<11}{mode:<10}{f['kills']:>6}{f['intact']:>6}/{args.kills:<2}{f['identical']:>8}/"
                      f"{args.kills:<2}{f['chains']:>7}{spread:>30}{ref_seconds:>8.1f}{f['seconds']:>8.1f}"
                      f"  {'OK' if good else 'FAILED'}"
                      + (f"  ({f['late_reruns']} late re-runs)" if f["late_reruns"] else ""), flush=True)
                for p in f["problems"][:10]:
                    print(f"    {p}", flush=True)
    finally:
        if not args.out:
            shutil.rmtree(out, ignore_errors=True)
    return 0 if all_good else 1


if __name__ == "__main__":
    sys.exit(main())
