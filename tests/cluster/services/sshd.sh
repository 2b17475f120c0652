#!/usr/bin/env bash
# A private sshd on 127.0.0.1 with throw-away keys, for tests; all files in DIR.
#   sshd.sh start DIR   -> prints 'export SWARMDESIGN_SSH="ssh -F DIR/ssh_config"'
#   sshd.sh stop DIR    -> stops that sshd (idempotent)
set -euo pipefail

usage() { echo "usage: $0 start|stop DIR (DIR absolute)" >&2; exit 2; }
[[ $# -eq 2 && $2 == /* ]] || usage
cmd=$1 dir=${2%/}

# Is pid $1 alive and our sshd? Its command line names DIR; this also skips
# zombies (empty cmdline) and pids reused by other processes.
ours() { tr '\0' ' ' <"/proc/$1/cmdline" 2>/dev/null | grep -qF -- "$dir/"; }

stop() {
    local pid i
    pid=$(cat "$dir/sshd.pid" 2>/dev/null) || true
    if [[ -n $pid ]] && ours "$pid"; then
        kill "$pid" 2>/dev/null || true
        for ((i = 0; i < 50; i++)); do ours "$pid" || break; sleep 0.1; done
        if ours "$pid"; then kill -9 "$pid" 2>/dev/null || true; fi
    fi
    rm -f "$dir/sshd.pid"
}

fail() {
    echo "sshd.sh: $*" >&2
    [[ -f $dir/sshd.log ]] && { echo "=== $dir/sshd.log" >&2; tail -n 30 "$dir/sshd.log" >&2; }
    stop
    exit 1
}

start() {
    local port user i
    if [[ -s $dir/sshd.pid ]] && ours "$(<"$dir/sshd.pid")"; then
        echo "sshd already running for $dir; run '$0 stop $dir' first" >&2; exit 1
    fi
    mkdir -p "$dir"
    rm -f "$dir"/{ssh_host_ed25519_key,id_ed25519}{,.pub} "$dir"/known_hosts "$dir"/sshd.log
    ssh-keygen -q -t ed25519 -N '' -C swarmdesign-test-host -f "$dir/ssh_host_ed25519_key"
    ssh-keygen -q -t ed25519 -N '' -C swarmdesign-test-user -f "$dir/id_ed25519"
    cp "$dir/id_ed25519.pub" "$dir/authorized_keys"
    user=$(id -un)
    port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
    # sshd refuses to start without its privilege-separation dir (normally made by systemd).
    [[ -d /run/sshd ]] || mkdir -m 0755 /run/sshd

    # StrictModes no: DIR may live under /tmp with any permissions.
    # AcceptEnv + the client's SendEnv pass SLURM_CONF/OMPI_* to remote commands.
    cat >"$dir/sshd_config" <<EOF
ListenAddress 127.0.0.1
Port $port
HostKey $dir/ssh_host_ed25519_key
AuthorizedKeysFile $dir/authorized_keys
PidFile $dir/sshd.pid
PasswordAuthentication no
KbdInteractiveAuthentication no
PubkeyAuthentication yes
PermitRootLogin prohibit-password
AllowUsers $user
UsePAM no
StrictModes no
AcceptEnv SLURM_CONF OMPI_* PATH
Subsystem sftp internal-sftp
EOF
    cat >"$dir/ssh_config" <<EOF
Host 127.0.0.1
  Port $port
  User $user
  IdentityFile $dir/id_ed25519
  IdentitiesOnly yes
  StrictHostKeyChecking no
  UserKnownHostsFile $dir/known_hosts
  BatchMode yes
  LogLevel ERROR
  SendEnv SLURM_CONF OMPI_*
EOF

    /usr/sbin/sshd -t -f "$dir/sshd_config" 2>"$dir/sshd.log" || fail "bad sshd_config"
    # -D keeps sshd in the foreground so $! is its pid; output to files so `$(sshd.sh start)` returns.
    /usr/sbin/sshd -D -f "$dir/sshd_config" -E "$dir/sshd.log" </dev/null >/dev/null 2>&1 &
    echo $! >"$dir/sshd.pid"
    for ((i = 0; i < 100; i++)); do
        (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null && break
        kill -0 "$(<"$dir/sshd.pid")" 2>/dev/null || fail "sshd exited"
        sleep 0.1
    done
    timeout 20 ssh -F "$dir/ssh_config" 127.0.0.1 true </dev/null ||
        fail "ssh -F $dir/ssh_config 127.0.0.1 true failed"
    echo "export SWARMDESIGN_SSH=\"ssh -F $dir/ssh_config\""
}

case $cmd in
    start) start ;;
    stop) stop ;;
    *) usage ;;
esac
