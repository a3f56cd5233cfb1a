#!/usr/bin/env bash
# radcl's rcontrib against Radiance's, side by side in one go on one machine (issue 57), on
# office_clear's room with a grid of SENSORS upward sensors over the floor at 0.8 m:
#   sky   Honeybee's annual daylight-coefficient command, in its direct rcontrib form:
#           rcontrib -aa 0 -ab 2 -ad 5000 -lw 2e-5 -c 1 -faf -I -y N -e MF:1 -f reinhart.cal
#             -b rbin -bn Nrbins -m skyglow office_dome.oct
#         (a Reinhart MF:1 sky, 146 bins). Both are Monte Carlo, and a sensor's sum over the bins
#         varies by several percent from one Radiance run to the next at these settings: Radiance
#         runs a second time for that scale. The matrices agree when radcl's sensor sums differ
#         from Radiance's by no more than 1.5 times as much on average as Radiance's two runs do
#         from each other, and by under 1% in the mean signed difference
#   sky-rf  the same through Radiance's rfluxmtx as Honeybee runs it (with RADIANCE_BIN's
#         rfluxmtx; radcl's side has radcl's rcontrib first on PATH):
#           rfluxmtx -aa 0 -ab 2 -ad 5000 -lw 2e-5 -c 1 -faf -I -y N - sky.dome -i room.oct
#   sun   the direct-sun matrix of SUNS suns (unit radiance, 0.533 degrees, spread evenly over
#         the sky above the horizon, each its own modifier):
#           rcontrib -aa 0 -I -faf -ab 0 -dc 1 -dt 0 -dj 0 -M suns.mod suns.oct
#         (deterministic: the matrices agree when every number is within 1e-3 relative or
#         1e-9 absolute)
# Both run with -n THREADS. radcl runs on the device RADCL_DEVICE names (radcl's default when
# unset) and is timed warm: an untimed run over the same input first compiles and caches the
# device programs (PoCL also builds kernels for each new launch size). The timed run has
# RADCL_PROFILE=1; its phase breakdown is printed. Then one more run with RADCL_PROFILE=raw
# (RADCL_NO_OVERLAP=1) gives bare Embree's time on the very rays the trace phase traced. The sun
# case's rays are all shadow rays, which no tool replays through bare Embree: it says so.
# Scratch (the suns, octrees made by Radiance's oconv, the matrices) in mktemp -d.
#
# usage: RADIANCE_BIN=/path/to/radiance/bin tests/bench/rcontrib.sh [build-dir] [threads]
#   RADIANCE_LIB: Radiance's library folder for its RAYPATH (default: $RADIANCE_BIN/../lib)
#   SENSORS: sensors in the grid (default 10000); SUNS: suns (default 5000)
#   RC_CASES: the cases (default "sky sky-rf sun")
#   RC_REPEAT: timed runs of each command, the fastest counted (default 1)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
threads=${2:-$(nproc)}
[ -n "${RADIANCE_BIN:-}" ] || { echo "rcontrib.sh: set RADIANCE_BIN to Radiance's bin/" >&2; exit 1; }
rbin=$(cd "$RADIANCE_BIN" && pwd)
rlib=${RADIANCE_LIB:-$rbin/../lib}
sensors=${SENSORS:-10000}
nsuns=${SUNS:-5000}
cases=${RC_CASES:-sky sky-rf sun}
repeat=${RC_REPEAT:-1}
scenes=$root/tests/data/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Exactly $sensors points on a regular grid over the floor (0.1 m in from the walls), facing up.
awk -v n="$sensors" 'BEGIN { x0 = 0.1; x1 = 5.9; y0 = 0.1; y1 = 3.9
  nx = int(sqrt(n * (x1 - x0) / (y1 - y0)) + 0.5); if (nx < 1) nx = 1; ny = int((n + nx - 1) / nx)
  for (k = 0; k < n; k++) { i = k % nx; j = int(k / nx)
    printf "%.4f %.4f 0.8 0 0 1\n", x0 + (i + 0.5) * (x1 - x0) / nx, y0 + (j + 0.5) * (y1 - y0) / ny } }' \
  > "$work/grid.pts"

