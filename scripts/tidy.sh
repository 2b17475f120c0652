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
# One log per file; --quiet drops clang-tidy's "N warnings generated" chatter.
printf '%s\n' "${files[@]}" | xargs -P "$jobs" -I{} sh -c \
  'f="$1"; shift; "$@" "$f" > "'"$logs"'/$(printf %s "$f" | tr / _).log" 2>&1 || true' \
  sh {} "$tidy" -p "$build" --quiet "${extra[@]}"
elapsed=$((SECONDS - start))

# A header's finding is reported once per file that includes it; show each once.
cat "$logs"/*.log | grep -E '^[^ ].*:[0-9]+:[0-9]+: (warning|error): ' | sort -u > "$logs/findings" || true
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
if grep -lE 'error: |Error while processing' "$logs"/*.log >/dev/null 2>&1; then
  cat "$logs"/*.log
  echo "tidy: FAILED: clang-tidy could not process some files, ${elapsed}s on $jobs jobs"
  exit 1
fi
echo "tidy: OK: ${#files[@]} files clean, ${elapsed}s on $jobs jobs"
