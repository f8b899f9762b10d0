#!/usr/bin/env bash
# The README's first command on a bare Debian 12: a debootstrap'ed bookworm (minbase: no
# compiler, no python3, an empty ccache) in a chroot, a clone of this checkout's HEAD in it,
# `bash scripts/demo.sh` timed to its last line. Root only (debootstrap, chroot, mounts).
# Usage: experiments/ci/bare_demo.sh WORKDIR [LOG]
#   WORKDIR keeps bookworm-pristine.tar (made once, ~100 s from deb.debian.org) and the chroot.
set -euo pipefail
work=${1:?usage: bare_demo.sh WORKDIR [LOG]}
log=${2:-$work/demo.log}
repo=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
mkdir -p "$work"
if [ ! -f "$work/bookworm-pristine.tar" ]; then
  debootstrap --variant=minbase bookworm "$work/seed" http://deb.debian.org/debian
  tar -C "$work/seed" -cf "$work/bookworm-pristine.tar" . && rm -rf "$work/seed"
fi
root="$work/bare"
# A run killed before its trap could leave the host's /proc, /sys or /dev mounted in there:
# unmount first, and never delete across a mount.
for m in dev sys proc; do umount -l "$root/$m" 2>/dev/null || true; done
trap 'for m in dev sys proc; do umount -l "$root/$m" 2>/dev/null || true; done' EXIT
rm -rf --one-file-system "$root" && mkdir -p "$root"
tar -C "$root" -xf "$work/bookworm-pristine.tar"
cp /etc/resolv.conf "$root/etc/resolv.conf"
git clone -q "$repo" "$root/root/mtcs"
for m in proc sys dev; do mount --bind "/$m" "$root/$m"; done
start=$(date +%s)
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin TERM=dumb \
  bash -c 'cd /root/mtcs && bash scripts/demo.sh' > "$log" 2>&1
echo "bare_demo: $(git -C "$repo" rev-parse --short HEAD): $(( $(date +%s) - start )) s to the demo's last line" | tee -a "$log"
