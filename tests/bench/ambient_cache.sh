#!/usr/bin/env bash
# The irradiance cache's cost and accuracy: radcl's rtrace building its cache from nothing on
# the reference runs, against Radiance 5.4a's stored times (radiance_times.tsv, one process)
# and results (the _high runs for accuracy, the sphere's exact answers), and the time for
# -ab 1..8 at fixed -ad on the integrating sphere (it should grow about linearly); rpict on
# office_view at 256^2 and 1024^2 with Radiance's options; lookup throughput: office_view at
# 512^2 reading a read-only copy of office_clear_high.amb (about 98,000 records).
#
# Errors are against the converged answer at the runs' own -ab (Radiance's -aa 0 mean of 30
# runs, tests/data/results/*_mc5.txt) and, for radcl, against the _high runs as well. With
# RADIANCE_BIN set to a directory holding Radiance's rtrace and rpict, Radiance runs here too,
# in the same go, and its times and errors come from that run.
#
# BENCH_REPEAT=n runs each sensor case and rpict n times on both sides and reports the median
# time (the lent GPU machine's times vary by up to 1.6x from call to call; the sphere runs once).
#
# usage: tests/bench/ambient_cache.sh [build-dir] [threads]   (rpict uses every core)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
threads=${2:-2}
scenes=$root/tests/data/scenes
ref=${RADCL_REFERENCE:-$root/../shared/reference}/results
data=$root/tests/data/results # the converged answers (tests/data/README.md)
times=$ref/radiance_times.tsv
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

repeat=${BENCH_REPEAT:-1}
# median input-file command... : runs the command (a function printing seconds) $repeat times,
# each reading the input file afresh; prints the median.
median() {
  local k in=$1
  shift
  for ((k = 0; k < repeat; k++)); do "$@" < "$in"; done | sort -n | awk '{ v[NR] = $1 }
    END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
ref_time() { awk -F'\t' -v n="$1" '$1 == n { print $2 }' "$times"; }
# shellcheck source=tests/bench/sensor_errors.sh
. "$root/tests/bench/sensor_errors.sh"
run() { # output-file args... ; prints seconds
  local out=$1; shift
  ( cd "$scenes" && /usr/bin/time -f "%e" "$build/bin/rtrace" -n "$threads" -u- -h -I "$@" \
      > "$out" 2> "$work/err" ) || { cat "$work/err" >&2; exit 1; }
  tail -n 1 "$work/err"
}

radiance() { # output program args... ; Radiance's program from RADIANCE_BIN; prints seconds
  local out=$1 prog=$2; shift 2
  ( cd "$scenes" && /usr/bin/time -f "%e" "$RADIANCE_BIN/$prog" "$@" > "$out" 2> "$work/rerr" ) ||
    { cat "$work/rerr" >&2; exit 1; }
  tail -n 1 "$work/rerr"
}

# Warm the program cache so compile time is not measured.
( cd "$scenes" && head -n 2 sphere_wall.pts | "$build/bin/rtrace" -h -I -ab 1 -aa 0.1 sphere.oct > /dev/null )

printf '%-24s %8s %10s %7s   %-15s %-15s %s\n' case radcl_s radiance_s speedup \
  "radcl err" "Radiance err" "(vs converged -ab 5; radcl vs _high)"
for name in office_clear_default office_overcast_default luminaires_default; do
  case $name in
  office_clear_default) oct=office_clear.oct pts=office_grid.pts base=office_clear ;;
  office_overcast_default) oct=office_overcast.oct pts=office_grid.pts base=office_overcast ;;
  luminaires_default) oct=luminaires.oct pts=luminaires_grid.pts base=luminaires ;;
  esac
  opts="-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3"
  # One sensor first, so the scene's program is compiled (and cached) before the timed run.
  run "$work/warm.txt" -ab 5 -ad 64 -as 0 -ar 256 -aa 0.15 -lw 1e-3 "$oct" < <(head -n 1 "$scenes/$pts") >/dev/null
  secs=$(median "$scenes/$pts" run "$work/$name.txt" $opts "$oct")
  # Radiance on this machine when RADIANCE_BIN names its binaries (its errors from that run),
  # else its stored time and result.
  rt=$(ref_time "$name") rres=$ref/$name.txt where=stored
  if [ -n "${RADIANCE_BIN:-}" ]; then
    rt=$(median "$scenes/$pts" radiance "$work/r_$name.txt" rtrace -h -I $opts "$oct")
    rres=$work/r_$name.txt where=here
  fi
  exact=$data/${base}_mc5.txt
  e=$(errs "$work/$name.txt" "$exact")
  er=$(errs "$rres" "$exact")
  eh=$(errs "$work/$name.txt" "$ref/${base}_high.txt")
  printf '%-24s %8s %10s %6.2fx   %-15s %-15s %s\n' "$name" "$secs" "$rt ($where)" \
    "$(awk -v a="$rt" -v b="$secs" 'BEGIN { print a / b }')" "$e" "$er" "$eh"
