#!/usr/bin/env bash
# Runs clang-tidy (version 14, with the repository's .clang-tidy) over every .cpp file under
# src/ (and tests/ with --tests), using the compile database of an existing CMake build tree.
# Fails if clang-tidy reports anything. It builds nothing: the build tree must have been
# configured (compile_commands.json) and built once, as scripts/setup.sh does.
set -euo pipefail
cd "$(dirname "$0")/.."

usage() {
  cat <<'EOF'
Usage: scripts/tidy.sh [--build DIR] [--jobs N] [--tests] [FILE...]

Runs clang-tidy 14 with the checked-in .clang-tidy over src/**/*.cpp (or the FILEs given)
and fails on any warning (WarningsAsErrors is '*'). Prints one summary line at the end.

  --build DIR  CMake build tree holding compile_commands.json (default: build)
  --jobs N     clang-tidy processes in parallel (default: nproc)
  --tests      also check tests/**/*.cpp
  -h, --help   this text

Files with the same compile command are checked eight at a time, from one source including
them (SWARMDESIGN_TIDY_BATCH=N changes the size; 1 checks each file alone). A file found clean
is remembered in ~/.cache/swarmdesign/tidy until it or anything it includes changes.
EOF
}

build=build
jobs="$(nproc)"
with_tests=0
files=()
while (($#)); do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --tests) with_tests=1; shift ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "tidy: unknown option $1" >&2; usage >&2; exit 2 ;;
    *) files+=("$1"); shift ;;
  esac
done

tidy="$(command -v clang-tidy-14 || command -v clang-tidy || true)"
if [ -z "$tidy" ]; then
  echo "tidy: clang-tidy is not installed (scripts/setup.sh installs it)" >&2
  exit 2
fi
if [ ! -f "$build/compile_commands.json" ]; then
  echo "tidy: $build/compile_commands.json is missing; configure the build first (scripts/setup.sh)" >&2
  exit 2
fi

if ((${#files[@]} == 0)); then
  dirs=(src)
  if ((with_tests)); then dirs+=(tests); fi
  mapfile -t files < <(find "${dirs[@]}" -name '*.cpp' | sort)
fi

# The database holds GCC's command lines. Clang accepts them, but reports its own warnings:
# those are not what this check is about (GCC's -Werror build is), so they are not errors
# here, and a GCC-only option clang does not know is not an error either.
extra=(--extra-arg=-Wno-error --extra-arg=-Wno-unknown-warning-option --extra-arg=-w)

logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT
start=$SECONDS

# GCC's precompiled headers (-include cmake_pch.hxx with its .gch) mean nothing to clang: the
# check reads a copy of the database without them, so each file is parsed as it is written.
# A unity source (CMake's Unity/unity_N_cxx.cxx, which #includes several .cpp files) stands in
# the database for the files it includes: each of them is checked alone, with its command.
mkdir -p "$logs/db"
python3 -c '
import json, re, sys
entries = []
for e in json.load(open(sys.argv[1])):
    if not re.search(r"/Unity/unity_[0-9]+_cxx\.cxx$", e["file"]):
        entries.append(e)
        continue
    for source in re.findall(r"^#include \"([^\"]+)\"", open(e["file"]).read(), re.M):
        entries.append(dict(e, file=source, command=e["command"].replace(e["file"], source)))
for e in entries:
    words, kept = e["command"].split(), []
    for i, w in enumerate(words):
        pch = w == "-include" and i + 1 < len(words) and words[i + 1].endswith("cmake_pch.hxx")
        if pch or (i > 0 and words[i - 1] == "-include" and w.endswith("cmake_pch.hxx")) or w == "-Winvalid-pch":
            continue
        kept.append(w)
    e["command"] = " ".join(kept)
json.dump(entries, open(sys.argv[2], "w"))
' "$build/compile_commands.json" "$logs/db/compile_commands.json"

# A file clang-tidy found clean is not checked again while nothing it depends on changed
# (scripts/lib/tidy_keys.py says what a key covers): the cache holds one empty file per clean
# key, in any clone. Findings are never cached.
cache="${SWARMDESIGN_TIDY_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/swarmdesign/tidy}"
mkdir -p "$cache"
find "$cache" -type f -mtime +30 -delete 2>/dev/null || true
printf '%s\n' "${files[@]}" | python3 scripts/lib/tidy_keys.py . "$build" "$logs/db/compile_commands.json" \
  "$("$tidy" --version | tr -s ' \n' ' ') ${extra[*]}" > "$logs/keys"
to_check=()
cached=0
while read -r f key; do
  if [ "$key" != "-" ] && [ -f "$cache/$key" ]; then
    touch "$cache/$key"
    cached=$((cached + 1))
  else
    to_check+=("$f")
  fi
done < "$logs/keys"

# One log per batch of files sharing a command (scripts/lib/tidy_batches.py: the headers they
# include are parsed and checked once per batch instead of once per file: 0.30 of the time, docs/build-speed.md);
# --quiet drops clang-tidy's "N warnings generated" chatter. The batch sources live outside the
# repository, so the configuration is named.
run_tidy() {  # run_tidy < sources, one per line: checks each, one log each
  xargs -P "$jobs" -I{} sh -c \
    'f="$1"; shift; "$@" "$f" > "'"$logs"'/$(printf %s "$f" | tr / _).log" 2>&1 || true' \
    sh {} "$tidy" -p "$logs/db" --config-file=.clang-tidy --quiet "${extra[@]}"
}
batch() {  # batch SIZE < files: writes batch sources, prints "SOURCE FILE..." lines
  python3 scripts/lib/tidy_batches.py "$logs/db/compile_commands.json" "$logs/batches" "$1"
}
if ((${#to_check[@]})); then
  printf '%s\n' "${to_check[@]}" | batch "${SWARMDESIGN_TIDY_BATCH:-8}" > "$logs/batches.txt"
  # A batch whose files do not compile as one (two of them define a helper of the same name)
  # is split in two and each half checked again, down to single files: its compiler errors
  # are the batch's, not the files'.
  while [ -s "$logs/batches.txt" ]; do
    cut -d' ' -f1 "$logs/batches.txt" | run_tidy
    while read -r source members; do
      log="$logs/$(printf %s "$source" | tr / _).log"
      if [ "$source" != "${members%% *}" ] && grep -qE '\[clang-diagnostic-error\]|Error while processing' "$log"; then
        echo "tidy: ${members// /, } do not compile as one ($(grep -m1 -oE "error: [^[]*" "$log" || echo "clang-tidy failed")): split" >&2
        rm -f "$log"
        n=$(wc -w <<< "$members")
        printf '%s\n' $members | batch $(((n + 1) / 2))
      fi
    done < "$logs/batches.txt" > "$logs/batches.next"
    mv "$logs/batches.next" "$logs/batches.txt"
  done
fi
elapsed=$((SECONDS - start))

# A header's finding is reported once per file that includes it; show each once.
cat "$logs"/*.log 2>/dev/null | grep -E '^[^ ].*:[0-9]+:[0-9]+: (warning|error): ' | sort -u > "$logs/findings" || true
count=$(wc -l < "$logs/findings")
if ((count)); then
  # Each finding with its context lines, as clang-tidy printed it, once.
  cat "$logs"/*.log | awk '
    /^[^ ].*:[0-9]+:[0-9]+: (warning|error|note): / { key = $0; show = !(key in seen); seen[key] = 1 }
    show && !/ warnings? (generated|treated as errors)\.?$/ && !/^Suppressed / && !/^Use -header-filter/ { print }'
  echo "tidy: FAILED: $count finding(s) in ${#files[@]} files ($(sed -E 's/.*\[([^],]+).*\]$/\1/' "$logs/findings" | sort | uniq -c | sort -rn | awk '{printf "%s%s %s", sep, $2, $1; sep=", "}')), ${elapsed}s on $jobs jobs"
  exit 1
fi
# A file clang-tidy could not parse yields an error without a check name; it fails too.
if grep -lsE 'error: |Error while processing' "$logs"/*.log >/dev/null 2>&1; then
  cat "$logs"/*.log
  echo "tidy: FAILED: clang-tidy could not process some files, ${elapsed}s on $jobs jobs"
  exit 1
fi
# Every file checked now is clean: remember it.
while read -r f key; do
  if [ "$key" != "-" ] && [ ! -f "$cache/$key" ]; then : > "$cache/$key"; fi
done < "$logs/keys"
echo "tidy: OK: ${#files[@]} files clean (${#to_check[@]} checked, $cached unchanged since a clean check), ${elapsed}s on $jobs jobs"
