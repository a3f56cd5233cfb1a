#!/bin/sh
# Annual daylight by daylight coefficients: the office of office_*.rad, a 24-sensor work plane
# (grid.pts) and the weather of sky.wea.  See README.md.
#
#   ./run.sh [results-folder]        (default: out/ next to this script)
#
# Needs on PATH: radcl's rcontrib (or Radiance's, to compare), and Radiance's oconv, gendaymtx,
# dctimestep and rmtxop.  Environment: WEA (weather file, default sky.wea), AD (-ad, default
# 1024), THRESH (lux for daylight autonomy, default 300), OCC_FROM/OCC_TO (occupied hours,
# default 8 to 18 local standard time).
set -e
here=$(cd "$(dirname "$0")" && pwd)
res=${1:-$here/out}
mkdir -p "$res"
res=$(cd "$res" && pwd)
if [ -n "$WEA" ]; then   # the caller's weather file, named from the caller's folder
  WEA=$(cd "$(dirname "$WEA")" && pwd)/$(basename "$WEA")
else
  WEA=$here/sky.wea
fi
cd "$here"
AD=${AD:-1024}
THRESH=${THRESH:-300}
OCC_FROM=${OCC_FROM:-8}
OCC_TO=${OCC_TO:-18}

for t in rcontrib gendaymtx dctimestep rmtxop; do
  command -v $t >/dev/null || { echo "run.sh: $t is not on PATH" >&2; exit 1; }
done
echo "rcontrib: $(command -v rcontrib) ($(rcontrib -version 2>&1 | head -n 1))"

# (a) the octree: radcl has no oconv of its own, so Radiance's is used when there is one.
# Without it radcl's rcontrib reads one .rad file directly (Radiance's rcontrib cannot).
if command -v oconv >/dev/null; then
  oconv office_mat.rad office_geom.rad office_desk.rad sky.rad > "$res/room.oct"
  scene="$res/room.oct"
else
  echo "run.sh: no oconv on PATH; giving rcontrib the scene as one .rad file" >&2
  cat office_mat.rad office_geom.rad office_desk.rad sky.rad > "$res/room.rad"
  scene="$res/room.rad"
fi

# (b) the daylight-coefficient matrix: one row per sensor, one RGB column per Reinhart patch
# (MF:1 gives 146: the ground, then 145 sky patches), binary float with a header.
t0=$(date +%s)
rcontrib -I -ab 2 -ad "$AD" -lw 1e-4 -faf -e MF:1 -f reinhart.cal -b rbin -bn Nrbins \
  -m skyglow "$scene" < grid.pts > "$res/dc.mtx"
t1=$(date +%s)
echo "rcontrib: $((t1 - t0)) s (whole seconds) for $(wc -l < grid.pts) sensors"

# (c) the sky matrix (146 patch radiances per time step of the weather file, sun included) and
# the illuminance: sensors x hours, RGB irradiance to lux by 179 lm/W.
gendaymtx -m 1 "$WEA" > "$res/sky.smx"
dctimestep "$res/dc.mtx" "$res/sky.smx" | rmtxop -fa -c 47.4 119.9 11.6 - > "$res/ill.mtx"

# (d) per sensor: mean illuminance and daylight autonomy (share of occupied hours at or above
# THRESH lux) over the occupied hours of the weather file.
awk -v thresh="$THRESH" -v from="$OCC_FROM" -v to="$OCC_TO" '
  FNR == NR { if (NF == 5 && $1 !~ /[a-z]/) { n++; occ[n] = ($3 >= from && $3 < to) } next }
  FILENAME == ARGV[2] { pt[++np] = $1 " " $2 " " $3; next }
  !body { if ($0 == "") body = 1; next }
  {
    row++; sum = 0; ok = 0; nocc = 0
    for (j = 1; j <= NF; j++) if (occ[j]) { nocc++; sum += $j; if ($j >= thresh) ok++ }
    if (!nocc) { print "run.sh: no occupied hours in the weather file" > "/dev/stderr"; exit 1 }
    mean = sum / nocc; da = 100 * ok / nocc
    printf "%-14s %10.0f %8.0f\n", pt[row], mean, da
    tmean += mean; tda += da
  }
  END {
    printf "%-14s %10.0f %8.0f\n", "all sensors", tmean / row, tda / row
    printf "(%d sensors, %d occupied hours from %g to %g h; DA: %% of them with E >= %g lux)\n", row, nocc, from, to, thresh
  }' "$WEA" grid.pts "$res/ill.mtx" > "$res/summary.txt.tmp"
{
  printf "%-14s %10s %8s\n" "sensor x y z" "mean lux" "DA %"
  cat "$res/summary.txt.tmp"
} > "$res/summary.txt"
rm -f "$res/summary.txt.tmp"
cat "$res/summary.txt"
echo "results in $res: dc.mtx (coefficients), sky.smx (sky matrix), ill.mtx (lux, sensors x hours)"
