#!/usr/bin/env bash
# package_test.sh BUILD SOURCE: installs BUILD into a scratch prefix and packs it as a .deb,
# then checks both trees and runs the unpacked package's binary and Python module.
set -euo pipefail
build="$(realpath "$1")"
source="$(realpath "$2")"
tmp="$(mktemp -d)"
trap 'kill "${server:-}" 2>/dev/null || true; rm -rf "$tmp"' EXIT
fail() { echo "package test: $*" >&2; exit 1; }
python_dir="$(sed -n 's/^SWARMDESIGN_PYTHON_INSTALL_DIR:STRING=//p' "$build/CMakeCache.txt")"
# The python3 the module was built for (Debian's, with its numpy), not whichever comes first.
python="$(sed -n 's/^PYTHON_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")"

# expect_tree ROOT: the files a user needs are there.
expect_tree() {
  local root="$1" f
  for f in bin/swarmdesign share/swarmdesign/web-root/index.html share/swarmdesign/missions/aac.json \
           share/doc/swarmdesign/LICENSE.demiurge share/doc/swarmdesign/README.md; do
    [ -s "$root/$f" ] || fail "$root/$f is missing"
  done
  [ -x "$root/bin/swarmdesign" ] || fail "$root/bin/swarmdesign is not executable"
  if [ -n "$python_dir" ]; then
    [ -f "$root/$python_dir/swarmdesign/__init__.py" ] || fail "$root/$python_dir/swarmdesign/__init__.py is missing"
    compgen -G "$root/$python_dir/swarmdesign/_core*.so" >/dev/null || fail "the Python module's _core is missing"
  fi
}

echo "== cmake --install"
cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install failed"; }
expect_tree "$tmp/prefix"

echo "== cpack: the Debian package"
(cd "$tmp" && cpack -G DEB -B "$tmp/pkg" --config "$build/CPackConfig.cmake" > "$tmp/cpack.log" 2>&1) \
  || { cat "$tmp/cpack.log"; fail "cpack failed"; }
deb="$(ls "$tmp"/pkg/swarmdesign_*.deb)"
dpkg-deb -c "$deb" > "$tmp/contents"
for f in ./usr/bin/swarmdesign ./usr/share/swarmdesign/web-root/index.html ./usr/share/swarmdesign/missions/aac.json; do
  grep -q " $f\$" "$tmp/contents" || fail "the package lacks $f"
done
# Nothing of the build machine leaks into the package: every path is under /usr.
if grep -v ' \./usr/' "$tmp/contents" | grep -v ' \./$' | grep -q .; then fail "files outside /usr: $(grep -v ' \./usr/' "$tmp/contents")"; fi
depends="$(dpkg-deb -f "$deb" Depends)"
for d in libsqlite3 libsodium libpugixml; do
  [[ $depends == *"$d"* ]] || fail "Depends lacks $d: $depends"
done
[ -z "$python_dir" ] || [[ $depends == *python3-numpy* ]] || fail "Depends lacks python3-numpy: $depends"
dpkg-deb -x "$deb" "$tmp/unpacked"
expect_tree "$tmp/unpacked/usr"

echo "== the unpacked binary"
bin="$tmp/unpacked/usr/bin/swarmdesign"
version="$("$bin" --version)"
[[ $version =~ ^swarmdesign\ [0-9.]+\ \(results\ version\ [0-9]+\)$ ]] || fail "--version printed '$version'"
[ "$version" = "$("$build/swarmdesign" --version)" ] || fail "the package's version differs from the build's"
export SWARMDESIGN_HOME="$tmp/home"
# The catalogue's AAC, 10 s long (mission files may hold // comments: no JSON parser here).
sed -E 's/"duration": *[0-9.]+/"duration": 10/' "$source/missions/aac.json" > "$tmp/aac-short.json"
design=(design --mission "$tmp/aac-short.json" --budget 1100 --fsm --chocolate --seed 3 --json --threads 2)
"$bin" "${design[@]}" --out "$tmp/packaged-design" > "$tmp/packaged.json"
"$build/swarmdesign" "${design[@]}" --out "$tmp/built-design" > "$tmp/built.json"
python3 - "$tmp/packaged.json" "$tmp/built.json" <<'PY' || fail "the packaged binary designs differently from the build's"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
assert a["elites"] and a["elites"][0]["configuration"], a
assert [(e["configuration"], e["mean_score"]) for e in a["elites"]] == [(e["configuration"], e["mean_score"]) for e in b["elites"]]
PY

echo "== the unpacked binary serves the unpacked pages"
echo '<!-- from the unpacked package -->' >> "$tmp/unpacked/usr/share/swarmdesign/web-root/index.html"
port="$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
"$bin" run-exp --port "$port" > "$tmp/server.log" 2>&1 &
server=$!
python3 - "$port" <<'PY' || { cat "$tmp/server.log"; fail "run-exp did not serve the package's index.html"; }
import sys, time, urllib.request
for _ in range(100):
    try:
        page = urllib.request.urlopen(f"http://127.0.0.1:{sys.argv[1]}/", timeout=2).read().decode()
        break
    except OSError:
        time.sleep(0.1)
else:
    sys.exit("no answer")
assert "from the unpacked package" in page, page[:200]
PY
kill "$server"; wait "$server" 2>/dev/null || true

if [ -n "$python_dir" ]; then
  echo "== the unpacked Python module"
  PYTHONPATH="$tmp/unpacked/usr/$python_dir" "$python" - "$tmp/unpacked" <<'PY' || fail "the package's Python module"
import sys
import swarmdesign as sd
assert sd.__file__.startswith(sys.argv[1]), sd.__file__
scores = sd.evaluate("aac", "--fsm-config --nstates 1 --s0 10 --rwm0 50", seeds=[1, 2], threads=1)
assert len(scores) == 2
PY
fi
echo "package test: OK ($(basename "$deb"), $(du -h "$deb" | cut -f1))"