done

echo
echo "integrating sphere, -ad 1024 -as 256 -aa 0.1 -ar 64 -lw 1e-5 (exact answers: sphere_exact.txt)"
printf '%-6s %9s %11s %10s %10s %10s\n' "-ab" radcl_s radiance_s radcl radiance exact
for ab in 1 2 4 8; do
  secs=$(run "$work/s$ab.txt" -ab "$ab" -ad 1024 -as 256 -aa 0.1 -ar 64 -lw 1e-5 sphere.oct \
    < "$scenes/sphere_wall.pts")
  rres=$ref/sphere_ab$ab.txt rt=$(ref_time sphere_ab$ab)
  if [ -n "${RADIANCE_BIN:-}" ]; then
    rt=$(radiance "$work/rs$ab.txt" rtrace -h -I -ab "$ab" -ad 1024 -as 256 -aa 0.1 -ar 64 \
      -lw 1e-5 sphere.oct < "$scenes/sphere_wall.pts")
    rres=$work/rs$ab.txt
  fi
  m=$(awk '{ s += $1; n++ } END { printf "%.4f", s / n }' "$work/s$ab.txt")
  r=$(awk '{ s += $1; n++ } END { printf "%.4f", s / n }' "$rres")
  x=$(awk -v ab="$ab" '$1 == ab { printf "%.4f", $2 }' "$ref/sphere_exact.txt")
  printf '%-6s %9s %11s %10s %10s %10s\n' "$ab" "$secs" "$rt" "$m" "$r" "$x"
done

pict() { # resolution extra-args... ; prints seconds
  local res=$1; shift
  ( cd "$scenes" && /usr/bin/time -f "%e" "$build/bin/rpict" -u- -vf office.vf \
      -x "$res" -y "$res" -ab 2 -ad 1024 -as 256 -aa 0.15 -ar 128 "$@" office_clear.oct \
      > "$work/pict.hdr" 2> "$work/err" ) || { cat "$work/err" >&2; exit 1; }
  tail -n 1 "$work/err"
}
echo
echo "rpict office_view (-ab 2 -ad 1024 -as 256 -aa 0.15 -ar 128), cache built as it renders"
printf '%-12s %9s %11s %12s\n' resolution radcl_s radiance_s pixels/s
pict 16 > /dev/null # compiles office_view's program
for res in 256 1024; do
  secs=$(median /dev/null pict "$res")
  rt=n/a
  [ "$res" = 256 ] && rt=$(ref_time office_view)
  if [ -n "${RADIANCE_BIN:-}" ]; then
    rt=$(median /dev/null radiance /dev/null rpict -vf office.vf -x "$res" -y "$res" -ab 2 -ad 1024 \
      -as 256 -aa 0.15 -ar 128 office_clear.oct)
  fi
  printf '%-12s %9s %11s %12.0f\n' "${res}x$res" "$secs" "$rt" \
    "$(awk -v s="$secs" -v r="$res" 'BEGIN { print r * r / s }')"
done
if [ -f "$ref/office_clear_high.amb" ]; then
  cp "$ref/office_clear_high.amb" "$work/high.amb"
  chmod 444 "$work/high.amb"
  nrec=$("$build/bin/radcl" ambient -d "$work/high.amb" | wc -l)
  secs=$(pict 512 -af "$work/high.amb")
  if [ -n "${RADIANCE_BIN:-}" ]; then
    # A fresh copy: run as root, neither program is kept from appending by the mode bits.
    cp -f "$ref/office_clear_high.amb" "$work/high.amb"
    rt=$(radiance /dev/null rpict -vf office.vf -x 512 -y 512 -ab 2 -ad 1024 -as 256 -aa 0.15 \
      -ar 128 -af "$work/high.amb" office_clear.oct)
    echo "Radiance here, the same run: $rt s"
  fi
  echo
  echo "lookups: office_view 512x512 reading office_clear_high.amb (~$nrec records, read-only)"
  printf '%9s s, %.0f pixels/s (every primary on a diffuse surface is one lookup; the seed\n' \
    "$secs" "$(awk -v s="$secs" 'BEGIN { print 512 * 512 / s }')"
  echo "report: 56.8 s on its GPU for 110,000 records, Radiance 6 s on a CPU)"
fi
