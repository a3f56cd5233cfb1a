#!/usr/bin/env bash
# Runs on the lent GPU machine, from the repository root, after scripts/device-bundle.sh made
# .devlibs/bundle.tar.xz here: registers the NVIDIA OpenCL driver (the machine's ICD list lacks
# it), then does what its arguments name, writing logs under $OUT:
#   devices   radcl devices --check
#   tests     the device-facing test executables on the GPU (stability suite first; TESTS
#             names some instead, TEST_LIMIT is each one's time limit in seconds)
#   bench     tests/bench/ambient_cache.sh on the GPU (Radiance alongside when it was bundled),
#             the median of BENCH_REPEAT (default 3) runs per sensor case and rpict
#   bench-cpu the same on PoCL with every core (NO_RADIANCE=1: radcl alone)
#   peers     tests/bench/peers.sh on the GPU against Radiance -n (all cores) in the same run
#             (P1-P5; needs Radiance bundled), its table and chart under $OUT
#   peers-cpu the same with radcl on PoCL over every core (PEERS_ARGS=--small: the 2-core cases)
#   cost      tests/bench/cost_study.sh on the GPU: radcl cost on office_clear, luminaires, the
#             deep plan and the sphere, Radiance's rtrace -n (all cores) beside it when it was
#             bundled; the tables and charts under $OUT (SCENES: a subset)
#   rounds    office_clear's cache build on the GPU, its rounds' time by size
#   cold      a first run on a machine that has compiled nothing (radcl's program cache and
#             NVIDIA's ComputeCache emptied): one sensor, compiling the scene's program, then
#             every sensor from the caches three times, and the programs' PTX sizes (their
#             largest functions in lines), for each option set in COLD_OPTIONS (a
#             '|'-separated list of RADCL_CL_OPTIONS values; default: none); COLD_SCENES
#             lists octree:sensor-file pairs (a file without a suffix takes .pts; default:
#             office_clear and luminaires)
#   sh        the command in DEVICE_SH, run by bash with the bundle's programs and libraries set
#             up ($b/bin holds radcl's programs, $RADIANCE_BIN Radiance's), from the root
#   profile   the benchmark's rtrace cases and rpict 256^2 on the GPU with RADCL_PROFILE=1: wall
#             time by phase of the renderer's work (PROFILE_DEVICE=pocl: on PoCL instead)
# usage: scripts/device-run.sh devices tests bench ...
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${OUT:-/tmp/out}
b=/tmp/radcl-bundle
mkdir -p "$b" "$out" /tmp/vendors /tmp/pocl /tmp/radcl-cache
tar -C "$b" -xJf "$root/.devlibs/bundle.tar.xz"
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/vendors/nvidia.icd
for f in /etc/OpenCL/vendors/*.icd; do [ -e "$f" ] && cp "$f" /tmp/vendors/; done
[ -x /usr/bin/time ] || cp "$b/bin/gnu-time" /usr/bin/time
export OCL_ICD_VENDORS=/tmp/vendors LD_LIBRARY_PATH=$b/lib POCL_CACHE_DIR=/tmp/pocl \
  RADCL_CACHE_DIR=/tmp/radcl-cache RADCL_TEST_DATA=$root/tests/data RADCL_BIN=$b/bin \
  RADCL_SOURCE_DIR=$root RADCL_REFERENCE=$b/ref
mkdir -p "$b/build" && ln -sfn "$b/bin" "$b/build/bin"
[ -x "$b/radiance/rtrace" ] && [ -z "${NO_RADIANCE:-}" ] && export RADIANCE_BIN=$b/radiance RAYPATH=.:$b/radiance RADIANCE_LIB=$b/radiance
# Without Radiance bundled, radcl's own function files (rayinit.cal): the bundle's bin/ has no
# lib/radcl beside it, so the programs would not find them.
[ -n "${RAYPATH:-}" ] || export RAYPATH=.:$root/lib

tests() { # the stability suite, then the rest, each executable under a time limit; TEST_JOBS
  # processes at once (NVIDIA's compiles of each scene's program are CPU-bound: they overlap),
  # each executable split into TEST_SHARDS gtest shards
  local t n=0 list=${TESTS:-$(ls "$b"/bin/test_*stability* "$b"/bin/test_render_ambient_leaks
    ls "$b"/bin/test_* | grep -v stability | grep -v ambient_leaks)}
  mkdir -p "$out/logs"
  local k shards=${TEST_SHARDS:-1}
  for t in $list; do
    for ((k = 0; k < shards; ++k)); do
      # shellcheck disable=SC2046 # no shard suffix when there is one shard
      GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$k one "$(basename "$t")" $( ((shards > 1)) && echo $k) &
      n=$((n + 1))
      [ $((n % ${TEST_JOBS:-1})) = 0 ] && wait
    done
  done
  wait
  local s f
  s=$(grep -c " rc=0 " "$out/times.txt") f=$(grep -vc " rc=0 " "$out/times.txt")
  for t in $(grep -v " rc=0 " "$out/times.txt" | cut -d' ' -f1); do
    echo "== $(grep "^$t " "$out/times.txt")"
    grep -E "FAILED|Failure|rror" "$out/logs/$t.log" | head -20
  done
  echo "test executables: $s passed, $f failed"
}

one() { # one test executable (gtest shard $2) under the time limit: its log, time and results
  local t=$1${2:+.$2} rc t0
  t0=$(date +%s)
  timeout "${TEST_LIMIT:-120}" "$b/bin/$1" ${GTEST_ARGS---gtest_brief=1} > "$out/logs/$t.log" 2>&1
  rc=$?
  echo "$t rc=$rc $(($(date +%s) - t0)) s" >> "$out/times.txt"
  grep -E "^\[  (PASSED|FAILED|SKIPPED) " "$out/logs/$t.log" | sed "s|^|$t: |" >> "$out/tests.txt"
}

cold() { # compile time of each scene's program from nothing, then the run from the cache
  local opts="-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3" o c
  local -a sets
  IFS='|' read -ra sets <<< "${COLD_OPTIONS:-}"
  [ ${#sets[@]} = 0 ] && sets=("")
  cd "$root/tests/data/scenes" || return
  for o in "${sets[@]}"; do
    for c in ${COLD_SCENES:-office_clear:office_grid luminaires:luminaires_grid}; do
      local pts=${c#*:}
      [[ $pts == *.* ]] || pts=$pts.pts
      rm -rf /tmp/radcl-cold ~/.nv/ComputeCache
      echo "== ${c%%:*} options '$o'"
      export RADCL_CL_OPTIONS=$o RADCL_CACHE_DIR=/tmp/radcl-cold
      /usr/bin/time -f "first sensor, compiling: %e s" "$b/bin/rtrace" -h -I $opts "${c%%:*}.oct" \
        < <(head -n 1 "$pts") > /dev/null
      for k in 1 2 3; do
        /usr/bin/time -f "all sensors, cached: %e s" "$b/bin/rtrace" -n "$(nproc)" -u- -h -I \
          $opts "${c%%:*}.oct" < "$pts" > "$out/cold_${c%%:*}_${#o}.txt"
      done
      # The programs' sizes: NVIDIA's binaries are PTX text, its functions' lengths in lines.
      for f in /tmp/radcl-cold/programs/*.bin; do
        echo "$(basename "$f"): $(wc -c < "$f") bytes"
        awk '/^\.(visible |weak )?\.?(entry|func)/ { n = $0; s = NR }
          /^}/ && n != "" { printf "  %d lines %s\n", NR - s, n; n = "" }' "$f" | sort -rn | head -6
      done
    done
  done
  unset RADCL_CL_OPTIONS
  export RADCL_CACHE_DIR=/tmp/radcl-cache
  cd "$root" || return
}

profile() { # each case's wall time and the renderer's phases
  local opts="-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3" dev=${PROFILE_DEVICE:-nvidia}
  timed() { RADCL_DEVICE=$dev RADCL_PROFILE=1 /usr/bin/time -f "%e s wall, %U s user" "$@" > /dev/null; }
  cd "$root/tests/data/scenes" || return
  head -n 1 office_grid.pts | RADCL_DEVICE=$dev "$b/bin/rtrace" -h -I $opts office_clear.oct > /dev/null
  for c in office_clear:office_grid office_overcast:office_grid luminaires:luminaires_grid; do
    echo "== ${c%%:*}"
    head -n 1 "${c#*:}.pts" | RADCL_DEVICE=$dev "$b/bin/rtrace" -h -I $opts "${c%%:*}.oct" > /dev/null
    timed "$b/bin/rtrace" -n "$(nproc)" -u- -h -I $opts "${c%%:*}.oct" < "${c#*:}.pts"
  done
  echo "== sphere -ab 4"
  timed "$b/bin/rtrace" -n "$(nproc)" -u- -h -I -ab 4 -ad 1024 -as 256 -aa 0.1 -ar 64 -lw 1e-5 \
    sphere.oct < sphere_wall.pts
  echo "== rpict office_view 256"
  RADCL_DEVICE=$dev "$b/bin/rpict" -u- -vf office.vf -x 16 -y 16 -ab 2 -ad 1024 -as 256 -aa 0.15 \
    -ar 128 office_clear.oct > /dev/null
  timed "$b/bin/rpict" -u- -vf office.vf -x 256 -y 256 -ab 2 -ad 1024 -as 256 -aa 0.15 -ar 128 \
    office_clear.oct
  cd "$root" || return
}

for what in "$@"; do
  echo "=== $what $(date +%T)"
  case $what in
  devices) RADCL_DEVICE=nvidia "$b/bin/radcl" devices --check ;;
  tests) RADCL_DEVICE=nvidia tests ;;
  bench) RADCL_DEVICE=nvidia BENCH_REPEAT=${BENCH_REPEAT:-3} "$root/tests/bench/ambient_cache.sh" "$b/build" "$(nproc)" 2>&1 | tee "$out/bench_gpu.txt" ;;
  cost) RADCL_DEVICE=nvidia OUT_DIR=$out "$root/tests/bench/cost_study.sh" "$b/build" "$(nproc)" 2>&1 | tee "$out/cost_gpu.txt" ;;
  peers) RADCL_DEVICE=nvidia PEERS_OUT=$out "$root/tests/bench/peers.sh" ${PEERS_ARGS:-} "$b/build" 2>&1 | tee "$out/peers_gpu.txt" ;;
  peers-cpu) RADCL_DEVICE=pocl PEERS_OUT=$out/pocl "$root/tests/bench/peers.sh" ${PEERS_ARGS:-} "$b/build" 2>&1 | tee "$out/peers_pocl.txt" ;;
  bench-cpu) RADCL_DEVICE=pocl "$root/tests/bench/ambient_cache.sh" "$b/build" "$(nproc)" 2>&1 | tee "$out/bench_pocl.txt" ;;
  profile) profile 2>&1 | tee "$out/profile.txt" ;;
  sh) b=$b out=$out bash -c "${DEVICE_SH:?set DEVICE_SH}" 2>&1 | tee -a "$out/sh.txt" ;;
  cold) RADCL_DEVICE=nvidia cold 2>&1 | tee "$out/cold.txt" ;;
  rounds) (cd "$root/tests/data/scenes" && RADCL_DEVICE=nvidia RADCL_DEBUG_CACHE=1 "$b/bin/rtrace" \
      -n "$(nproc)" -u- -h -I -ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3 office_clear.oct \
      < office_grid.pts 2>&1 >/dev/null | awk '/round/ { n = $6
      b = n < 64 ? "<64" : n < 1024 ? "<1024" : n < 8192 ? "<8192" : ">=8192"
      c[b]++; t[b] += $12; r[b] += n }
      END { for (k in c) printf "rays %s: %d rounds, %.3f s, %d rays\n", k, c[k], t[k], r[k] }') ;;
  esac
done
