#!/usr/bin/env bash
# Installs every dependency SwarmDesign needs from Debian's archive, then configures and
# builds it in ./build. Safe to run again: apt-get and CMake skip what is already done.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config git
  libcli11-dev nlohmann-json3-dev libsqlite3-dev libsodium-dev libboost-dev r-cran-irace
  libgtest-dev libgmock-dev libbenchmark-dev
  libcpp-httplib-dev  # the web app's server (run-exp)
  libpugixml-dev  # ARGoS experiment files (mission export-argos)
  chromium  # the web app's browser tests (headless)
  ffmpeg  # ffprobe checks the web app's downloaded run videos (browser tests)
  jq  # bench/native_vs_irace.sh
  openmpi-bin libopenmpi-dev  # designs on MPI ranks (mpirun -np N swarmdesign ...)
  slurm-client  # cluster projects submit designs with sbatch from a login node
  slurmctld slurmd munge openssh-server  # the cluster tests start a one-node Slurm and an sshd
  clang libclang-rt-14-dev  # scripts/sanitizers.sh: ASan, UBSan, TSan and libFuzzer runtimes
  clang-tidy  # scripts/tidy.sh, with the repository's .clang-tidy
  pybind11-dev python3-dev  # the Python module swarmdesign (build/python; src/python)
  python3-numpy python3-pytest python3-pandas python3-matplotlib  # its arrays, tests, tables, examples
)
# Node.js and npm bundle the web app's front end; a machine that has them already keeps its own.
if ! command -v npm >/dev/null 2>&1; then packages+=(nodejs npm); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The front end's npm packages, exactly as frontend/package-lock.json pins them.
if [ ! -f frontend/node_modules/.package-lock.json ] || [ frontend/package-lock.json -nt frontend/node_modules/.package-lock.json ]; then
  echo "setup: installing the front end's npm packages"
  (cd frontend && npm ci --no-audit --no-fund --loglevel=error)
fi

build_type="${SWARMDESIGN_BUILD_TYPE:-Release}"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$build_type" -DSWARMDESIGN_WERROR="${CI:+ON}"
cmake --build build -j "$(nproc)"
