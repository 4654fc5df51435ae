#!/usr/bin/env bash
# fresh-root.sh RELEASE [ROOT]: the README's two commands on a bare Debian, as a new user runs
# them. Makes a minimal root with debootstrap (RELEASE: bookworm = Debian 12, trixie = Debian 13,
# forky = Debian 14, today's testing, with Mesa 26 and no OSMesa)
# in ROOT (default /var/tmp/shadowlab-fresh-RELEASE), copies the kit's committed tree (git
# archive HEAD) into /root/shadowlab there, and runs `./kit demo` then `./kit test` as root in a
# chroot: ./kit must install everything itself.
# SHADOWLAB_FRESH_ARCH=arm64 makes an arm64 root (what Apple Silicon's containers run) and runs
# it under qemu-user-static (binfmt_misc must be mounted; about 10x slower): ROOT then defaults
# to /var/tmp/shadowlab-fresh-RELEASE-arm64.
# A failure names the release, the command and its last lines. Needs root and debootstrap.
# Downloaded .debs and ccache's objects are kept between runs (in $SHADOWLAB_FRESH_CACHE, default
# /var/cache/shadowlab-fresh/RELEASE): the root is still bare and ./kit still installs and builds
# everything, only without the network and compiler time; SHADOWLAB_FRESH_CACHE=none runs cold.
set -euo pipefail
release="${1:?usage: tools/fresh-root.sh bookworm|trixie|forky [ROOT]}"
arch="${SHADOWLAB_FRESH_ARCH:-$(dpkg --print-architecture)}"
tag="$release"
[ "$arch" = "$(dpkg --print-architecture)" ] || tag="$release-$arch"
root="${2:-/var/tmp/shadowlab-fresh-$tag}"
cache="${SHADOWLAB_FRESH_CACHE:-/var/cache/shadowlab-fresh}"
kit="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mirror="${SHADOWLAB_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
say() { printf '[fresh-root %s] %s\n' "$tag" "$*"; }

# The bare base is made once and kept as a tarball beside ROOT; every run starts from a fresh
# copy of it, so ./kit installs every package every time (debootstrap's network once).
base="$root.base.tar"
# Nothing may stay mounted inside ROOT before it is removed (a killed run leaves /dev bound).
unmount_all() {
  local m
  for m in $(awk -v r="$root/" 'index($2, r) == 1 { print $2 }' /proc/mounts | sort -r); do
    umount -l "$m" 2>/dev/null || true
  done
  ! awk -v r="$root/" 'index($2, r) == 1 { found = 1 } END { exit !found }' /proc/mounts ||
    { say "something is still mounted under $root: not removing it"; exit 1; }
}
unmount_all
if [ ! -s "$base" ]; then
  rm -rf --one-file-system "$root"
  say "debootstrap --variant=minbase $release $root"
  # A debootstrap older than the release has no script for it: testing's is sid's.
  script=/usr/share/debootstrap/scripts/$release
  [ -e "$script" ] || script=/usr/share/debootstrap/scripts/sid
  if [ "$tag" = "$release" ]; then
    debootstrap --variant=minbase "$release" "$root" "$mirror" "$script" >"$root.debootstrap.log" 2>&1 ||
      { say "debootstrap failed:"; tail -20 "$root.debootstrap.log"; exit 1; }
  else
    # Another architecture: unpack, then finish inside the root through qemu-user-static, whose
    # binfmt_misc entry names its interpreter by path: the root gets the same path.
    case $arch in arm64) qemu=/usr/bin/qemu-aarch64-static ;; *) qemu=/usr/bin/qemu-$arch-static ;; esac
    [ -x "$qemu" ] || { say "$qemu not found: apt-get install qemu-user-static"; exit 1; }
    debootstrap --foreign --variant=minbase --arch="$arch" "$release" "$root" "$mirror" "$script" \
      >"$root.debootstrap.log" 2>&1 || { say "debootstrap failed:"; tail -20 "$root.debootstrap.log"; exit 1; }
    cp "$qemu" "$root/usr/bin/"
    for entry in /proc/sys/fs/binfmt_misc/qemu-*; do
      interp=$(sed -n 's/^interpreter //p' "$entry" 2>/dev/null) || continue
      [ -n "$interp" ] && [ "$(readlink -f "$interp")" = "$(readlink -f "$qemu")" ] || continue
      mkdir -p "$root$(dirname "$interp")"
      ln -sf "/usr/bin/$(basename "$qemu")" "$root$interp"
    done
    chroot "$root" /debootstrap/debootstrap --second-stage >>"$root.debootstrap.log" 2>&1 ||
      { say "debootstrap's second stage failed:"; tail -20 "$root.debootstrap.log"; exit 1; }
  fi
  tar -C "$root" -cf "$base.tmp" . && mv "$base.tmp" "$base"
fi
rm -rf --one-file-system "$root"
mkdir -p "$root"
tar -C "$root" -xf "$base"
mkdir -p "$root/root/shadowlab"
git -C "$kit" archive HEAD | tar -x -C "$root/root/shadowlab"
cp /etc/resolv.conf "$root/etc/resolv.conf"
# The harness's setting, not the kit's (./kit never touches apt's settings): a mirror that
# serves a snapshot serves testing's Release file past its Valid-Until date.
echo 'Acquire::Check-Valid-Until "false";' >"$root/etc/apt/apt.conf.d/99shadowlab-snapshot"

mounts=()
cleanup() { for ((i=${#mounts[@]}-1; i>=0; i--)); do umount -l "${mounts[$i]}" 2>/dev/null || true; done; }
trap cleanup EXIT INT TERM
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
if [ "$cache" != none ]; then
  for pair in "apt:var/cache/apt/archives" "ccache:root/.cache/ccache"; do
    mkdir -p "$cache/$tag/${pair%%:*}" "$root/${pair#*:}"
    [ "${pair%%:*}" = apt ] && mkdir -p "$cache/$tag/apt/partial"
    mount --bind "$cache/$tag/${pair%%:*}" "$root/${pair#*:}"
    mounts+=("$root/${pair#*:}")
  done
fi

for cmd in "./kit demo" "./kit test"; do
  log="$root.$(echo "$cmd" | tr -c 'a-z' '_').log"
  say "$cmd"
  start=$(date +%s)
  if ! chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin TERM=dumb \
      /bin/bash -c "cd /root/shadowlab && $cmd" >"$log" 2>&1; then
    say "FAILED: $cmd on Debian $release ($arch) after $(( $(date +%s) - start )) s; last lines ($log):"
    tail -40 "$log"
    exit 1
  fi
  say "$cmd passed in $(( $(date +%s) - start )) s"
done
