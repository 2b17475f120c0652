#!/usr/bin/env python3
"""The include graph of src/ keeps its layers (src/CMakeLists.txt draws them):

1. a file of src/X includes only X's own headers and those of the libraries X links, directly
   or through them (each folder's CMakeLists.txt names them: sd_library(sd_X sd_Y ...), or
   target_link_libraries for the executable and the Python module): no include upward;
2. the front ends are thin (issue #54): web/ and python/ include no statistics/, storage/ or
   design/ header; they reach them only through app/ services;
3. no cycle between files (#include "a" in b and "b" in a, or longer): in src/app above all.

Usage: check_layers.py SRC_DIR. Prints every breach, one per line, and exits 1 if any."""

import re
import sys
from pathlib import Path

FRONT_ENDS = {"web", "python"}
NOT_FROM_FRONT_ENDS = {"statistics", "storage", "design"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/([^"]+)"', re.M)
LINKED = re.compile(r"\bsd_([a-z]+)\b")


def direct_dependencies(src: Path) -> dict[str, set[str]]:
    folders = {p.name for p in src.iterdir() if p.is_dir() and (p / "CMakeLists.txt").exists()}
    deps = {}
    for folder in folders:
        text = (src / folder / "CMakeLists.txt").read_text()
        named = set()
        for line in text.splitlines():
            if "sd_library(" in line or "target_link_libraries(" in line or "foreach(library" in line:
                named |= {m for m in LINKED.findall(line) if m in folders}
        deps[folder] = named - {folder}
    return deps


def closure(deps: dict[str, set[str]]) -> dict[str, set[str]]:
    out = {}
    for folder in deps:
        seen, todo = set(), list(deps[folder])
        while todo:
            d = todo.pop()
            if d not in seen:
                seen.add(d)
                todo.extend(deps.get(d, ()))
        out[folder] = seen
    return out


def main(src: Path) -> int:
    reachable = closure(direct_dependencies(src))
    problems = []
    graph: dict[str, set[str]] = {}
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".cpp", ".hpp"):
            continue
        rel = path.relative_to(src).as_posix()
        folder = rel.split("/")[0]
        graph.setdefault(rel, set())
        for included_folder, rest in INCLUDE.findall(path.read_text(errors="replace")):
            target = f"{included_folder}/{rest}"
            if not (src / target).exists():
                continue  # a generated header or a library's
            graph[rel].add(target)
            if included_folder == folder:
                continue
            if folder in reachable and included_folder not in reachable[folder]:
                problems.append(f"{rel}: includes {target}, but {folder} does not link {included_folder} (an include upward)")
            if folder in FRONT_ENDS and included_folder in NOT_FROM_FRONT_ENDS:
                problems.append(f"{rel}: includes {target}; a front end reaches {included_folder}/ only through app/")
    # Cycles: depth-first search over the file graph.
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> None:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                cycle = stack[stack.index(nxt):] + [nxt]
                problems.append("include cycle: " + " -> ".join(cycle))
            elif nxt not in state:
                visit(nxt)
        stack.pop()
        state[node] = 2

    sys.setrecursionlimit(10000)
    for node in sorted(graph):
        if node not in state:
            visit(node)
    for p in problems:
        print(p)
    print(f"{len(graph)} files, {sum(len(v) for v in graph.values())} includes of src/: "
          f"{len(problems)} breach{'es' if len(problems) != 1 else ''} of the layers")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(Path(sys.argv[1])))
