#!/usr/bin/env bash
# Runs README's two commands on a brand-new Debian 12 (a debootstrap chroot), to prove that
# install-deps.sh installs everything: a green run on a developer's machine can hide a missing
# package. Needs root and network access to the Debian mirror; takes about 4 minutes.
# Usage: sudo scripts/fresh-machine-check.sh [CHROOT_DIR]   (default /tmp/plascap-fresh)
set -euo pipefail
cd "$(dirname "$0")/.."
root=${1:-/tmp/plascap-fresh}
command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap
[ -x "$root/bin/bash" ] || debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian
rm -rf "$root/root/plascap"
git clone -q . "$root/root/plascap"
cp /etc/resolv.conf "$root/etc/resolv.conf"
mountpoint -q "$root/proc" || mount -t proc proc "$root/proc"
mountpoint -q "$root/dev" || mount --bind /dev "$root/dev"
trap 'umount "$root/proc" "$root/dev" 2>/dev/null || true' EXIT
chroot "$root" /bin/bash -c "cd /root/plascap && ./scripts/run-tests.sh && ./scripts/run-example.sh"
echo "fresh-machine-check: both README commands passed on a new Debian 12"
