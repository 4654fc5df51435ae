#!/usr/bin/env bash
# fresh-root.sh RELEASE [ROOT]: the README's two commands on a bare Debian, as a new user runs
# them. Makes a minimal root with debootstrap (RELEASE: bookworm = Debian 12, trixie = Debian 13;
# kept in ROOT, default /var/tmp/shadowlab-fresh-RELEASE, and reused while its base is intact),
# copies the kit's committed tree (git archive HEAD) into a clean /root/shadowlab there, and runs
# `./kit demo` then `./kit test` as root in a chroot: ./kit must install everything itself.
# A failure names the release, the command and its last lines. Needs root and debootstrap.
set -euo pipefail
release="${1:?usage: tools/fresh-root.sh bookworm|trixie [ROOT]}"
root="${2:-/var/tmp/shadowlab-fresh-$release}"
kit="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mirror="${SHADOWLAB_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
say() { printf '[fresh-root %s] %s\n' "$release" "$*"; }

if [ ! -x "$root/usr/bin/apt-get" ] || [ ! -f "$root/.fresh-root-base" ]; then
  rm -rf "$root"
  say "debootstrap --variant=minbase $release $root"
  debootstrap --variant=minbase "$release" "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
    { say "debootstrap failed:"; tail -20 "$root.debootstrap.log"; exit 1; }
  touch "$root/.fresh-root-base"
fi
# A reused root keeps the packages ./kit installed before (the check is that it installs them,
# which the first run proves); the kit itself is always a clean copy.
rm -rf "$root/root/shadowlab"
mkdir -p "$root/root/shadowlab"
git -C "$kit" archive HEAD | tar -x -C "$root/root/shadowlab"
cp /etc/resolv.conf "$root/etc/resolv.conf"

mounts=()
cleanup() { for ((i=${#mounts[@]}-1; i>=0; i--)); do umount -l "${mounts[$i]}" 2>/dev/null || true; done; }
trap cleanup EXIT
for m in proc sys dev dev/pts dev/shm; do
  mkdir -p "$root/$m"
  case $m in
    proc) mount -t proc proc "$root/proc" ;;
    sys) mount -t sysfs sys "$root/sys" ;;
    dev/pts) mount -t devpts devpts "$root/dev/pts" ;;
    dev/shm) mount -t tmpfs shm "$root/dev/shm" ;;
    *) mount --bind "/$m" "$root/$m" ;;
  esac
  mounts+=("$root/$m")
done

for cmd in "./kit demo" "./kit test"; do
  log="$root.$(echo "$cmd" | tr -c 'a-z' '_').log"
  say "$cmd"
  start=$(date +%s)
  if ! chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin TERM=dumb \
      /bin/bash -c "cd /root/shadowlab && $cmd" >"$log" 2>&1; then
    say "FAILED: $cmd on Debian $release after $(( $(date +%s) - start )) s; last lines ($log):"
    tail -40 "$log"
    exit 1
  fi
  say "$cmd passed in $(( $(date +%s) - start )) s"
done
