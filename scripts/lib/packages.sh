# Debian packages SwarmDesign needs (sourced by setup.sh and test.sh, not run). Two lists:
# what the program needs (setup.sh) and what only the tests need (test.sh), so that a
# researcher's first command installs no daemon, browser, sanitizer runtime or linter.

# swarmdesign, its web app and its Python module: build and run.
product_packages=(
  build-essential cmake ninja-build pkg-config
  ccache  # every build tree compiles through it (CMakeLists.txt): a second clone builds warm
  libcli11-dev nlohmann-json3-dev libsqlite3-dev libsodium-dev libboost-dev
  libcpp-httplib-dev  # the web app's server (run-exp)
  libpugixml-dev  # ARGoS experiment files (mission export-argos)
  libarchive-dev  # a home's backups (admin backup/restore)
  pybind11-dev python3-dev python3-numpy  # the Python module swarmdesign (build/python)
)
# Node.js and npm bundle the web app's front end; a machine that has them keeps its own.
if ! command -v npm >/dev/null 2>&1; then product_packages+=(nodejs npm); fi

# Clusters (setup.sh --cluster, and the tests): MPI ranks (mpirun -np N swarmdesign ...).
# A Slurm login node has its own Slurm client; the tests bring theirs below.
cluster_packages=(openmpi-bin libopenmpi-dev)

# Only the tests (test.sh): their frameworks, the browser, the sanitizers, the linter, and
# the real services the cluster tests start on private ports and stop again.
test_packages=(
  libgtest-dev libgmock-dev libbenchmark-dev  # the test suite and bench/
  clang libclang-rt-14-dev  # scripts/sanitizers.sh: ASan, UBSan, TSan and libFuzzer runtimes
  lld  # the sanitizer trees link with it: cmake/precompiled_headers.cmake says why
  clang-tidy  # scripts/tidy.sh, with the repository's .clang-tidy
  chromium  # the web app's browser tests (headless)
  ffmpeg  # ffprobe checks the web app's downloaded run videos (browser tests)
  python3-pytest python3-pandas python3-matplotlib  # the Python module's tests, tables, examples
  r-cran-irace  # the real irace 3.5 the interoperability tests compare with
  jq  # bench/native_vs_irace.sh
  "${cluster_packages[@]}"
  slurm-client slurmctld slurmd munge openssh-server  # the cluster tests' one-node Slurm and sshd
)

# Services that packages above bring: installing them starts none, and the ones this script
# installed are left disabled (a machine that had them before keeps them as they were).
declare -A package_services=([munge]=munge [slurmctld]=slurmctld [slurmd]=slurmd [openssh-server]=ssh)

sd_installed_now=()  # what install_packages installed in this run

sd_sudo() {
  if [ "$(id -u)" -ne 0 ]; then sudo "$@"; else "$@"; fi
}

# install_packages WHO PACKAGE...: installs the missing ones from Debian's archive.
install_packages() {
  local who="$1"
  shift
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "$who: installing ${missing[*]}"
  # No package starts a service while it installs (invoke-rc.d and deb-systemd-invoke ask
  # policy-rc.d; 101 = not allowed). An administrator's own policy-rc.d is left alone.
  local policy=/usr/sbin/policy-rc.d made_policy=""
  if [ ! -e "$policy" ]; then
    printf '#!/bin/sh\nexit 101\n' | sd_sudo tee "$policy" >/dev/null
    sd_sudo chmod 755 "$policy"
    made_policy=1
  fi
  local status=0
  sd_sudo apt-get update -qq || status=$?
  if ((status == 0)); then
    DEBIAN_FRONTEND=noninteractive sd_sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" || status=$?
  fi
  if [ -n "$made_policy" ]; then sd_sudo rm -f "$policy"; fi
  ((status == 0)) || return "$status"
  sd_installed_now+=("${missing[@]}")
  for p in "${missing[@]}"; do
    local service="${package_services[$p]:-}"
    [ -n "$service" ] || continue
    if command -v systemctl >/dev/null 2>&1; then sd_sudo systemctl disable --quiet "$service" >/dev/null 2>&1 || true; fi
    if command -v update-rc.d >/dev/null 2>&1; then sd_sudo update-rc.d "$service" disable >/dev/null 2>&1 || true; fi
  done
}

# The daemons the test packages bring, by process name.
sd_daemons=(munged slurmctld slurmd sshd)

# sd_daemon_pids: the pids of those daemons running now, one a line.
sd_daemon_pids() {
  local d
  for d in "${sd_daemons[@]}"; do pgrep -x "$d" || true; done | sort -n
}

# check_no_new_services BEFORE: fails if a daemon runs now that was not running when BEFORE
# (sd_daemon_pids' output) was taken, or if a service of a package installed in this run is
# enabled.
check_no_new_services() {
  local before="$1" now new="" p service bad=0
  now="$(sd_daemon_pids)"
  new="$(comm -13 <(printf '%s\n' "$before" | sed '/^$/d') <(printf '%s\n' "$now" | sed '/^$/d'))"
  if [ -n "$new" ]; then
    echo "services: still running after the suite:" >&2
    # shellcheck disable=SC2086
    ps -o pid=,args= -p $(echo $new | tr ' ' ',') >&2 || true
    bad=1
  fi
  for p in "${sd_installed_now[@]}"; do
    service="${package_services[$p]:-}"
    [ -n "$service" ] || continue
    if command -v systemctl >/dev/null 2>&1 && [ "$(systemctl is-enabled "$service" 2>/dev/null)" = enabled ]; then
      echo "services: $service (package $p) is enabled" >&2
      bad=1
    fi
    if compgen -G "/etc/rc[2-5].d/S*$service" >/dev/null; then
      echo "services: $service (package $p) starts at boot (/etc/rc?.d)" >&2
      bad=1
    fi
  done
  ((bad == 0)) || return 1
  echo "services: none left running or enabled (checked: ${sd_daemons[*]})"
}
