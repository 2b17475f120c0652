#!/usr/bin/env bash
# Times the README's first command on a fresh Debian 12, as a newcomer runs it: a bookworm
# made by debootstrap (Debian's standard base system: no compiler, no CMake, no Node.js), this
# repository cloned into it, then, inside it,
#   ./scripts/setup.sh && ./build/swarmdesign design --mission aac --budget 2000 --fsm --chocolate --seed 1 --out aac-design
# timed from the start to the printed design, apt included. It then lists the services the
# set-up left enabled or running in the fresh system (there should be none).
#
# Usage (root): bench/first_command.sh [ROOTFS]   (default /srv/swarmdesign-fresh; made if absent,
#               and a fresh copy of it is used, so the base is never touched by a run)
# Needs: debootstrap (apt-get install debootstrap), the network to Debian's archive.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
base="${1:-/srv/swarmdesign-fresh}"
[ "$(id -u)" -eq 0 ] || { echo "first_command.sh: run as root (debootstrap and chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || { echo "first_command.sh: apt-get install debootstrap first" >&2; exit 2; }

if [ ! -x "$base/bin/bash" ]; then
  echo "== debootstrap bookworm into $base (not timed)"
  debootstrap bookworm "$base" http://deb.debian.org/debian >/dev/null
fi
run="$(mktemp -d /srv/swarmdesign-run.XXXXXX)"
echo "== a fresh copy of the base in $run"
cp -a "$base/." "$run/"
cleanup() {
  for m in dev/pts dev proc sys; do umount "$run/$m" 2>/dev/null || true; done
  rm -rf "$run"
}
trap cleanup EXIT
mount -t proc proc "$run/proc"
mount -t sysfs sys "$run/sys"
mount --bind /dev "$run/dev"
mount --bind /dev/pts "$run/dev/pts"
cp /etc/resolv.conf "$run/etc/resolv.conf"
git clone -q "$repo" "$run/root/swarmdesign"
# A network that inspects TLS (a lab's or a sandbox's proxy) has its own certificate authority;
# the fresh system trusts what this machine trusts, as its administrator would set it up
# (a plain network needs none of this). apt's ca-certificates picks them up when installed.
extra_env=()
if compgen -G "/usr/local/share/ca-certificates/*.crt" >/dev/null; then
  mkdir -p "$run/usr/local/share/ca-certificates"
  cp /usr/local/share/ca-certificates/*.crt "$run/usr/local/share/ca-certificates/"
fi
if [ -n "${NODE_EXTRA_CA_CERTS:-}" ] && [ -f "$NODE_EXTRA_CA_CERTS" ]; then
  mkdir -p "$run$(dirname "$NODE_EXTRA_CA_CERTS")"
  cp "$NODE_EXTRA_CA_CERTS" "$run$NODE_EXTRA_CA_CERTS"
  extra_env+=("NODE_EXTRA_CA_CERTS=$NODE_EXTRA_CA_CERTS")
fi

echo "== README command 1 (timed)"
start=$(date +%s)
chroot "$run" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin TERM=dumb "${extra_env[@]}" \
  bash -c 'cd /root/swarmdesign && ./scripts/setup.sh && ./build/swarmdesign design --mission aac --budget 2000 --fsm --chocolate --seed 1 --out aac-design' \
  > "$run/first-command.log" 2>&1 || { tail -40 "$run/first-command.log"; echo "first_command.sh: the command failed" >&2; exit 1; }
took=$(($(date +%s) - start))
grep -A3 "Configuration string" "$run/first-command.log" | head -4 || true
grep -E '^== ' "$run/first-command.log" || true
echo "first command: $((took / 60)) min $((took % 60)) s from a fresh Debian 12 to the printed design ($(nproc) cores)"

echo "== services the set-up left"
enabled="$(chroot "$run" sh -c 'ls /etc/rc2.d 2>/dev/null | grep "^S" || true; systemctl list-unit-files --state=enabled --no-legend 2>/dev/null | awk "{print \$1}" || true' | sort)"
base_enabled="$(chroot "$base" sh -c 'ls /etc/rc2.d 2>/dev/null | grep "^S" || true; systemctl list-unit-files --state=enabled --no-legend 2>/dev/null | awk "{print \$1}" || true' | sort)"
new="$(comm -13 <(echo "$base_enabled") <(echo "$enabled") | sed '/^$/d')"
if [ -n "$new" ]; then echo "enabled by the set-up: $new"; exit 1; fi
echo "none enabled by the set-up"
left=""
for p in /proc/[0-9]*; do
  [ "$(readlink "$p/root" 2>/dev/null)" = "$run" ] && left+=" $(tr '\0' ' ' < "$p/cmdline")"
done
if [ -n "$left" ]; then echo "still running in the fresh system:$left"; exit 1; fi
echo "none running"
