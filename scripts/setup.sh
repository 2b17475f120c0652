#!/usr/bin/env bash
# Sets SwarmDesign up on Debian 12: installs what it needs from Debian's archive (and the web
# app's npm packages), then configures and builds it in ./build. Safe to run again: apt-get,
# npm, CMake and ccache skip what is already done.
#   scripts/setup.sh            swarmdesign, its web app and its Python module: no daemon,
#                               browser, sanitizer or linter is installed, no test is built
#   scripts/setup.sh --cluster  the same with MPI (mpirun -np N swarmdesign ...)
#   scripts/setup.sh --tests    everything scripts/test.sh needs: the test-only packages too
#                               (scripts/test.sh --help lists them), and every target built
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/stages.sh
source scripts/lib/packages.sh

with_tests=0
with_cluster=0
for arg in "$@"; do
  case "$arg" in
    --tests) with_tests=1; with_cluster=1 ;;
    --cluster) with_cluster=1 ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "setup.sh: unknown option '$arg' (see scripts/setup.sh --help)" >&2; exit 2 ;;
  esac
done

stage "set-up: Debian packages"
install_packages setup "${product_packages[@]}"
if ((with_tests)); then
  install_packages setup "${test_packages[@]}"
elif ((with_cluster)); then
  install_packages setup "${cluster_packages[@]}"
fi

# The front end's npm packages, exactly as frontend/package-lock.json pins them.
if [ ! -f frontend/node_modules/.package-lock.json ] || [ frontend/package-lock.json -nt frontend/node_modules/.package-lock.json ]; then
  stage "set-up: npm packages of the front end"
  (cd frontend && npm ci --no-audit --no-fund --loglevel=error)
fi

# A tree configured before keeps its choice of tests and benchmarks (a developer's tree that
# scripts/test.sh built stays whole); a new one builds the program alone unless --tests.
options=(-DSWARMDESIGN_WERROR="${CI:+ON}")
if ((with_tests)); then
  options+=(-DSWARMDESIGN_TESTS=ON -DSWARMDESIGN_BENCH=ON)
elif [ ! -f build/CMakeCache.txt ]; then
  options+=(-DSWARMDESIGN_TESTS=OFF -DSWARMDESIGN_BENCH=OFF)
fi
build_type="${SWARMDESIGN_BUILD_TYPE:-Release}"
if ((with_tests)); then
  stage "Release build: everything (build/)"
else
  stage "Release build: swarmdesign, web app, Python module (build/)"
fi
configure_log="$(mktemp)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$build_type" "${options[@]}" > "$configure_log" 2>&1 \
  || { cat "$configure_log"; rm -f "$configure_log"; exit 1; }
rm -f "$configure_log"
if ((with_tests)); then
  cmake --build build -j "$(nproc)"
else
  cmake --build build -j "$(nproc)" --target product
fi
stage_end
