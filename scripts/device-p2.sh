#!/usr/bin/env bash
# Device-side study of the no-cache case (peers P2): the phases of radcl's run on the GPU and on
# PoCL over every core, with chunk and generation sizes varied (P2_VARIANTS on the GPU,
# P2_POCL_VARIANTS on PoCL: lists of NAME=value settings, "base" for none), and Embree's own
# rate on its rays.
# Run by scripts/device-run.sh sh (DEVICE_SH='bash scripts/device-p2.sh').
set -uo pipefail
scenes=$RADCL_TEST_DATA/scenes
w=/tmp/p2w
mkdir -p "$w"
awk -v n=9923 'BEGIN { x0 = 0.1; x1 = 5.9; y0 = 0.1; y1 = 3.9; z = 0.8
  a = (x1 - x0) / (y1 - y0); nx = int(sqrt(n * a) + 0.5); ny = int(n / nx + 0.5)
  for (j = 0; j < ny; j++) for (i = 0; i < nx; i++)
    printf "%.4f %.4f %g 0 0 1\n", x0 + (i + 0.5) * (x1 - x0) / nx, y0 + (j + 0.5) * (y1 - y0) / ny, z }' > "$w/p2.pts"
cat "$scenes/office_grid.pts" "$w/p2.pts" > "$w/p2all.pts"
opts="-ab 2 -aa 0 -ad 1024 -lw 1e-4"
one() { # label, env..., then runs radcl rtrace on the P2 points
  local label=$1
  shift
  echo "== $label"
  (cd "$scenes" && env RADCL_PROFILE=1 "$@" /usr/bin/time -f "%e s wall, %U s user, %S s sys" \
    "$RADCL_BIN/rtrace" -n "$(nproc)" -h -u- -I+ $opts office_clear.oct < "$w/p2all.pts" > /dev/null)
}
one warm RADCL_DEVICE=nvidia 2>&1 | tail -1
variants() { # device label settings...: one run per setting ("base": none)
  local dev=$1 label=$2 v
  shift 2
  for v in "$@"; do
    if [ "$v" = base ]; then one "$label $v" RADCL_DEVICE=$dev 2>&1; else one "$label $v" RADCL_DEVICE=$dev "$v" 2>&1; fi
  done
}
variants nvidia gpu ${P2_VARIANTS:-"base" "RADCL_CHUNK_RAYS=1048576" "RADCL_GENERATION_RAYS=16777216" "RADCL_NO_OVERLAP=1"}
one "gpu waves" RADCL_DEVICE=nvidia RADCL_PROFILE=waves 2>&1 | tail -25
# PoCL over every core: its generations default to 2^18 rays (a batch of about 29 of these
# primaries), which may leave many cores idle at each batch's first generations and its last.
one "pocl warm" RADCL_DEVICE=pocl 2>&1 | tail -1
variants pocl pocl ${P2_POCL_VARIANTS:-"base" "RADCL_GENERATION_RAYS=1048576" "RADCL_GENERATION_RAYS=4194304"}
echo "== embree"
(cd "$scenes" && "$RADCL_BIN/bench_embree_rays" office_clear.oct office_grid.pts 2>&1 | tail -20)
