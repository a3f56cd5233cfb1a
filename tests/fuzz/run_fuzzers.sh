#!/usr/bin/env bash
# Runs radcl's libFuzzer targets (docs/development.md) and prints, per target, executions, exec/s,
# coverage (cov/ft of libFuzzer's final status line, and of the whole corpus afterwards) and
# findings (crash-/leak-/timeout-/oom- files).
#
#   tests/fuzz/run_fuzzers.sh [seconds] [jobs] [--bin DIR] [--work DIR] [--only NAME]...
#
#   seconds   fuzzing time per target (default 600)
#   jobs      parallel fuzzing processes per target, -jobs=N -workers=N (default 1)
#   --bin     folder of already built fuzz_* binaries (no clang or cmake needed); default:
#             configure and build the `fuzz` preset, then use build-fuzz/fuzz
#   --work    where corpora, logs and findings go (default build-fuzz/work); the corpus of a
#             previous run is kept and extended
#   --only    run only this target (repeatable), e.g. --only rad_reader
#
# Exit status: 0 when no target has findings, 1 when some has, 2 for a usage or build error.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/../.." && pwd)
SECONDS_PER_TARGET=600
JOBS=1
BIN=""
WORK=""
ONLY=()
positional=0
while (($#)); do
  case "$1" in
  --bin) BIN=$2; shift 2 ;;
  --work) WORK=$2; shift 2 ;;
  --only) ONLY+=("$2"); shift 2 ;;
  -h | --help) sed -n '2,17p' "$0"; exit 0 ;;
  -*) echo "run_fuzzers.sh: unknown option $1" >&2; exit 2 ;;
  *)
    if ((positional == 0)); then SECONDS_PER_TARGET=$1; else JOBS=$1; fi
    positional=$((positional + 1))
    shift
    ;;
  esac
done
[[ $SECONDS_PER_TARGET =~ ^[0-9]+$ && $JOBS =~ ^[0-9]+$ && $JOBS -ge 1 ]] || {
  echo "run_fuzzers.sh: seconds and jobs must be positive integers" >&2
  exit 2
}

if [[ -z $BIN ]]; then
  command -v clang++ >/dev/null || {
    echo "run_fuzzers.sh: clang++ not found; build elsewhere and pass --bin DIR" >&2
    exit 2
  }
  (cd "$ROOT" && { [[ -f build-fuzz/CMakeCache.txt ]] || cmake --preset fuzz >/dev/null; } &&
    cmake --build build-fuzz -j "$JOBS" --target radcl_fuzzers) || exit 2
  BIN=$ROOT/build-fuzz/fuzz
fi
BIN=$(cd "$BIN" && pwd)
WORK=${WORK:-$ROOT/build-fuzz/work}
mkdir -p "$WORK"
WORK=$(cd "$WORK" && pwd)

