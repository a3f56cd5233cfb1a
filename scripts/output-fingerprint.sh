#!/usr/bin/env bash
# Prints one SHA-256 per case of a fixed set of rtrace and rpict runs (every material family,
# the cache's build passes, -as, virtual sources, mist, BSDFs, rpict's adaptive sampling, ray
# trees). radcl's runs are repeatable, so two builds that print the same list give the same
# bytes: run it before and after a change that must not change any output, on each device.
#   scripts/output-fingerprint.sh [BIN_DIR] > fingerprint.txt   (BIN_DIR: build/bin)
# RADCL_DEVICE picks the device as for the programs themselves.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/bin}
sc=$root/tests/data/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# prism.cal is Radiance's: the shared reference folder holds it (RADCL_REFERENCE_SCENES).
ref=${RADCL_REFERENCE_SCENES:-$root/../shared/reference/scenes}
export RAYPATH=${RAYPATH:-.:$root/lib:$ref}
# rtrace's -u+ (its default) and rpict's take a seed from the clock unless RADCL_SEED fixes it.
export RADCL_SEED=${RADCL_SEED:-1}
cd "$sc"

case_() { # name, then the command; prints "sha256  name"
  local name=$1
  shift
  if ! "$@" > "$work/$name" 2> "$work/$name.err"; then
    echo "FAILED $name: $(head -c 300 "$work/$name.err")"
    return
  fi
  # A picture's header names the time it was made.
  echo "$(LC_ALL=C sed '1,/^$/{/^CAPDATE=/d;/^GMT=/d}' "$work/$name" | sha256sum | cut -c1-64)  $name"
}

rt=$bin/rtrace
rp=$bin/rpict
case_ office_aa0 "$rt" -h -I -ab 2 -aa 0 -ad 256 -lw 1e-3 office_clear.oct < office_grid.pts
case_ office_cache "$rt" -h -I -ab 2 office_clear.oct < office_grid.pts
case_ office_as "$rt" -h -I -ab 1 -aa .15 -ad 256 -as 128 office_overcast.oct < office_grid.pts
case_ office_frozen "$rt" -h -I -ab 1 -aa 0 -ad 64 office_clear_frozen.oct < office_grid.pts
case_ office_outputs "$rt" -h -otodLNnspM -ab 1 -aa 0 -ad 32 office_clear.oct < office_grid.pts
case_ office_trace "$rt" -h -otTv -ab 1 -aa 0 -ad 8 office_clear.oct < <(head -3 office_grid.pts)
case_ materials "$rt" -h -ab 1 -aa 0 -ad 64 materials.oct < materials_rays.txt
case_ materials_plain "$rt" -h -ab 2 -aa 0 -ad 32 materials_plain.oct < materials_rays.txt
case_ prism "$rt" -h -ab 1 prism.oct < prism_rays.txt
case_ mist "$rt" -h -ab 1 -aa 0 -ad 64 -me .02 .02 .02 -ma .5 .5 .5 mist.oct < mist_rays.txt
case_ bsdf "$rt" -h -ab 1 -aa 0 -ad 64 bsdf.oct < bsdf_rays.txt
case_ aniso "$rt" -h -ab 1 -aa 0 -ad 64 aniso.oct < aniso_rays.txt
case_ luminaires "$rt" -h -I -ab 2 -aa 0 -ad 128 luminaires.oct < luminaires_grid.pts
case_ luminaires_cache "$rt" -h -I -ab 2 -aa .1 -ad 512 luminaires.oct < luminaires_grid.pts
case_ sphere_cache "$rt" -h -I -ab 4 -aa .1 -ad 256 sphere.oct < sphere_wall.pts
case_ deep_plan "$rt" -h -I -ab 2 -aa 0 -ad 64 -lw 1e-4 deep_plan.rad < deep_plan_grid.pts
case_ room_rpict "$rp" -vf "$root/scenes/room.vf" -x 128 -y 96 -ab 1 -aa 0 -ad 64 "$root/scenes/room.rad"
case_ cornell_rpict "$rp" -vf cornell.vf -x 96 -y 96 -ab 1 cornell.oct
case_ glossy_rpict "$rp" -vtl -vp 0.05 0.05 0.5 -vd 0 0 -1 -vu 0 1 0 -vh 1.6 -vv 1.2 -x 64 -y 64 -ps 1 -u- -ab 1 -aa 0 -ad 16 glossy_plane.rad
case_ furnished_rpict "$rp" -vf office.vf -x 96 -y 72 -ab 1 -aa .2 -ad 128 furnished.oct
case_ chrome_rpict "$rp" -vtc -vp 0 0 0.5 -vd 1 0 0 -vu 0 0 1 -vh 360 -vv 50 -x 128 -y 26 -ab 0 chrome_figures.rad
case_ glow_rpict "$rp" -vp 0 0 10 -vd 0 0 -1 -vu 0 1 0 -x 96 -y 72 -ab 0 -ps 4 glow_pattern.rad
