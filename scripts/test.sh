#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs the whole test suite with CTest.
#   scripts/test.sh          everything (what CI runs), one stage after the other:
#                              clang-tidy over src/ (scripts/tidy.sh, .clang-tidy),
#                              the Release suite (build/), then the suite under sanitizers
#                              (scripts/sanitizers.sh: ASan+UBSan in build-asan, TSan in build-tsan)
#   scripts/test.sh --fast   the unit tests only (CTest label `unit`), on an existing build:
#                            rebuilds what changed, no set-up; a minute or two
# Other kinds by label: ctest --test-dir build -L workflow|cluster|calibration|slow|browser
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  "")
    ./scripts/setup.sh
    ./scripts/tidy.sh
    ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900
    ./scripts/sanitizers.sh
    ;;
  --fast)
    if [ ! -f build/build.ninja ]; then
      echo "test.sh --fast: no build yet; run scripts/test.sh (or scripts/setup.sh) once first" >&2
      exit 2
    fi
    cmake --build build -j "$(nproc)"
    ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900 -L unit
    ;;
  -h|--help)
    sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
    ;;
  *)
    echo "test.sh: unknown option '$1' (see scripts/test.sh --help)" >&2
    exit 2
    ;;
esac
