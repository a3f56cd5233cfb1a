#!/usr/bin/env bash
# Packs what a run on the lent GPU machine needs into .devlibs/ (git-ignored, named in the
# device tool's `carry`): a build's programs and device-facing test executables, the shared
# libraries that machine lacks (Embree, TBB, the ICD loader), GNU time for the benchmarks, and
# the reference results the benchmarks read. With RADIANCE_BIN set, Radiance's rtrace and rpict
# from there (and the .cal files of the folders in RADIANCE_LIB, a
# colon list) go along for same-machine comparisons; they
# stay outside the repository (with oconv and vwrays for tests/bench/peers.sh). Build with -DRADCL_WITH_OIIO=OFF: OpenImageIO is not carried.
#
# usage: scripts/device-bundle.sh [build-dir]      then scripts/device-run.sh on the device
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build-gpu}" && pwd)
ref=${RADCL_REFERENCE:-$root/../shared/reference}
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage"/{bin,lib,ref,radiance}
cp "$build"/bin/{radcl,rtrace,rpict,gensky} "$stage/bin/"
[ -e "$build/bin/rcontrib" ] && cp "$build/bin/rcontrib" "$stage/bin/"
for t in "$build"/bin/bench_{gen_scenes,picture_mean,embree_rays}; do # peers.sh helpers, the Embree limit
  if [ -e "$t" ]; then cp "$t" "$stage/bin/"; fi
done
for t in "$build"/bin/test_{render,cli,device,calc,ambient}_*; do
  if [ -e "$t" ]; then cp "$t" "$stage/bin/"; fi # a build of the programs alone has none
done
cp /usr/bin/time "$stage/bin/gnu-time"
# Every library outside glibc and the C++ runtime, which that machine has in newer versions.
ldd "$build"/bin/{radcl,rtrace,rpict} $(ls "$build"/bin/rcontrib 2>/dev/null) $(ls "$stage"/bin/test_* 2>/dev/null) | awk '$3 ~ /^\// { print $3 }' |
  sort -u | grep -Ev '/(libc|libm|libgcc_s|libstdc\+\+|ld-linux[^/]*)\.so' |
  xargs -r cp -L -t "$stage/lib/"
cp -r "$ref/results" "$stage/ref/"
if [ -n "${RADIANCE_BIN:-}" ]; then
  cp "$RADIANCE_BIN"/{rtrace,rpict} "$stage/radiance/"
  for p in oconv vwrays rcontrib rfluxmtx; do # peers.sh: the open-plan octrees, rays from a view; rcontrib.sh
    if [ -e "$RADIANCE_BIN/$p" ]; then cp "$RADIANCE_BIN/$p" "$stage/radiance/"; fi
  done
  IFS=: read -ra libs <<< "${RADIANCE_LIB:-}"
  for d in "${libs[@]}"; do cp "$d"/*.cal "$stage/radiance/" 2>/dev/null || true; done
fi
mkdir -p "$root/.devlibs"
tar -C "$stage" -cJf "$root/.devlibs/bundle.tar.xz" .
du -h "$root/.devlibs/bundle.tar.xz"
