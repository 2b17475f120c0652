#!/usr/bin/env bash
# The test suite under sanitizers (docs/hardening.md). Needs what scripts/setup.sh --tests installs.
#   scripts/sanitizers.sh          both stages, ASan+UBSan then TSan (what scripts/test.sh runs)
#   scripts/sanitizers.sh --asan   build-asan: clang, ASan+UBSan (+ libFuzzer targets), the suite
#   scripts/sanitizers.sh --tsan   build-tsan: clang, TSan, the tests of the concurrent parts
# Any sanitizer report fails its test, and so the stage. Both trees compile through ccache
# (CMakeLists.txt), so a second clone on the same machine builds warm.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/stages.sh

jobs="$(nproc)"
# Suppressions, only for third-party code we cannot fix, each with its reason: scripts/sanitizers/.
supp() { [ -f "scripts/sanitizers/$1" ] && echo ":suppressions=$PWD/scripts/sanitizers/$1"; return 0; }

# Debug keeps assertions on; -O1 (ASan's own advice) runs the simulator about three times
# faster than -O0 and still reports exact lines. Both stages use clang 14: its runtimes are
# what libFuzzer needs, and one compiler keeps the two builds' reports alike.
configure() {  # configure <dir> <cmake args...>
  local dir="$1"
  shift
  CC=clang CXX=clang++ cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1" \
    -DSWARMDESIGN_BENCH=OFF -DSWARMDESIGN_WERROR=ON "$@" >/dev/null
}

# ASan+UBSan: the whole suite but for what cannot run under them or would not fit CI's time:
#   browser      chromium drives the page; the server it talks to is the binary the workflow
#                tests already run here, and the page itself is JavaScript
#   cluster      Slurm daemons and OpenMPI: their own libraries leak by design (LSan) and
#                mpirun's children do not inherit the options reliably
#   slow         the scaled-down thesis experiment, ~3 min in Release and ~10 under ASan; its
#                parts (designs, leases, reports) run in the workflow and app tests
#   calibration  simulates the ARGoS reference controllers' runs, ~1 min in Release; the same
#                simulator code runs in every unit test of simulator/, modules/, evaluation/
#   interop      the real irace (R) starting the binary 300 times; irace's strings are parsed
#                in-process by a unit test here, and fuzzed
#   cross_cpu    glibc's FMA vs SSE2 paths: a property of the GCC Release binary users run
asan() {
  stage "ASan+UBSan build (build-asan)"
  configure build-asan -DSWARMDESIGN_SANITIZE=address,undefined -DSWARMDESIGN_FUZZ=ON \
    -DSWARMDESIGN_TEST_LABELS="unit;workflow"
  cmake --build build-asan -j "$jobs"
  stage "ASan+UBSan tests: labels unit, workflow, fuzz"
  ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:print_stacktrace=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1$(supp asan.supp)" \
  LSAN_OPTIONS="print_suppressions=0$(supp lsan.supp)" \
  UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1$(supp ubsan.supp)" \
    ctest --test-dir build-asan --output-on-failure -j "$jobs" --timeout 1800 -L '^(unit|workflow|fuzz)$'
}

# TSan: the concurrent parts only (the rest is single-threaded code the ASan stage covers):
# the executor (core), the web server's cluster collector, design and evolution jobs, two designs sharing the pool, leases racing
# sweeps (app), the web server with its background designs and experiments, Exec runs (their
# registry) and many viewers (web),
# concurrent sign-ups, the designs store's leases and a design detached from the CLI
# (workflow). Test folders built: core, app, web, workflow.
tsan_tests='^(Executor|ClusterCollection|DesignJob|EvolutionJob|ProjectDesign|LeaseRace|WebServer|WebSecurity|WebConcurrency|RunRegistry|workflow_concurrency|workflow_designs|DesignLease|run_design)\.'
tsan() {
  stage "TSan build (build-tsan)"
  configure build-tsan -DSWARMDESIGN_SANITIZE=thread -DSWARMDESIGN_TEST_FOLDERS="core;app;web;workflow"
  cmake --build build-tsan -j "$jobs" --target swarmdesign core_tests app_tests web_tests workflow_tests
  stage "TSan tests: the concurrent parts"
  TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:history_size=4$(supp tsan.supp)" \
    ctest --test-dir build-tsan --output-on-failure -j "$jobs" --timeout 1800 -R "$tsan_tests"
}

case "${1:-}" in
  "") asan; tsan ;;
  --asan) asan ;;
  --tsan) tsan ;;
  -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
  *) echo "sanitizers.sh: unknown option '$1' (see scripts/sanitizers.sh --help)" >&2; exit 2 ;;
esac
stage_end
