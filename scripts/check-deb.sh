#!/usr/bin/env bash
# Checks radcl's Debian package on a fresh Debian 12: builds a minimal bookworm root with
# debootstrap, installs the package there with apt-get (which must pull every dependency the
# package declares), and renders the example scene with the installed rpict and rtrace.
#
#   sudo bash scripts/check-deb.sh build/radcl_0.1.0_amd64.deb [root-folder]
#
# Needs root, debootstrap and a Debian mirror (MIRROR, default deb.debian.org). Not a test:
# it downloads a whole system; run it when the packaging changes.
set -euo pipefail
deb=$(readlink -f "$1")
root=${2:-/tmp/radcl-deb-root}
mirror=${MIRROR:-http://deb.debian.org/debian}
[ -f "$deb" ] || { echo "check-deb: no package $deb" >&2; exit 1; }
if [ ! -x "$root/usr/bin/apt-get" ]; then
  rm -rf "$root"
  debootstrap --variant=minbase bookworm "$root" "$mirror"
fi
# What a booted machine has: PoCL reads the processor topology from /sys.
cleanup() { for m in dev/pts dev sys proc; do umount "$root/$m" 2>/dev/null || true; done; }
trap cleanup EXIT
mount -t proc proc "$root/proc"
mount --bind /sys "$root/sys"
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
cp "$deb" "$root/tmp/"
chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
  DEBIAN_FRONTEND=noninteractive bash -euc "
    apt-get update -qq
    apt-get install -y -qq /tmp/$(basename "$deb") > /tmp/apt.log
    echo 'installed: '\$(dpkg-query -W -f='\${Package} \${Version} \${Depends}' radcl)
    cd /tmp
    /opt/radcl/bin/rtrace -version
    /opt/radcl/bin/rpict -vf /opt/radcl/share/radcl/examples/room.vf -x 128 -y 96 -ab 1 -aa 0 \
      -ad 64 /opt/radcl/share/radcl/examples/room.rad > room.hdr
    head -c 400 room.hdr | grep -a -E '^(rpict|SOFTWARE|-Y)'
    echo '0.5 2.5 0.8 0 0 -1' | /opt/radcl/bin/rtrace -h -ab 1 -aa 0 -ad 64 \
      /opt/radcl/share/radcl/examples/room.rad
  "
echo "check-deb: $(basename "$deb") installs and renders on Debian 12 (bookworm)"
