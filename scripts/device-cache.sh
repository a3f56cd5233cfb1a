#!/usr/bin/env bash
# Device-side study of the cache cases (peers P1 and P4): the phases of radcl's run on the GPU,
# and the cache build's rounds summed by their number of primaries (RADCL_DEBUG_CACHE).
# Run by scripts/device-run.sh sh (DEVICE_SH='bash scripts/device-cache.sh'); CACHE_CASES picks
# "P1", "P4" or both (P4 needs Radiance's oconv in the bundle); CACHE_VARIANTS: environment
# settings (VAR=value, space-separated) each given a P1 run of its own beside the plain ones.
set -uo pipefail
scenes=$RADCL_TEST_DATA/scenes
w=/tmp/cachew
mkdir -p "$w"
grid() {
  awk -v n="$1" -v x0="$2" -v x1="$3" -v y0="$4" -v y1="$5" -v z="$6" 'BEGIN {
    a = (x1 - x0) / (y1 - y0); nx = int(sqrt(n * a) + 0.5); ny = int(n / nx + 0.5)
    for (j = 0; j < ny; j++) for (i = 0; i < nx; i++)
      printf "%.4f %.4f %g 0 0 1\n", x0 + (i + 0.5) * (x1 - x0) / nx, y0 + (j + 0.5) * (y1 - y0) / ny, z }'
}
opts="-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3"
# rounds FILE: the build's rounds by size (primaries), their count, primaries and seconds.
rounds() {
  awk '/ round / { p = $6; b = (p < 64 ? "a <64" : p < 1024 ? "b <1k" : p < 8192 ? "c <8k" : "d >=8k")
    n[b]++; t[b] += $12; s[b] += p; N++; T += $12 }
    / hemispheres, / { h += $4; r += $6; m++ }
    END { for (k in n) printf "  rounds %s: %d, %d primaries, %.3f s\n", k, n[k], s[k], t[k]
      printf "  all rounds: %d, %.3f s; %d record batches, %d hemispheres, %d records\n", N, T, m, h, r }' "$1" | sort
}
# one LABEL DIR OCT PTS env...: a profiled run, then its rounds
one() {
  local label=$1 dir=$2 oct=$3 pts=$4
  shift 4
  echo "== $label"
  (cd "$dir" && env RADCL_PROFILE=1 RADCL_DEBUG_CACHE=1 "$@" /usr/bin/time -f "%e s wall, %U s user, %S s sys" \
    "$RADCL_BIN/rtrace" -n "$(nproc)" -h -u- -I $opts "$oct" < "$pts" > /dev/null 2> "$w/err")
  grep -v "^cache:" "$w/err" | grep -v "^profile: wave" | tail -40
  rounds "$w/err"
}
for c in ${CACHE_CASES:-P1 P4}; do
  case $c in
  P1)
    cat "$scenes/office_grid.pts" > "$w/p1.pts"
    grid 99923 0.1 5.9 0.1 3.9 0.8 >> "$w/p1.pts"
    head -n 1 "$w/p1.pts" | (cd "$scenes" && RADCL_DEVICE=nvidia "$RADCL_BIN/rtrace" -h -I $opts office_clear.oct > /dev/null)
    one "P1 gpu" "$scenes" office_clear.oct "$w/p1.pts" RADCL_DEVICE=nvidia
    for v in ${CACHE_VARIANTS:-}; do
      one "P1 gpu $v" "$scenes" office_clear.oct "$w/p1.pts" RADCL_DEVICE=nvidia "$v"
    done
    one "P1 gpu again" "$scenes" office_clear.oct "$w/p1.pts" RADCL_DEVICE=nvidia
    one "P1 gpu waves" "$scenes" office_clear.oct "$w/p1.pts" RADCL_DEVICE=nvidia RADCL_PROFILE=waves
    ;;
  P4)
    op=$w/openplan
    "$RADCL_SOURCE_DIR/tests/bench/openplan_scene.sh" "$RADCL_BIN" "$scenes" "$RADIANCE_BIN" \
      "$RADIANCE_LIB" "$op"
    grid 10000 0.2 59.8 0.2 23.8 0.8 > "$w/p4.pts"
    head -n 1 "$w/p4.pts" | (cd "$op" && RADCL_DEVICE=nvidia "$RADCL_BIN/rtrace" -h -I $opts openplan.oct > /dev/null)
    one "P4 gpu" "$op" openplan.oct "$w/p4.pts" RADCL_DEVICE=nvidia
    ;;
  esac
done
