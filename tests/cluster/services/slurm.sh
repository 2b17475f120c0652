#!/usr/bin/env bash
# Single-node Slurm (Debian packages) for tests; all state lives in DIR.
#   slurm.sh start DIR   -> prints "export SLURM_CONF=DIR/slurm.conf"
#   slurm.sh stop DIR    -> stops the daemons started in DIR (idempotent)
# Needs no /etc/slurm, /run/munge or systemd.
set -euo pipefail

usage() { echo "usage: $0 start|stop DIR (DIR absolute)" >&2; exit 2; }
[[ $# -eq 2 && $2 == /* ]] || usage
cmd=$1 dir=${2%/}

# A free TCP port (bind to 0 and let the kernel choose).
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("",0)); print(s.getsockname()[1])'; }

# Is pid $1 alive and one of ours? Our daemons all have DIR in their command line;
# this also skips zombies (empty cmdline) and pids reused by other processes.
ours() { tr '\0' ' ' <"/proc/$1/cmdline" 2>/dev/null | grep -qF -- "$dir/"; }

# Kill the process whose pid is in file $1 and wait (bounded) until it is gone.
kill_pidfile() {
    local f=$1 pid i
    pid=$(cat "$f" 2>/dev/null) || true
    if [[ -n $pid ]] && ours "$pid"; then
        kill "$pid" 2>/dev/null || true
        for ((i = 0; i < 50; i++)); do ours "$pid" || break; sleep 0.1; done
        if ours "$pid"; then kill -9 "$pid" 2>/dev/null || true; fi
    fi
    rm -f "$f"
}

dump_logs() {
    local f
    for f in "$dir"/munged.log "$dir"/slurmctld.log "$dir"/slurmd.log \
             "$dir"/slurmctld.out "$dir"/slurmd.out; do
        [[ -f $f ]] && { echo "=== $f" >&2; tail -n 30 "$f" >&2; }
    done
    return 0
}

stop() {
    # Cancel remaining jobs first: slurmstepd/job processes outlive slurmd otherwise.
    if [[ -s $dir/slurmctld.pid ]] && ours "$(<"$dir/slurmctld.pid")"; then
        export SLURM_CONF=$dir/slurm.conf
        if timeout 10 scancel -u "$(id -un)" 2>/dev/null; then
            for ((i = 0; i < 50; i++)); do
                [[ -z $(timeout 5 squeue -h -o %i 2>/dev/null) ]] && break
                sleep 0.2
            done
        fi
    fi
    kill_pidfile "$dir/slurmd.pid"
    kill_pidfile "$dir/slurmctld.pid"
    kill_pidfile "$dir/munged.pid"
}

start() {
    local host user ctld_port slurmd_port node i f
    for f in munged slurmctld slurmd; do
        if [[ -s $dir/$f.pid ]] && ours "$(<"$dir/$f.pid")"; then
            echo "$f already running for $dir; run '$0 stop $dir' first" >&2; exit 1
        fi
    done
    # Fresh state every time (old job state would refer to old ports/keys). Stale
    # *.pid.slurm files matter: slurmctld/slurmd SIGTERM the pid found in them.
    rm -rf "$dir"/{state,spool} "$dir"/munge.socket* "$dir"/*.pid.slurm "$dir"/munged.pid.munge
    mkdir -p "$dir"/{state,spool}
    # 0755, not 0700: munged wants its socket reachable by job users.
    chmod 755 "$dir"
    host=$(hostname -s)
    user=$(id -un)

    # --- munge: private key + socket so nothing depends on /etc/munge or /run/munge.
    rm -f "$dir/munge.key"
    dd if=/dev/urandom of="$dir/munge.key" bs=1 count=1024 status=none
    chmod 400 "$dir/munge.key"
    # -F + '&' keeps the pid ours; --force because munged refuses to run as root otherwise.
    munged -F --force --socket="$dir/munge.socket" --key-file="$dir/munge.key" \
        --pid-file="$dir/munged.pid.munge" --log-file="$dir/munged.log" \
        --seed-file="$dir/munged.seed" </dev/null >>"$dir/munged.log" 2>&1 &
    echo $! >"$dir/munged.pid"
    for ((i = 0; i < 50; i++)); do [[ -S $dir/munge.socket ]] && break; sleep 0.1; done
    [[ -S $dir/munge.socket ]] || { echo "munged did not start" >&2; dump_logs; stop; exit 1; }

    # --- slurm.conf: node line from `slurmd -C` (minus its UpTime line).
    node=$(slurmd -C | grep '^NodeName=')
    ctld_port=$(free_port)
    slurmd_port=$(free_port)
    while [[ $slurmd_port == "$ctld_port" ]]; do slurmd_port=$(free_port); done
    : >"$dir/plugstack.conf"  # keep /etc/slurm/plugstack.conf out of the picture
    cat >"$dir/slurm.conf" <<EOF
ClusterName=swarmtest
SlurmctldHost=$host
SlurmUser=$user
SlurmdUser=$user
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
# Our own munged, for daemons and clients alike.
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid.slurm
SlurmdPidFile=$dir/slurmd.pid.slurm
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
PlugStackConfig=$dir/plugstack.conf
# No cgroups: plain /proc process tracking.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
# Start jobs right after submit (defaults delay each start by ~2-3 s).
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
# Allocate cores, not whole nodes, so several 1-task jobs run at once.
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
# No slurmdbd: keep finished jobs visible in scontrol for 10 minutes.
MinJobAge=600
ReturnToService=2
KillWait=5
OverTimeLimit=0
MailProg=/bin/true
SlurmctldDebug=info
SlurmdDebug=info
$node State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF

    # -D: foreground, so the pid is ours; output to files so `$(slurm.sh start)` returns.
    slurmctld -D -f "$dir/slurm.conf" </dev/null >"$dir/slurmctld.out" 2>&1 &
    echo $! >"$dir/slurmctld.pid"
    slurmd -D -f "$dir/slurm.conf" </dev/null >"$dir/slurmd.out" 2>&1 &
    echo $! >"$dir/slurmd.pid"

    export SLURM_CONF=$dir/slurm.conf
    for ((i = 0; i < 150; i++)); do
        if [[ $(timeout 5 sinfo -h -N -o %t 2>/dev/null) == idle ]]; then
            echo "export SLURM_CONF=$SLURM_CONF"
            return 0
        fi
        # Fail fast if a daemon died.
        for f in slurmctld slurmd; do
            kill -0 "$(<"$dir/$f.pid")" 2>/dev/null || break 2
        done
        sleep 0.2
    done
    echo "slurm did not come up (node not idle, or a daemon exited)" >&2
    timeout 5 sinfo -N >&2 || true
    dump_logs
    stop
    exit 1
}

case $cmd in
    start) start ;;
    stop) stop ;;
    *) usage ;;
esac