TARGETS=()
for b in "$BIN"/fuzz_*; do
  [[ -x $b ]] || continue
  t=${b##*/fuzz_}
  if ((${#ONLY[@]})) && [[ " ${ONLY[*]} " != *" $t "* ]]; then continue; fi
  TARGETS+=("$t")
done
((${#TARGETS[@]})) || { echo "run_fuzzers.sh: no fuzz_* binaries in $BIN" >&2; exit 2; }

D=$ROOT/tests/data
# Seed files of one target from tests/data (and the repository's scenes/ and lib/): globs that
# match nothing are skipped.
seed_files() {
  shopt -s nullglob globstar
  case "$1" in
  rad_reader) printf '%s\n' "$D"/**/*.rad "$ROOT"/scenes/*.rad ;;
  octree_reader) printf '%s\n' "$D"/**/*.oct "$D"/scene/bad_octree/* ;;
  mesh_reader) printf '%s\n' "$D"/**/*.rtm ;;
  amb_reader) printf '%s\n' "$D"/**/*.amb "$D"/**/*.amb.txt ;;
  picture_reader) printf '%s\n' "$D"/**/*.hdr "$D"/**/*.pic ;;
  options) printf '%s\n' "$D"/**/*.vf "$ROOT"/scenes/*.vf ;;
  cal_parser) printf '%s\n' "$D"/**/*.cal "$ROOT"/lib/*.cal ;;
  esac
  printf '%s\n' "$D"/fuzz/"$1"/*
  shopt -u nullglob globstar
}

# Small seeds no data file provides: typical command lines; tiny pictures (flat and run-length
# encoded scanlines, and a column-major orientation).
extra_seeds() {
  local dir=$1
  case "$2" in
  options)
    printf -- '-h -I -ab 5 -ad 1024 -as 512 -aa 0.1 -ar 256 -lw 1e-4 -ov scene.oct' >"$dir/x-rtrace"
    printf -- '-ffd -oodvVwWlLcpnNsmMrxRX -x 10 -y 4 -n 2 -te a -ti b -w- scene.oct' >"$dir/x-fmt"
    printf -- '-vf - -x 64 -y 32 -pa 0 -ps 2 -pt .1 -av .1 .1 .1 -S 3 -o f%%03d.hdr s.oct\0#?RADIANCE\nVIEW= -vtv -vp 1 2 3 -vd 0 1 0\n\n' >"$dir/x-rpict"
    printf -- '-vth -vh 180 -vv 180 -vo 1 -va 10 -vs .2 -vl -.1 -dj .7 -ds .1 -defaults' >"$dir/x-view"
    ;;
  command_line) # words, option files a and b, variables A and B, view file v (NUL-separated)
    printf -- '-ab 2 @a -vf v\0-aa .1 @b\0-ad 9 $A\0-as 3 $B\0-ar 5\0rview -vtv -vp 1 2 3\n' >"$dir/x-nested"
    printf -- '@a\0@a\0\0\0\0' >"$dir/x-self"
    printf -- '-x 64 -y 32 -vf - -S 2 @b\0\0-ps 2 -pt .1 $A\0-dj .5\0\0#?RADIANCE\nVIEW= -vth -vh 180\n\n' >"$dir/x-rpict"
    ;;
  ray_input) # a format byte, -x and -y bytes, then rays: ascii from the data's ray and sensor
    # files (no count, a 4x3 count, -x 1 flushes), and binary records
    local f
    for f in "$D"/scenes/*_rays.txt "$D"/scenes/*.pts; do
      { printf 'a\000\000'; head -c 4096 "$f"; } >"$dir/x-${f##*/}"
    done
    { printf 'a\004\003'; head -c 4096 "$D"/scenes/office_grid.pts; } >"$dir/x-count"
    printf 'a\001\000 0 0 0 0 0 1\n0 0 0 0 0 0\n0 0 0 1 0 0\n' >"$dir/x-flush"
    printf 'f\002\001\000\000\200\077\000\000\200\077\000\000\200\077\000\000\000\000\000\000\000\000\000\000\200\077' >"$dir/x-float"
    printf 'd\000\000\000\000\000\000\000\000\360\077\000\000\000\000\000\000\370\177' >"$dir/x-double-nan"
    ;;
  picture_reader)
    printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=2\n\n-Y 2 +X 2\n\200\200\200\201\001\001\001\001\100\100\100\202\001\001\001\001' >"$dir/x-flat"
    printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n\002\002\000\010\210\200\210\100\004\001\002\003\004\204\004\210\201' >"$dir/x-rle"
    printf '#?RADIANCE\nFORMAT=32-bit_rle_xyze\nPRIMARIES= 0 0 1 1 .3 .3 .3 .3\n\n+X 2 -Y 1\n\200\200\200\201\001\002\003\201' >"$dir/x-columns"
    ;;
  esac
}

# libFuzzer's figures from one log: executions, exec/s, cov, ft (empty when absent).
log_stats() {
  awk '
    /^stat::number_of_executed_units:/ { execs = $2 }
    /^stat::average_exec_per_sec:/ { rate = $2 }
    /^#[0-9]+/ && / cov: / {
      n = substr($1, 2)
      for (i = 1; i < NF; ++i) { if ($i == "cov:") cov = $(i + 1); if ($i == "ft:") ft = $(i + 1) }
    }
    END { if (execs == "") execs = n; print execs + 0, rate + 0, cov + 0, ft + 0 }' "$1"
}