# Honeybee's sky receiver: ground glow (one bin), sky glow in Reinhart MF:1 (145 bins).
cat > "$work/sky.dome" << 'EOF'
#@rfluxmtx h=u u=Y
void glow ground_glow
0
0
4 1 1 1 0

ground_glow source ground
0
0
4 0 0 -1 180

#@rfluxmtx h=r1 u=Y
void glow sky_glow
0
0
4 1 1 1 0

sky_glow source sky
0
0
4 0 0 1 180
EOF
# The suns: a Fibonacci spiral over the upper hemisphere (even in solid angle).
awk -v n="$nsuns" -v mod="$work/suns.mod" 'BEGIN { ga = 3.14159265358979 * (3 - sqrt(5))
  for (k = 1; k <= n; k++) { z = (k - 0.5) / n; r = sqrt(1 - z * z); p = k * ga
    printf "void light solar%d\n0\n0\n3 1 1 1\n\nsolar%d source sun%d\n0\n0\n4 %.6f %.6f %.6f 0.533\n\n",
      k, k, k, r * cos(p), r * sin(p), z
    print "solar" k > mod } }' > "$work/suns.rad"
# Frozen octrees (they are read from the scratch folder): the room, and the room with the suns.
(cd "$scenes" && "$rbin/oconv" -f office_mat.rad office_geom.rad office_desk.rad) > "$work/room.oct"
(cd "$scenes" && "$rbin/oconv" -f office_mat.rad office_geom.rad office_desk.rad "$work/suns.rad") \
  > "$work/suns.oct"
# rfluxmtx runs "rcontrib" from PATH: radcl's side finds radcl's first.
mkdir -p "$work/radcl-path"
ln -s "$build/bin/rcontrib" "$work/radcl-path/rcontrib"

secs() { awk '/^[0-9.]+$/ { t = $1 } END { print t }' "$1"; }
least() { printf '%s\n' "$@" | sort -g | head -n 1; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
# run side dir input output command...: the fastest of $repeat timed runs, in seconds; radcl's
# side is warmed first and profiled (its last timed run's profile in $work/profile).
run() {
  local side=$1 dir=$2 in=$3 out=$4 k ts=() env=()
  shift 4
  if [ "$side" = radcl ]; then
    env=(RAYPATH=".:$root/lib" PATH="$work/radcl-path:$rbin:$PATH")
    ( cd "$dir" && env "${env[@]}" "$@" < "$in" > /dev/null 2> "$work/err" ) ||
      { echo "rcontrib.sh: radcl failed (warm-up) in $dir: $*" >&2; cat "$work/err" >&2; exit 1; }
    env+=(RADCL_PROFILE=1)
  else
    env=(RAYPATH=".:$rlib" PATH="$rbin:$PATH")
  fi
  for ((k = 0; k < repeat; k++)); do
    ( cd "$dir" && env "${env[@]}" /usr/bin/time -f "%e" "$@" < "$in" > "$out" 2> "$work/err" ) ||
      { echo "rcontrib.sh: $side failed in $dir: $*" >&2; cat "$work/err" >&2; exit 1; }
    ts+=("$(secs "$work/err")")
  done
  if [ "$side" = radcl ]; then grep "^profile:" "$work/err" > "$work/profile" || true; fi
  least "${ts[@]}"
}
# floats file rows cols: the matrix's numbers (the last rows x cols x 3 floats of the file,
# after its header), one bin's three per line.
floats() { tail -c $(($2 * $3 * 12)) "$1" | od -v -An -tf4 -w12; }
# Each sensor's sum over the bins (luminance weights) in two matrices: "mean% max% over5
# signed% n" of (a - b) / b: the mean of its size, the largest, how many over 5%, its mean.
sums_differ() {
  local rows=$3 cols=$4 f
  for f in "$1" "$2"; do
    floats "$f" "$rows" "$cols" | awk -v c="$cols" '
      { s += 0.265 * $1 + 0.670 * $2 + 0.065 * $3 } NR % c == 0 { print s; s = 0 }' > "$f.sums"
  done
  paste "$1.sums" "$2.sums" | awk '$2 > 0 { d = ($1 - $2) / $2; a = d < 0 ? -d : d; n++; t += a
      u += d; if (a > m) m = a; if (a > 0.05) o++ }
    END { printf "%.2f %.2f %d %+.2f %d", 100 * t / n, 100 * m, o, 100 * u / n, n }'
}
# Every number within 1e-3 relative or 1e-9 absolute: "numbers lit bad worst-relative".
all_differ() {
  paste <(floats "$1" "$3" "$4") <(floats "$2" "$3" "$4") | awk '
    { for (j = 1; j <= 3; j++) { a = $j; b = $(j + 3); d = a - b; d = d < 0 ? -d : d
        m = b < 0 ? -b : b; n++; lit += m > 0
        if (d > 1e-3 * m && d > 1e-9) bad++; if (m > 0 && d / m > w) w = d / m } }
    END { printf "%d %d %d %.1e", n, lit, bad, w }'
}
# raw dir command...: bare Embree on the trace phase's rays (RADCL_PROFILE=raw).
raw() {
  local dir=$1
  shift
  ( cd "$dir" && env RAYPATH=".:$root/lib" PATH="$work/radcl-path:$rbin:$PATH" RADCL_PROFILE=raw \
      RADCL_NO_OVERLAP=1 "$@" < "$work/grid.pts" > /dev/null 2> "$work/raw" ) ||
    { echo "rcontrib.sh: radcl failed (RADCL_PROFILE=raw): $*" >&2; cat "$work/raw" >&2; exit 1; }
  grep 'raw embree' "$work/raw" | sed 's/^profile: *raw embree */Embree alone /' || true
}

