#!/usr/bin/env bash
# A smoke of each front end on a built tree (scripts/test.sh --quick runs it):
#   CLI     --version, a random walk evaluated on AAC, a small design of a 10-s AAC
#   web     one page end to end: the real server and Debian's chromium (frontend/e2e/views)
#   Python  import swarmdesign, the same scores as the CLI's, bit for bit
# Usage: scripts/smoke.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."

case "${1:-}" in
  -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
esac
build="$(realpath "${1:-build}")"
bin="$build/swarmdesign"
[ -x "$bin" ] || { echo "smoke: $bin is missing; build first (scripts/setup.sh)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export SWARMDESIGN_HOME="$tmp/home"
fail() { echo "smoke: FAILED: $*" >&2; exit 1; }

walk=(--fsm-config --nstates 1 --s0 10 --rwm0 50)

echo "smoke: CLI"
"$bin" --version | grep -q '^swarmdesign .* (results version [0-9]*)$' || fail "swarmdesign --version"
"$bin" evaluate --mission aac --seeds 1-3 --json "${walk[@]}" > "$tmp/cli.json"
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert len(d["runs"]) == 3, d' "$tmp/cli.json" \
  || fail "evaluate --json did not give three runs"
# The catalogue's AAC, 10 s long (mission files may hold // comments: no JSON parser here).
sed -E 's/"duration": *[0-9.]+/"duration": 10/' missions/aac.json > "$tmp/aac-short.json"
"$bin" design --mission "$tmp/aac-short.json" --budget 1100 --fsm --chocolate --seed 1 --out "$tmp/design" --json \
  > "$tmp/design.json" || fail "design"
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["elites"][0]["configuration"], d' "$tmp/design.json" \
  || fail "design --json has no best configuration"

echo "smoke: Python"
# The python3 the module was built for (Debian's, with its numpy), not whichever comes first.
python="$(sed -n 's/^PYTHON_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")"
PYTHONPATH="$build/python" "${python:-python3}" - "$tmp/cli.json" <<'EOF' || fail "the Python module"
import json, sys
import swarmdesign as sd
cli = [run["score"] for run in json.load(open(sys.argv[1]))["runs"]]
ours = sd.evaluate("aac", "--fsm-config --nstates 1 --s0 10 --rwm0 50", seeds=[1, 2, 3], threads=1)
assert [float(x) for x in ours] == [float(x) for x in cli], (list(ours), cli)
EOF

echo "smoke: web page"
if [ -x /usr/bin/chromium ] && [ -d frontend/node_modules/playwright-core ]; then
  (cd frontend && SWARMDESIGN_BIN="$bin" SWARMDESIGN_WEB_ROOT="$build/web-root" SWARMDESIGN_SCREENSHOTS="$build/screenshots" \
    node --test --test-concurrency=1 e2e/views.test.mjs) > "$tmp/web.log" 2>&1 || { cat "$tmp/web.log"; fail "the web page"; }
else
  fail "no chromium or playwright-core: run scripts/test.sh once (it installs them)"
fi
echo "smoke: OK: CLI, Python and the web page"
