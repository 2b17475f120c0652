#!/usr/bin/env python3
"""Precompiled headers, side by side: compiles a sample of a build tree's files twice each,
with the tree's precompiled header and without it (the same command, its -include-pch and
-include dropped), one after the other, never through ccache, and prints the wall times and
their ratio. The tree must be built (its .pch files exist).

    bench/pch_compile_sample.py build-asan [N]     # N test files and N library files (default 12)

docs/build-speed.md has the figures this printed."""

import json
import random
import shlex
import subprocess
import sys
import time
from pathlib import Path


def without_pch(args: list[str]) -> list[str]:
    out, i = [], 0
    while i < len(args):
        if args[i] == "-Xclang" and i + 1 < len(args) and args[i + 1] in ("-include-pch", "-include"):
            i += 4  # -Xclang -include-pch -Xclang FILE
            continue
        if args[i] == "-include" or args[i].startswith("-include-pch"):  # GCC's form
            i += 2
            continue
        out.append(args[i])
        i += 1
    return out


def timed(args: list[str], cwd: str) -> float:
    start = time.perf_counter()
    subprocess.run(args, cwd=cwd, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main(tree: Path, n: int) -> None:
    entries = [e for e in json.loads((tree / "compile_commands.json").read_text()) if "include-pch" in e["command"] or
               "-include " in e["command"]]
    random.seed(54)
    tests = [e for e in entries if "/tests/" in e["file"]]
    libraries = [e for e in entries if "/tests/" not in e["file"] and "/src/" in e["file"]]
    for kind, sample in (("test", random.sample(tests, min(n, len(tests)))),
                         ("library", random.sample(libraries, min(n, len(libraries))))):
        with_total = without_total = 0.0
        for e in sample:
            args = shlex.split(e["command"])
            args = [a for a in args if a != "ccache"]
            o = args.index("-o")
            args[o + 1] = "/dev/null"
            with_pch = timed(args, e["directory"])
            plain = timed(without_pch(args), e["directory"])
            with_total += with_pch
            without_total += plain
            print(f"  {kind:7} {Path(e['file']).name:44} {plain:6.2f} s -> {with_pch:6.2f} s")
        print(f"{kind} files: {without_total:.1f} s without, {with_total:.1f} s with the precompiled header: "
              f"{with_total / without_total:.2f} of the time ({len(sample)} files)")


if __name__ == "__main__":
    main(Path(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 12)
