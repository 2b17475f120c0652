#!/usr/bin/env python3
"""How long a design takes to stop after Ctrl-C (issue #55: within 2 s at any budget).

A design of AAC (20 robots, 120 s; FSM, Chocolate) runs from Python with sd.design() at each
budget; a timer sends this process SIGINT (what Ctrl-C sends) after each delay, and the latency
is the time from the signal to the KeyboardInterrupt in Python. Each stopped design is then
resumed once for a few seconds and stopped again, to show that it resumes. The race's first step
at a large budget holds thousands of runs, so a stop heard only between steps waited for all of
them (87 s at 500k before this change); a stop heard between runs waits for one run per thread.

    PYTHONPATH=build/python python3 bench/cancel_latency.py [--budgets 5000,20000,500000]
        [--delays 1.5,4,9] [--threads 0]

Prints one line per (budget, delay) and the worst latency per budget."""

import argparse
import os
import signal
import sys
import tempfile
import threading
import time
from pathlib import Path

import swarmdesign as sd


def stop_after(delay, sent):
    def fire():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)
    timer = threading.Timer(delay, fire)
    timer.daemon = True
    timer.start()
    return timer


def one_stop(run, delay):
    """Seconds from SIGINT to KeyboardInterrupt, and whether the call ended by the signal."""
    sent = []
    timer = stop_after(delay, sent)
    try:
        run()
    except KeyboardInterrupt:
        return time.perf_counter() - sent[0], True
    finally:
        timer.cancel()
    return 0.0, False  # it ended before the signal


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--budgets", default="5000,20000,500000")
    parser.add_argument("--delays", default="1.5,4,9")
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    budgets = [int(b) for b in args.budgets.split(",")]
    delays = [float(d) for d in args.delays.split(",")]
    worst = {}
    with tempfile.TemporaryDirectory(prefix="sd-cancel-") as scratch:
        for budget in budgets:
            for delay in delays:
                folder = Path(scratch) / f"aac-{budget}-{delay}"
                latency, stopped = one_stop(lambda: sd.design("aac", budget, architectures="fsm", flavours="chocolate",
                                                              seed=1, folder=folder, threads=args.threads), delay)
                if not stopped:
                    print(f"budget {budget:>7}: finished before the stop at {delay} s", flush=True)
                    continue
                resumed_latency, resumed_stopped = one_stop(
                    lambda: sd.resume_design(folder, threads=args.threads), 2.0)
                state = sd.Design.open(folder).progress.get("experiments_used", "?")
                print(f"budget {budget:>7}: Ctrl-C at {delay:4.1f} s stopped in {latency:6.3f} s; resumed and "
                      f"stopped again in {resumed_latency:6.3f} s ({'stopped' if resumed_stopped else 'finished'}; "
                      f"{state} runs durable)", flush=True)
                worst[budget] = max(worst.get(budget, 0.0), latency, resumed_latency if resumed_stopped else 0.0)
    print("worst latency per budget: " + ", ".join(f"{b}: {w:.3f} s" for b, w in worst.items()))
    return 0 if all(w <= 2.0 for w in worst.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
