#!/usr/bin/env bash
# radcl against Radiance, side by side in one go on one machine, on the cases a user runs:
#   P1  office_clear, a workplane grid (100,000 points; --small: 10,000) at the default
#       settings -ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3 (irradiance cache)
#   P2  office_clear, 10,000 points (--small: 2,000) at -ab 2 -aa 0 -ad 1024 -lw 1e-4 (no cache)
#   P3  rpict office_view 1024^2 (--small: 512^2) at -ab 2 -ad 1024 -as 256 -aa 0.15 -ar 128,
#       against Radiance's rpict and against vwrays -ff | rtrace -n N -ffc
#   P4  an open-plan floor of 60 furnished office bays (instances; 1.19 million plant-mesh
#       triangles placed), 10,000 points at the default settings (needs Radiance's oconv;
#       not in --small)
#   P5  the integrating sphere at -ab 8 (-ad 1024 -as 256 -aa 0.1 -ar 64 -lw 1e-5)
# Radiance runs with -n set to every core. Grids are generated here. Errors: P1 on its first
# 77 points (office_grid.pts) against the converged -ab 5 answer (tests/data/results/
# office_clear_mc5.txt), P5 against the sphere's exact answer; where no converged answer exists
# (P2, P3, P4) the two renderers' mean difference is shown instead. Times are warm: each
# scene's device program is compiled (and cached) by a one-point run first, which is not timed.
#
# Writes docs/bench/peers.md (--small: docs/bench/peers_2core.md) with the table, the machine,
# the date and the commit, and a bar chart of the speed-ups (peers.svg / peers_2core.svg), from
# the rows it also writes as peers.tsv / peers_2core.tsv.
#
# usage: RADIANCE_BIN=/path/to/radiance/bin tests/bench/peers.sh [--small] [build-dir]
#   RADIANCE_LIB: Radiance's library folder for its RAYPATH (default: $RADIANCE_BIN/../lib)
#   PEERS_OUT: folder for the .md and .svg (default: docs/bench)
#   PEERS_CASES: the cases to run (default "P1 P2 P3 P4 P5"; P4 is skipped with --small)
#   PEERS_LABEL: appended to each case's name (e.g. "PoCL" for a run with radcl on the CPU)
#   PEERS_REPEAT: runs of each command, the fastest counted (default 1; on a shared virtual
#     machine whose times swing by a third from run to run, 3 gives steadier ratios)
# Each run leaves its rows in $PEERS_OUT/peers.tsv; tests/bench/peers_report.sh merges several
# runs' files into one table and chart.
set -euo pipefail
small=0
if [ "${1:-}" = --small ]; then
  small=1
  shift
fi
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
[ -n "${RADIANCE_BIN:-}" ] || { echo "peers.sh: set RADIANCE_BIN to Radiance's bin/" >&2; exit 1; }
rbin=$(cd "$RADIANCE_BIN" && pwd)
rlib=${RADIANCE_LIB:-$rbin/../lib}
cores=$(nproc)
scenes=$root/tests/data/scenes
results=$root/tests/data/results
outdir=${PEERS_OUT:-$root/docs/bench}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck source=tests/bench/sensor_errors.sh
. "$root/tests/bench/sensor_errors.sh"

if [ $small = 1 ]; then n1=10000 n2=2000 res=512 tag=peers_2core; else n1=100000 n2=10000 res=1024 tag=peers; fi
default="-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3"
nocache="-ab 2 -aa 0 -ad 1024 -lw 1e-4"
picture="-ab 2 -ad 1024 -as 256 -aa 0.15 -ar 128"
sphere="-ab 8 -ad 1024 -as 256 -aa 0.1 -ar 64 -lw 1e-5"

# grid N x0 x1 y0 y1 z: about N upward points on a regular grid over the rectangle.
grid() {
  awk -v n="$1" -v x0="$2" -v x1="$3" -v y0="$4" -v y1="$5" -v z="$6" 'BEGIN {
    a = (x1 - x0) / (y1 - y0); nx = int(sqrt(n * a) + 0.5); ny = int(n / nx + 0.5)
    for (j = 0; j < ny; j++) for (i = 0; i < nx; i++)
      printf "%.4f %.4f %g 0 0 1\n", x0 + (i + 0.5) * (x1 - x0) / nx, y0 + (j + 0.5) * (y1 - y0) / ny, z }'
}
# The reference sensors first (for the errors), then the generated grid.
cat "$scenes/office_grid.pts" > "$work/p1.pts"
grid $((n1 - 77)) 0.1 5.9 0.1 3.9 0.8 >> "$work/p1.pts"
cat "$scenes/office_grid.pts" > "$work/p2.pts"
grid $((n2 - 77)) 0.1 5.9 0.1 3.9 0.8 >> "$work/p2.pts"

