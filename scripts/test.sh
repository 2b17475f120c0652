#!/usr/bin/env bash
# Sets up everything the tests need and runs them all (what CI runs, .ci/run).
#   scripts/test.sh           everything, one stage after the other, each timed, then a table:
#                               set-up: scripts/setup.sh --tests (the program's packages and the
#                                 test-only ones below; every target, benchmarks included)
#                               clang-tidy over src/ (scripts/tidy.sh, .clang-tidy)
#                               the Release suite (build/): every CTest label
#                               ASan+UBSan (build-asan) and TSan (build-tsan): scripts/sanitizers.sh
#                               a check that no service it installed or started is left on
#   scripts/test.sh --quick   on a built tree: rebuilds what changed, the unit tests and a smoke
#                             of each front end (CLI, web page in chromium, Python); under a minute
#   scripts/test.sh --fast    on a built tree: rebuilds what changed and runs the unit tests
# Test-only Debian packages it installs (scripts/lib/packages.sh says why each):
#   TEST_PACKAGES
# Installing them starts no service, and the ones it installs stay disabled: the cluster
# tests start their own Slurm and sshd on private ports and stop them.
# Other kinds by label: ctest --test-dir build -L unit|workflow|cluster|calibration|slow|interop|cross_cpu|browser|python|package
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/stages.sh
source scripts/lib/packages.sh

jobs="$(nproc)"

# slowest BUILD N: the N longest tests of the last ctest run in BUILD, from CTest's own timings.
slowest() {
  local cost="$1/Testing/Temporary/CTestCostData.txt"
  [ -f "$cost" ] || return 0
  echo "The $2 slowest tests of $1 (seconds):"
  # (awk, not head: head would leave sort writing to a closed pipe, and pipefail fail on it)
  # Each line is "NAME RUNS SECONDS"; a parameterised test's NAME has spaces in it.
  awk '/^---/ { exit } NF >= 3 { t = $NF; sub(/ +[0-9]+ +[0-9.e+-]+$/, ""); printf "%8.1f  %s\n", t, $0 }' "$cost" \
    | sort -rn | awk -v n="$2" 'NR <= n' 
}

need_built_tree() {
  if [ ! -f build/build.ninja ] || ! grep -q '^SWARMDESIGN_TESTS:BOOL=ON' build/CMakeCache.txt; then
    echo "test.sh $1: no test build yet; run scripts/test.sh once first (or scripts/setup.sh --tests)" >&2
    exit 2
  fi
}

case "${1:-}" in
  "")
    services_before="$(sd_daemon_pids)"
    stage "set-up: test packages"
    install_packages test "${product_packages[@]}" "${test_packages[@]}"
    stage_end
    ./scripts/setup.sh --tests
    stage "clang-tidy over src/"
    ./scripts/tidy.sh
    stage "Release tests (build/, every label)"
    ctest --test-dir build --output-on-failure -j "$jobs" --timeout 900
    slowest build 20
    stage_end
    ./scripts/sanitizers.sh
    stage "no service left running or enabled"
    check_no_new_services "$services_before"
    ;;
  --quick|--fast)
    need_built_tree "$1"
    stage "build (what changed)"
    cmake --build build -j "$jobs"
    stage "unit tests"
    ctest --test-dir build --output-on-failure -j "$jobs" --timeout 900 -L unit
    if [ "$1" = --quick ]; then
      stage "smoke: CLI, web page, Python"
      ./scripts/smoke.sh build
    fi
    ;;
  -h|--help)
    awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0" | while IFS= read -r line; do
      if [ "$line" = "  TEST_PACKAGES" ]; then echo "${test_packages[*]}" | fold -s -w 92 | sed 's/^/  /'; else echo "$line"; fi
    done
    ;;
  *)
    echo "test.sh: unknown option '$1' (see scripts/test.sh --help)" >&2
    exit 2
    ;;
esac
