#!/usr/bin/env bash
# Rays per second of radcl's rtrace on the reference scenes, with 1 and 2 host threads, against
# Radiance 5.4a's single-process times stored in the reference set (radiance_times.tsv: one
# run each on a 2-core machine like this one). Radiance is not run here: its time per sensor or
# ray is taken from the stored run (which includes its start-up, so it slightly favours radcl
# on tiny inputs) and scaled to the same number of rays.
#
# usage: tests/bench/rtrace_rays.sh [build-dir] [sensor-points] [camera-rays]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
npts=${2:-100000}
nrays=${3:-1000000}
scenes=$root/tests/data/scenes
times=${RADCL_REFERENCE:-$root/../shared/reference}/results/radiance_times.tsv
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

ref_time() { awk -F'\t' -v n="$1" '$1 == n { print $2 }' "$times"; }

# Sensor grid over the luminaires room's workplane (8 x 6 m at 0.75 m), facing up.
awk -v n="$npts" 'BEGIN { nx = int(sqrt(n * 8 / 6)); ny = int(n / nx);
  for (j = 0; j < ny; j++) for (i = 0; i < nx; i++)
    printf "%.5f %.5f 0.75 0 0 1\n", (i + 0.5) * 8 / nx, (j + 0.5) * 6 / ny }' > "$work/grid.pts"
npts=$(wc -l < "$work/grid.pts")
# Camera rays: vwrays' 160 rays of materials.vf repeated.
reps=$(( (nrays + 159) / 160 ))
for ((k = 0; k < reps; k++)); do cat "$scenes/materials_rays.txt"; done | head -n "$nrays" > "$work/cam.txt"
nrays=$(wc -l < "$work/cam.txt")

run() { # name n-threads args... ; prints seconds and the stats line
  local name=$1 threads=$2 input=$3; shift 3
  ( cd "$scenes" && RADCL_STATS=1 /usr/bin/time -f "%e" "$build/bin/rtrace" -n "$threads" "$@" \
      < "$input" > /dev/null 2> "$work/$name.err" ) || { cat "$work/$name.err"; exit 1; }
  local secs stats
  secs=$(tail -n 1 "$work/$name.err")
  stats=$(grep 'rays/s' "$work/$name.err" | sed 's/^rtrace: //')
  echo "$secs|$stats"
}

# Warm the program cache so compile time is not measured.
( cd "$scenes" && head -n 3 "$work/grid.pts" | "$build/bin/rtrace" -h -I -ab 0 luminaires.oct > /dev/null )
( cd "$scenes" && head -n 3 "$work/cam.txt" | "$build/bin/rtrace" -h -ab 0 materials_plain.oct > /dev/null )

printf '%-34s %8s %7s %12s %12s %9s\n' case rays threads radcl_s radiance_s speedup
lum_ref=$(ref_time luminaires_ab0)
cam_ref=$(ref_time materials_plain_rays_v)
for threads in 1 2; do
  r=$(run lum$threads "$threads" "$work/grid.pts" -h -I -ab 0 -dj 0 -ds 0.01 -dt 0 -dc 1 luminaires.oct)
  secs=${r%%|*}
  rad=$(awk -v t="$lum_ref" -v n="$npts" 'BEGIN { printf "%.2f", t * n / 52 }')
  printf '%-34s %8d %7d %12s %12s %8.1fx   %s\n' "luminaires_ab0 (sensors)" "$npts" "$threads" \
    "$secs" "$rad" "$(awk -v a="$rad" -v b="$secs" 'BEGIN { print a / b }')" "${r#*|}"
  r=$(run cam$threads "$threads" "$work/cam.txt" -h -ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1 -ov materials_plain.oct)
  secs=${r%%|*}
  rad=$(awk -v t="$cam_ref" -v n="$nrays" 'BEGIN { printf "%.2f", t * n / 160 }')
  printf '%-34s %8d %7d %12s %12s %8.1fx   %s\n' "materials_plain_rays_v (camera)" "$nrays" \
    "$threads" "$secs" "$rad" "$(awk -v a="$rad" -v b="$secs" 'BEGIN { print a / b }')" "${r#*|}"
done