# sky_row case what radcl-matrix radiance-matrix: the table row in $row (t and r the times;
# noise from the sky case's two Radiance runs, when it ran).
sky_row() {
  local mean max over bias n ok=NO
  read -r mean max over bias n <<< "$(sums_differ "$3" "$4" "$sensors" 146)"
  if [ -z "${noise:-}" ]; then
    ok="(no Radiance noise figure: run the sky case too)"
  elif awk -v m="$mean" -v z="$noise" -v b="$bias" 'BEGIN { exit !(m <= 1.5 * z && b < 1 && b > -1) }'; then
    ok=yes
  fi
  row="| $2 | $t | $r | $(ratio "$r" "$t") | $ok: sensor sums differ by $mean% on average ($bias% signed), at most $max%, $over of $n over 5% |"
}
want() { [[ " $cases " == *" $1 "* ]]; }
commit=$(git -C "$root" rev-parse --short HEAD 2> /dev/null || echo unknown)
cpu=$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)
device=$("$build/bin/radcl" devices 2> /dev/null | awk '/^\*/ { $1 = ""; $2 = ""; print; exit }' |
  sed 's/^ *//')
echo "radcl rcontrib against Radiance rcontrib, $(date -u +%Y-%m-%d), radcl at commit $commit"
echo "on ${device:-an unknown device} (RADCL_DEVICE=${RADCL_DEVICE:-unset}), host $(nproc) cores: $cpu;"
echo "$(RAYPATH=".:$rlib" "$rbin/rcontrib" -version 2>&1 | head -n 1); both -n $threads;" \
  "$sensors sensors, $nsuns suns$([ "$repeat" -gt 1 ] && echo ", fastest of $repeat runs")"
echo
rows=() notes=()
sky=(-n "$threads" -aa 0 -ab 2 -ad 5000 -lw 2e-5 -c 1 -faf -I -y "$sensors")

