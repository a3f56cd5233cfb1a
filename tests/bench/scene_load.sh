#!/usr/bin/env bash
# Scene-load benchmark: how long `radcl scene` takes to read a large mesh and a large .rad
# file, and to build Embree's scene from each. Builds nothing: give it a build directory that
# has bin/radcl and bin/bench_gen_scenes (a Release build, for numbers worth reporting).
#   tests/bench/scene_load.sh [build-dir] [mesh-triangles] [polygons]
# Prints one row per scene: file size, median load and build seconds of 3 runs, and
# triangles per second over load + build.
set -euo pipefail

build=$(cd "${1:-build}" && pwd)
mesh_tris=${2:-1000000}
polys=${3:-100000}
runs=3
radcl=$build/bin/radcl
gen=$build/bin/bench_gen_scenes
for exe in "$radcl" "$gen"; do
  [[ -x $exe ]] || { echo "scene_load.sh: missing $exe (build targets radcl, bench_gen_scenes)" >&2; exit 1; }
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" # the .rad file names the mesh relative to here, as Radiance finds it

"$gen" mesh "$mesh_tris" terrain.rtm >/dev/null
"$gen" polygons "$polys" tiles.rad >/dev/null

median() { sort -g | sed -n "$(((runs + 1) / 2))p"; }

# One row: name, file(s) measured for size, the scene input, triangle count.
bench() {
  local name=$1 sized=$2 input=$3 out loads=() builds=() tris
  for ((i = 0; i < runs; ++i)); do
    out=$("$radcl" scene --time "$input")
    loads+=("$(awk '/^load time/ {print $3}' <<<"$out")")
    builds+=("$(awk '/^build time/ {print $3}' <<<"$out")")
  done
  # "ray tracing     T triangles from P polygons, ..., M meshes (N triangles); ..."
  tris=$(awk '/^ray tracing/ {t = $3; n = $0; sub(/.*meshes \(/, "", n); sub(/ .*/, "", n); print t + n}' <<<"$out")
  local load build size
  load=$(printf '%s\n' "${loads[@]}" | median)
  build=$(printf '%s\n' "${builds[@]}" | median)
  size=$(du -cb $sized | tail -1 | cut -f1)
  awk -v n="$name" -v s="$size" -v l="$load" -v b="$build" -v t="$tris" 'BEGIN {
    printf "%-22s %10.1f MB %10d %9.3f %9.3f %12.0f\n", n, s / 1e6, t, l, b, t / (l + b) }'
}

printf '%-22s %13s %10s %9s %9s %12s\n' scene "file size" triangles "load s" "build s" "triangles/s"
bench "mesh ($mesh_tris tris)" "terrain.rtm terrain.rad" terrain.rad
bench "polygons ($polys)" tiles.rad tiles.rad
echo "(median of $runs runs; triangles/s = triangles / (load + build); $(nproc) cores)"
