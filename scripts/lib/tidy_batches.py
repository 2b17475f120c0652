#!/usr/bin/env python3
"""Groups the files scripts/tidy.sh checks into batches: one source per batch that #includes
several files compiled with the same command.

clang-tidy spends most of a file's time matching its checks over the headers it includes
(nlohmann/json, CLI11, httplib, the standard library): a batch of files with the same command
parses and matches those once. Its diagnostics inside each file are the same as the file's own
(the checks used here do not depend on which file is the main one; bugprone-suspicious-include
would flag the batch's own #includes, and the NOLINT on each says it is meant). A batch that does
not compile as one (two files defining the same helper, say) is given back to this script by
tidy.sh, halved (SIZE = half its files), down to single files.

Usage: tidy_batches.py COMPILE_DB BATCH_DIR SIZE < files
Adds one database entry per batch to COMPILE_DB and prints one line per batch:
"BATCH_SOURCE FILE..." (a file alone in its group is its own batch: "FILE FILE").
"""
import json
import os
import sys


def main() -> int:
    database, batch_dir, size = sys.argv[1], sys.argv[2], int(sys.argv[3])
    with open(database, encoding="utf-8") as f:
        entries = json.load(f)
    by_file = {}
    for entry in entries:
        path = os.path.realpath(os.path.join(entry.get("directory", "."), entry["file"]))
        by_file[path] = entry

    groups = {}
    order = []
    for line in sys.stdin:
        name = line.strip()
        if not name:
            continue
        entry = by_file.get(os.path.realpath(name))
        if entry is None:  # not in the database: clang-tidy will say so for the file alone
            print(f"{name} {name}")
            continue
        words = entry["command"].split()
        if "-o" in words[:-1]:
            del words[words.index("-o"):words.index("-o") + 2]
        key = (entry.get("directory", ""), " ".join(w for w in words if w != entry["file"]))
        if key not in groups:
            groups[key] = []
            order.append(key)
        groups[key].append((name, entry, os.path.realpath(name)))

    os.makedirs(batch_dir, exist_ok=True)
    for key in order:
        members = groups[key]
        for start in range(0, len(members), size):
            chunk = members[start:start + size]
            if len(chunk) == 1:
                print(f"{chunk[0][0]} {chunk[0][0]}")
                continue
            source = os.path.join(batch_dir, f"batch_{len(entries)}.cpp")
            with open(source, "w", encoding="utf-8") as out:
                for _, _, path in chunk:
                    out.write(f'#include "{path}"  // NOLINT(bugprone-suspicious-include)\n')
            first = chunk[0][1]
            entries.append(dict(first, file=source, command=first["command"].replace(first["file"], source)))
            print(source + " " + " ".join(name for name, _, _ in chunk))
    with open(database, "w", encoding="utf-8") as f:
        json.dump(entries, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
