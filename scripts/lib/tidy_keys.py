#!/usr/bin/env python3
"""Cache keys for scripts/tidy.sh: one line "FILE KEY" per source file given on stdin.

A file's key digests everything clang-tidy's verdict on it depends on: clang-tidy's version,
the .clang-tidy file, the file's compile command and the content of every file it includes
(the build's own dependency list, `ninja -t deps`). Paths inside the repository are written
relative to it, so a fresh clone of the same sources gets the same keys. A file the build has
no dependency list for gets no key (it is always checked).

Usage: tidy_keys.py ROOT BUILD_DIR COMPILE_DB TIDY_VERSION_TEXT < files
"""
import hashlib
import json
import os
import subprocess
import sys


def main() -> int:
    root, build, database, tidy_version = sys.argv[1:5]
    root = os.path.realpath(root)
    build_abs = os.path.realpath(build)

    def relative(path: str, base: str) -> str:
        full = os.path.realpath(os.path.join(base, path))
        return os.path.relpath(full, root) if full.startswith(root + os.sep) else full

    with open(database, encoding="utf-8") as f:
        commands = json.load(f)
    by_source = {}
    for entry in commands:
        source = relative(entry["file"], entry.get("directory", root))
        text = entry.get("command") or " ".join(entry.get("arguments", []))
        words = text.split()
        output = entry.get("output") or (words[words.index("-o") + 1] if "-o" in words[:-1] else None)
        by_source[source] = (text.replace(build_abs, "<build>").replace(root, "<root>"), output)

    deps = {}
    listing = subprocess.run(["ninja", "-C", build, "-t", "deps"], capture_output=True, text=True, check=False).stdout
    current = None
    for line in listing.splitlines():
        if not line.strip():
            current = None
        elif not line.startswith(" "):
            current = line.split(":", 1)[0]
            deps[current] = [] if "(VALID)" in line else None
        elif current is not None and deps.get(current) is not None:
            deps[current].append(line.strip())

    digests = {}

    def digest(path: str) -> str:
        if path not in digests:
            try:
                with open(path, "rb") as f:
                    content = f.read()
                # A file the build generated (a unity source #includes each .cpp by its absolute
                # path) is digested with the clone's paths taken out, as commands are.
                if os.path.realpath(path).startswith(build_abs + os.sep):
                    content = content.replace(build_abs.encode(), b"<build>").replace(root.encode(), b"<root>")
                digests[path] = hashlib.sha256(content).hexdigest()
            except OSError:
                digests[path] = "missing"
        return digests[path]

    with open(os.path.join(root, ".clang-tidy"), "rb") as f:
        config = hashlib.sha256(f.read()).hexdigest()

    for source in (line.strip() for line in sys.stdin):
        if not source:
            continue
        command, output = by_source.get(relative(source, root), (None, None))
        headers = deps.get(output) if output else None
        if command is None or headers is None:
            print(source, "-")
            continue
        h = hashlib.sha256()
        for part in (tidy_version, config, command):
            h.update(part.encode())
            h.update(b"\0")
        for header in headers:
            full = os.path.join(build_abs, header)
            h.update(relative(header, build_abs).encode())
            h.update(digest(full).encode())
        print(source, h.hexdigest())
    return 0


if __name__ == "__main__":
    sys.exit(main())
