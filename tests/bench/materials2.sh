#!/usr/bin/env bash
# The second-wave material scenes (issue 33: `aniso`: plastic2, metal2, trans2, ashik2;
# `prism`: prism1, prism2, whose prism.cal is Radiance's and is found on RAYPATH: put the
# reference scenes folder in RADIANCE_LIB; `mist_global`: the global medium -me/-ma/-mg;
# `bsdf`: BSDF and aBSDF windows and a BSDF tile; `mist`: mist volumes with source lists, at
# the reference's -ms 0.05) timed against Radiance side by side in one
# go: the sensor grid at the default settings
# (-ab 5 with the cache), the camera rays at -ab 1 -aa 0 -ad 2048 and rpict's reference view
# (256 x 192, -ab 1 -ad 1024 -as 256 -aa 0.1 -ar 64 -ps 1). Radiance's rtrace runs with -n set
# to the threads given (its rpict: one process; radcl's uses every core). Each time is the
# fastest of BENCH_REPEAT (default 3) runs, after a warm-up that compiles radcl's programs. Prints seconds and Radiance / radcl ratios.
#
# usage: RADIANCE_BIN=... tests/bench/materials2.sh [build-dir] [threads]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
threads=${2:-$(nproc)}
repeat=${BENCH_REPEAT:-3}
: "${RADIANCE_BIN:?set RADIANCE_BIN to the bin folder of Radiance}"
export RAYPATH=.:${RADIANCE_LIB:-$RADIANCE_BIN/../lib}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$root/tests/data/scenes"

best() { # command...: the fastest of $repeat runs, in seconds
  local k t b=
  for ((k = 0; k < repeat; k++)); do
    t=$(/usr/bin/time -f %e bash -c "$* > /dev/null 2>&1" 2>&1 | tail -1)
    if [ -z "$b" ] || awk -v a="$t" -v b="$b" 'BEGIN { exit !(a < b) }'; then b=$t; fi
  done
  echo "$b"
}

def="-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3"
aa0="-ab 1 -aa 0 -ad 2048 -lw 1e-5"
printf '%-34s %9s %9s %7s\n' case radcl Radiance ratio
row() { # label radcl-command radiance-command
  local a b
  a=$(best "$2")
  b=$(best "$3")
  printf '%-34s %8.2fs %8.2fs %6.2fx\n' "$1" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { print b / a }')"
}
# scene: label octree file-prefix extra-options
for c in "aniso aniso.oct aniso" "prism prism.oct prism" \
  "mist_global mist_nomist.oct mist -me 0.03 0.03 0.04 -ma 0.8 0.8 0.8 -mg 0.3" \
  "bsdf bsdf.oct bsdf" "mist mist.oct mist -ms 0.05"; do
  read -r s oct f extra <<< "$c"
  n=$(wc -l < "${f}_grid.pts")
  view="-vf $f.vf -x 256 -y 192 -ab 1 -ad 1024 -as 256 -aa 0.1 -ar 64 -ps 1 $extra"
  "$build/bin/rtrace" -h -I $def $extra $oct < ${f}_grid.pts > /dev/null # warm-up
  "$build/bin/rtrace" -h $aa0 $extra $oct < ${f}_rays.txt > /dev/null
  "$build/bin/rpict" $view $oct > /dev/null
  row "$s grid ($n), defaults" "$build/bin/rtrace -n $threads -h -I $def $extra $oct < ${f}_grid.pts" \
    "$RADIANCE_BIN/rtrace -n $threads -h -I $def $extra $oct < ${f}_grid.pts"
  row "$s rays (192), -ab 1 -aa 0" "$build/bin/rtrace -n $threads -h $aa0 $extra $oct < ${f}_rays.txt" \
    "$RADIANCE_BIN/rtrace -n $threads -h $aa0 $extra $oct < ${f}_rays.txt"
  row "$s view 256x192 (rpict)" "$build/bin/rpict $view $oct" "$RADIANCE_BIN/rpict $view $oct"
done
echo "($(nproc) cores, $threads threads, fastest of $repeat runs each)"
