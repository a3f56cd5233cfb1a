#!/usr/bin/env bash
# What accuracy costs in time: a ladder of ambient settings from coarse to fine, on the office
# (clear sky) and the luminaires room, each run by radcl's rtrace and, with RADIANCE_BIN set,
# by Radiance's in the same go. Two ladders: the irradiance cache (-aa > 0) and plain Monte-Carlo
# integration (-aa 0, where -ad is the number of paths per sensor). Every step is at -ab 5, so
# each is scored against the converged -ab 5 answer (tests/data/results/*_mc5.txt: Radiance's
# -aa 0 mean of 30 runs, standard error 0.1-0.4% per sensor): mean and worst sensor's relative
# luminance error. radcl runs with -u- (one fixed seed); Radiance seeds itself from the clock,
# so its errors are one draw each.
#
# BENCH_REPEAT=n: radcl's time is the median of n runs (Radiance runs once).
# LADDER=cache|mc|both (default both); SCENES: a space-separated list of scene names with
# a sensor file (default "office_clear luminaires").
#
# usage: tests/bench/accuracy_cost.sh [build-dir] [threads]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
threads=${2:-2}
scenes=$root/tests/data/scenes
data=$root/tests/data/results
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
repeat=${BENCH_REPEAT:-1}

cache_steps=(
  "-aa 0.25 -ad 256 -as 64 -ar 128 -lw 1e-3"
  "-aa 0.2 -ad 512 -as 128 -ar 128 -lw 1e-3"
  "-aa 0.15 -ad 1024 -as 256 -ar 256 -lw 1e-3"
  "-aa 0.1 -ad 2048 -as 512 -ar 512 -lw 1e-3"
)
mc_steps=(
  "-aa 0 -ad 256 -as 0 -lw 1e-4"
  "-aa 0 -ad 1024 -as 0 -lw 1e-4"
  "-aa 0 -ad 4096 -as 0 -lw 1e-4"
)
case ${LADDER:-both} in
  cache) steps=("${cache_steps[@]}") ;;
  mc) steps=("${mc_steps[@]}") ;;
  both) steps=("${cache_steps[@]}" "${mc_steps[@]}") ;;
  *) echo "accuracy_cost.sh: LADDER must be cache, mc or both" >&2; exit 2 ;;
esac

sensors() { case $1 in luminaires*) echo luminaires_grid.pts ;; *) echo office_grid.pts ;; esac; }
# shellcheck source=tests/bench/sensor_errors.sh
. "$root/tests/bench/sensor_errors.sh"
timed() { # output-file command... ; prints seconds
  local out=$1; shift
  (cd "$scenes" && /usr/bin/time -f "%e" "$@" > "$out" 2> "$work/err") ||
    { cat "$work/err" >&2; exit 1; }
  tail -n 1 "$work/err"
}
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# Warm the program cache so compile time is not measured: one sensor at every step (programs
# are specialised to the settings as well as the scene).
for c in ${SCENES:-office_clear luminaires}; do
  for s in "${steps[@]}"; do
    # shellcheck disable=SC2086 # the settings are words
    (cd "$scenes" && head -n 1 "$(sensors "$c")" |
      "$build/bin/rtrace" -u- -h -I -ab 5 $s "$c.oct" > /dev/null)
  done
done

echo "| scene | settings (-ab 5) | radcl s | Radiance s | speed-up | radcl error (mean worst) | Radiance error |"
echo "|---|---|---:|---:|---:|---|---|"
for c in ${SCENES:-office_clear luminaires}; do
  pts=$scenes/$(sensors "$c")
  for s in "${steps[@]}"; do
    # shellcheck disable=SC2086 # the settings are words
    t=$(for ((k = 0; k < repeat; k++)); do
      timed "$work/radcl.txt" "$build/bin/rtrace" -n "$threads" -u- -h -I -ab 5 $s "$c.oct" < "$pts"
    done | median)
    re=$(errs "$work/radcl.txt" "$data/${c}_mc5.txt")
    rt="" sp="" rr=""
    if [ -n "${RADIANCE_BIN:-}" ]; then
      # shellcheck disable=SC2086
      rt=$(timed "$work/rad.txt" "$RADIANCE_BIN/rtrace" -h -I -ab 5 $s "$c.oct" < "$pts")
      sp=$(awk -v a="$t" -v b="$rt" 'BEGIN { printf "%.2fx", b / a }')
      rr=$(errs "$work/rad.txt" "$data/${c}_mc5.txt")
    fi
    echo "| $c | $s | $t | $rt | $sp | $re | $rr |"
  done
done
