#!/usr/bin/env bash
# Pixels per second of radcl's rpict on the deterministic direct-light views, at 256^2 and
# 1024^2 (or the reference's own size), against Radiance 5.4a's single-process times stored in
# the reference set (radiance_times.tsv, one run each on a 2-core machine like this one), scaled
# by the number of pixels. Radiance is not run here.
#
# usage: tests/bench/rpict_pixels.sh [build-dir] [sizes...]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
shift || true
sizes=${*:-"256 1024"}
scenes=$root/tests/data/scenes
times=${RADCL_REFERENCE:-$root/../shared/reference}/results/radiance_times.tsv
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
direct="-ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1 -ps 1"

ref_time() { awk -F'\t' -v n="$1" '$1 == n { print $2 }' "$times"; }

# name view octree reference-name reference-pixels
cases=("cornell_ab0_view cornell.vf cornell.oct cornell_ab0_view 65536"
       "materials_plain_view_ab0 materials.vf materials_plain.oct materials_plain_view_ab0 92928")
printf '%-26s %11s %9s %10s %12s %12s %8s\n' case size pixels radcl_s radiance_s pixels/s speedup
for c in "${cases[@]}"; do
  read -r name vf oct ref refpix <<< "$c"
  rt=$(ref_time "$ref")
  # Warm the program cache.
  ( cd "$scenes" && "$build/bin/rpict" -vf "$vf" -x 16 -y 16 $direct "$oct" > /dev/null )
  for s in $sizes; do
    out=$work/$name-$s.hdr
    secs=$( { cd "$scenes" && /usr/bin/time -f "%e" "$build/bin/rpict" -vf "$vf" -x "$s" -y "$s" \
               $direct -o "$out" "$oct"; } 2>&1 | tail -n 1 )
    px=$(awk 'NR > 1 && /^-Y/ { print $2 * $4; exit }' "$out" 2>/dev/null || true)
    [ -n "$px" ] || px=$(head -c 2000 "$out" | strings | awk '/^-Y/ { print $2 * $4; exit }')
    rad=$(awk -v t="$rt" -v p="$px" -v r="$refpix" 'BEGIN { printf "%.2f", t * p / r }')
    printf '%-26s %11s %9d %10s %12s %12.0f %7.1fx\n' "$name" "${s}^2" "$px" "$secs" "$rad" \
      "$(awk -v p="$px" -v s="$secs" 'BEGIN { print p / s }')" \
      "$(awk -v a="$rad" -v b="$secs" 'BEGIN { print a / b }')"
  done
done