repeat=${PEERS_REPEAT:-1}
secs() { awk '/^[0-9.]+$/ { t = $1 } END { print t }' "$1"; }
least() { printf '%s\n' "$@" | sort -g | head -n 1; }
# radcl dir input output program args... : prints seconds (the fastest of $repeat runs)
radcl() {
  local dir=$1 in=$2 out=$3 prog=$4 k ts=()
  shift 4
  for ((k = 0; k < repeat; k++)); do
    ( cd "$dir" && /usr/bin/time -f "%e" "$build/bin/$prog" "$@" < "$in" > "$out" 2> "$work/err" ) ||
      { cat "$work/err" >&2; exit 1; }
    ts+=("$(secs "$work/err")")
  done
  least "${ts[@]}"
}
radiance() {
  local dir=$1 in=$2 out=$3 prog=$4 k ts=()
  shift 4
  for ((k = 0; k < repeat; k++)); do
    ( cd "$dir" && RAYPATH=.:$rlib /usr/bin/time -f "%e" "$rbin/$prog" "$@" < "$in" > "$out" \
        2> "$work/err" ) || { cat "$work/err" >&2; exit 1; }
    ts+=("$(secs "$work/err")")
  done
  least "${ts[@]}"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
# Mean relative difference of the luminances in two value files (rgb per line).
differ() { errs "$1" "$2" | awk '{ print $1 }'; }
# Mean luminance of a picture (radcl's picture reader).
lum() { "$build/bin/bench_picture_mean" "$1"; }
warm() { # dir octree options...: compiles the scene's program for these options (with the
  # cache or without, the kernels differ), on one sensor
  local dir=$1 oct=$2
  shift 2
  ( cd "$dir" && head -n 1 "$work/p2.pts" | "$build/bin/rtrace" -h -I "$@" "$oct" > /dev/null )
}
# sensors case dir points octree options...: both renderers' rtrace -I over the points after a
# warm-up; sets t and r (seconds), the values in $work/c<case>.txt and $work/r<case>.txt.
sensors() {
  local c=$1 dir=$2 pts=$3 oct=$4
  shift 4
  warm "$dir" "$oct" "$@"
  t=$(radcl "$dir" "$pts" "$work/c$c.txt" rtrace -n "$cores" -h -I "$@" "$oct")
  r=$(radiance "$dir" "$pts" "$work/r$c.txt" rtrace -n "$cores" -h -I "$@" "$oct")
}

cases=${PEERS_CASES:-P1 P2 P3 P4 P5}
want() { [[ " $cases " == *" $1 "* ]]; }
rows=()
add() { rows+=("$(printf '%s\t' "$@")"); printf '%-4s %-46s %9s %9s %7sx  %-16s %-16s\n' "$@"; }
printf '%-4s %-46s %9s %9s %8s  %-16s %-16s\n' case what radcl_s radiance_s speedup "radcl err" \
  "Radiance err"

# P1
if want P1; then
sensors 1 "$scenes" "$work/p1.pts" office_clear.oct $default
head -n 77 "$work/c1.txt" > "$work/c1h.txt"
head -n 77 "$work/r1.txt" > "$work/r1h.txt"
add P1 "office_clear, $n1 points, cache" "$t" "$r" "$(ratio "$r" "$t")" \
  "$(errs "$work/c1h.txt" "$results/office_clear_mc5.txt")" \
  "$(errs "$work/r1h.txt" "$results/office_clear_mc5.txt")"
fi

# P2
if want P2; then
sensors 2 "$scenes" "$work/p2.pts" office_clear.oct $nocache
add P2 "office_clear, $n2 points, -aa 0" "$t" "$r" "$(ratio "$r" "$t")" \
  "differ $(differ "$work/c2.txt" "$work/r2.txt")" "(no converged)"
fi

# P3: rpict, and vwrays | rtrace -n N -ffc
if want P3; then
( cd "$scenes" && "$build/bin/rpict" -vf office.vf -x 16 -y 16 $picture office_clear.oct > /dev/null )
t=$(radcl "$scenes" /dev/null "$work/c3.hdr" rpict -vf office.vf -x "$res" -y "$res" $picture office_clear.oct)
r=$(radiance "$scenes" /dev/null "$work/r3.hdr" rpict -vf office.vf -x "$res" -y "$res" $picture office_clear.oct)
vres=$(cd "$scenes" && "$rbin/vwrays" -d -vf office.vf -x "$res" -y "$res")
vs=()
for ((k = 0; k < repeat; k++)); do
  vs+=("$( ( cd "$scenes" && RAYPATH=.:$rlib /usr/bin/time -f "%e" bash -c \
    "'$rbin/vwrays' -ff -vf office.vf -x $res -y $res | '$rbin/rtrace' -n $cores -ffc $vres $picture office_clear.oct > '$work/v3.hdr'" ) 2>&1 | tail -n 1)")
done
v=$(least "${vs[@]}")
dc=$(awk -v a="$(lum "$work/c3.hdr")" -v b="$(lum "$work/r3.hdr")" 'BEGIN { printf "%.2f%%", 100 * (a - b) / b }')
add P3 "rpict office_view ${res}^2 vs rpict" "$t" "$r" "$(ratio "$r" "$t")" "mean $dc" "(no converged)"
add P3v "rpict office_view ${res}^2 vs vwrays + rtrace -n $cores" "$t" "$v" "$(ratio "$v" "$t")" "" ""
fi

# P4: the open-plan floor (Radiance's oconv makes the octrees both renderers read).
if [ $small = 0 ] && want P4; then
  op=$work/openplan
  "$root/tests/bench/openplan_scene.sh" "$build/bin" "$scenes" "$rbin" "$rlib" "$op"
  grid 10000 0.2 59.8 0.2 23.8 0.8 > "$work/p4.pts"
  sensors 4 "$op" "$work/p4.pts" openplan.oct $default
  add P4 "open-plan floor, 1.19M triangles, 10000 pts" "$t" "$r" "$(ratio "$r" "$t")" \
    "differ $(differ "$work/c4.txt" "$work/r4.txt")" "(no converged)"
fi

# P5
if want P5; then
sensors 5 "$scenes" "$scenes/sphere_wall.pts" sphere.oct $sphere
exact=$(awk '$1 == 8 { print $2 }' "$results/sphere_exact.txt")
serr() { awk -v x="$exact" '{ s += $1; n++ } END { printf "%+.2f%%", 100 * (s / n - x) / x }' "$1"; }
add P5 "integrating sphere, -ab 8" "$t" "$r" "$(ratio "$r" "$t")" "$(serr "$work/c5.txt")" \
  "$(serr "$work/r5.txt")"
fi

# The record: the rows as TSV (with a line describing this run), then the table and chart.
commit=${PEERS_COMMIT:-$(git -C "$root" rev-parse --short HEAD 2> /dev/null || echo unknown)}
cpu=$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)
device=$("$build/bin/radcl" devices 2> /dev/null | awk '/^\*/ { $1 = ""; print; exit }' | sed 's/^ *//')
mkdir -p "$outdir"
{
  echo "# run: $(date -u +%Y-%m-%d), radcl at commit $commit on ${device:-an unknown device}" \
    "($cores cores: $cpu), against $("$rbin/rtrace" -version | head -n 1) with -n $cores" \
    "$([ $small = 1 ] && echo '(--small)')${PEERS_LABEL:+ [$PEERS_LABEL]}$([ "$repeat" -gt 1 ] && echo ", fastest of $repeat runs each")"
  for row in "${rows[@]}"; do
    printf '%s\n' "$row" | awk -F'\t' -v l="${PEERS_LABEL:-}" 'BEGIN { OFS = "\t" }
      { if (l != "") $1 = $1 "/" l; print }'
  done
} > "$outdir/$tag.tsv"
title="radcl and Radiance side by side$([ $small = 1 ] && echo ', 2-core mode')"
"$root/tests/bench/peers_report.sh" "$outdir/$tag" "$title" "$outdir/$tag.tsv"