printf 'fuzzing %d target(s), %ss each, %d job(s); binaries %s; work %s\n' \
  "${#TARGETS[@]}" "$SECONDS_PER_TARGET" "$JOBS" "$BIN" "$WORK"
SUMMARY=()
total_findings=0
for t in "${TARGETS[@]}"; do
  exe=$BIN/fuzz_$t
  seeds=$WORK/seeds/$t corpus=$WORK/corpus/$t logs=$WORK/logs/$t findings=$WORK/findings/$t
  rm -rf "$seeds" "$logs"
  mkdir -p "$seeds" "$corpus" "$logs" "$findings/previous"
  # Findings of earlier runs are kept aside, so that the counts below are this run's.
  find "$findings" -maxdepth 1 -type f -exec mv -f {} "$findings/previous/" \;
  while IFS= read -r f; do
    [[ -f $f && ${f##*/} != README.md ]] && cp "$f" "$seeds/$(basename "$(dirname "$f")")-${f##*/}"
  done < <(seed_files "$t")
  extra_seeds "$seeds" "$t"

  args=(-max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048
    -print_final_stats=1 -artifact_prefix="$findings/")
  [[ -f $ROOT/tests/fuzz/$t.dict ]] && args+=(-dict="$ROOT/tests/fuzz/$t.dict")
  echo "== $t: $(ls "$seeds" | wc -l) seeds, $(ls "$corpus" | wc -l) corpus inputs kept"
  # A hung run is stopped well after libFuzzer's own time limit would have ended it.
  limit=$((SECONDS_PER_TARGET + 300))
  if ((JOBS > 1)); then
    (cd "$logs" && timeout -k 30 "$limit" "$exe" "${args[@]}" -jobs="$JOBS" -workers="$JOBS" \
      "$corpus" "$seeds" >"$logs/driver.log" 2>&1) || true
  else
    (cd "$logs" && timeout -k 30 "$limit" "$exe" "${args[@]}" "$corpus" "$seeds" \
      >"$logs/fuzz-0.log" 2>&1) || true
  fi

  execs=0 rate=0 cov=0 ft=0
  for log in "$logs"/fuzz-*.log; do
    [[ -f $log ]] || continue
    read -r e r c f < <(log_stats "$log")
    execs=$((execs + e)) rate=$((rate + r))
    ((c > cov)) && cov=$c
    ((f > ft)) && ft=$f
  done
  # Coverage of everything the corpus now holds (all jobs together): a pass without mutation.
  read -r ccov cft < <("$exe" -runs=0 -rss_limit_mb=2048 "$corpus" "$seeds" 2>&1 |
    awk '/INITED/ && / cov: / { for (i = 1; i < NF; ++i) { if ($i == "cov:") c = $(i + 1)
                                                        if ($i == "ft:") f = $(i + 1) } }
         END { print c + 0, f + 0 }') || true
  mapfile -t found < <(find "$findings" -maxdepth 1 -type f \
    \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | sort)
  total_findings=$((total_findings + ${#found[@]}))
  SUMMARY+=("$(printf '%-15s %12d %9d %7d %8d %9s %9s %5d %8d' "$t" "$execs" "$rate" "$cov" "$ft" \
    "${ccov:-?}" "${cft:-?}" "$(ls "$corpus" | wc -l)" "${#found[@]}")")
  for f in "${found[@]}"; do echo "   finding: $f"; done
done

echo
printf '%-15s %12s %9s %7s %8s %9s %9s %5s %8s\n' target executions exec/s cov ft \
  corpus_cov corpus_ft units findings
printf '%s\n' "${SUMMARY[@]}"
echo "(cov/ft: libFuzzer's last status line, the highest of the jobs; corpus_cov/ft: one pass"
echo " over the final corpus; findings are under $WORK/findings/<target>/)"
((total_findings == 0))