if want sky; then
  cmd=(rcontrib "${sky[@]}" -e MF:1 -f reinhart.cal -b rbin -bn Nrbins -m skyglow office_dome.oct)
  t=$(run radcl "$scenes" "$work/grid.pts" "$work/c_sky" "$build/bin/${cmd[0]}" "${cmd[@]:1}")
  cp "$work/profile" "$work/profile_sky"
  r=$(run radiance "$scenes" "$work/grid.pts" "$work/r_sky" "$rbin/${cmd[0]}" "${cmd[@]:1}")
  sleep 1 # Radiance seeds its random numbers from the clock
  run radiance "$scenes" "$work/grid.pts" "$work/r_sky2" "$rbin/${cmd[0]}" "${cmd[@]:1}" > /dev/null
  read -r noise nmax nover nbias n <<< "$(sums_differ "$work/r_sky2" "$work/r_sky" "$sensors" 146)"
  sky_row sky "sky: Reinhart MF:1, -ab 2 -ad 5000, $sensors sensors" "$work/c_sky" "$work/r_sky"
  rows+=("$row")
  rows+=("| sky: Radiance against a second Radiance run (the noise) | | | | sensor sums differ by $noise% on average ($nbias% signed), at most $nmax%, $nover of $n over 5% |")
  notes+=("sky (\`${cmd[*]}\`), bare Embree on the trace phase's rays: $(raw "$scenes" "$build/bin/${cmd[0]}" "${cmd[@]:1}")")
fi

if want sky-rf; then
  if [ -x "$rbin/rfluxmtx" ]; then
    cmd=(rfluxmtx "${sky[@]}" - sky.dome -i room.oct)
    t=$(run radcl "$work" "$work/grid.pts" "$work/c_rf" "$rbin/rfluxmtx" "${cmd[@]:1}")
    cp "$work/profile" "$work/profile_sky-rf"
    r=$(run radiance "$work" "$work/grid.pts" "$work/r_rf" "$rbin/rfluxmtx" "${cmd[@]:1}")
    sky_row sky-rf "sky through rfluxmtx (Honeybee's command), $sensors sensors" "$work/c_rf" "$work/r_rf"
    rows+=("$row")
  else
    notes+=("sky-rf: skipped, no rfluxmtx in $rbin")
  fi
fi

if want sun; then
  cmd=(rcontrib -n "$threads" -aa 0 -I -faf -ab 0 -dc 1 -dt 0 -dj 0 -M suns.mod suns.oct)
  t=$(run radcl "$work" "$work/grid.pts" "$work/c_sun" "$build/bin/${cmd[0]}" "${cmd[@]:1}")
  cp "$work/profile" "$work/profile_sun"
  r=$(run radiance "$work" "$work/grid.pts" "$work/r_sun" "$rbin/${cmd[0]}" "${cmd[@]:1}")
  read -r n lit bad worst <<< "$(all_differ "$work/c_sun" "$work/r_sun" "$sensors" "$nsuns")"
  ok=$([ "$bad" = 0 ] && echo yes || echo NO)
  rows+=("| sun: $nsuns suns (-M), -ab 0 -dc 1, $sensors sensors | $t | $r | $(ratio "$r" "$t") | $ok: $bad of $n numbers ($lit non-zero) off by more than 1e-3 rel. and 1e-9 abs.; worst relative $worst |")
  notes+=("sun: no bare-Embree time: its rays are all shadow rays toward the suns (the shadow-trace phase), which RADCL_PROFILE=raw does not replay and bench_embree_rays cannot make")
fi

echo "| case | radcl s | Radiance s | Radiance/radcl | matrices agree |"
echo "|---|---:|---:|---:|---|"
printf '%s\n' "${rows[@]}"
echo
[ ${#notes[@]} = 0 ] || printf -- '- %s\n' "${notes[@]}"
echo "- rays per second: radcl's rcontrib has no RADCL_STATS report"
for c in $cases; do
  [ -e "$work/profile_$c" ] || continue
  echo
  echo "radcl's phases, $c (RADCL_PROFILE=1, the timed run):"
  echo
  echo '```'
  sed 's/^profile: //' "$work/profile_$c"
  echo '```'
done
