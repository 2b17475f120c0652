# Command-line helpers shared by the bench/ scripts. Not run on its own: a script sets PROG (its
# name in messages) and REPO_DIR (the repository root), then does
#   source "$SCRIPT_DIR/lib/cli.sh"
# Errors are one line on stderr: die exits 1 (a run failed), usage_error exits 2 (bad arguments).
# shellcheck shell=bash

die() {
  echo "$PROG: error: $*" >&2
  exit 1
}

usage_error() {
  echo "$PROG: error: $* (see --help)" >&2
  exit 2
}

# need_value "$@" in an option's case branch: $1 is the option, $2 its value.
need_value() { [[ $# -ge 2 && -n "$2" ]] || usage_error "$1 needs a value"; }

# positive NAME VALUE: VALUE is an integer >= 1 (no sign, no leading zero).
positive() { [[ "$2" =~ ^[1-9][0-9]*$ ]] || usage_error "$1 must be a positive integer, not '$2'"; }

# non_negative NAME VALUE: as positive, but 0 is allowed (e.g. --threads 0, all cores).
non_negative() { [[ "$2" =~ ^(0|[1-9][0-9]*)$ ]] || usage_error "$1 must be a non-negative integer, not '$2'"; }

# positive_number NAME VALUE: a decimal number above 0, e.g. 0.05 (awk decides "above 0").
positive_number() {
  if [[ "$2" =~ ^([0-9]+([.][0-9]*)?|[.][0-9]+)$ ]] && awk -v v="$2" 'BEGIN { exit !(v + 0 > 0) }'; then return; fi
  usage_error "$1 must be a positive number, not '$2'"
}

# resolve_binary VALUE: prints the absolute path of the swarmdesign executable: VALUE (--binary),
# else $SWARMDESIGN, else $REPO_DIR/build/swarmdesign, else the first one found under build/
# (other build layouts). Dies if none is executable; use as binary="$(resolve_binary "$binary")" || exit.
resolve_binary() {
  local b="${1:-${SWARMDESIGN:-}}"
  if [[ -z "$b" ]]; then
    if [[ -x "$REPO_DIR/build/swarmdesign" ]]; then
      b="$REPO_DIR/build/swarmdesign"
    elif [[ -d "$REPO_DIR/build" ]]; then
      b="$(find "$REPO_DIR/build" -name swarmdesign -type f -perm -u+x 2>/dev/null | head -n 1)"
    fi
    [[ -n "$b" ]] || die "swarmdesign binary not found under $REPO_DIR/build: build it or give --binary PATH"
  fi
  [[ -f "$b" && -x "$b" ]] || die "swarmdesign binary not found or not executable: $b (give --binary PATH)"
  echo "$(cd "$(dirname "$b")" && pwd)/$(basename "$b")"
}
