#!/usr/bin/env bash
# Stores Radiance's answers for the differential corpus (run outside CI, with a Radiance build;
# never needed by the tests themselves, which read what it stored).
#   RADIANCE_BIN=/path/to/radiance/bin RADIANCE_LIB=/path/to/its/lib tests/tools/corpus_radiance.sh
# For every scene tests/data/corpus/cNN.rad (written by corpus_gen.py) it writes, under
# tests/data/corpus/results/:
#   cNN_aa0.txt    8 independent draws without the cache: one rtrace -u+ run over the 12
#                  sensors repeated 8 times (each repetition draws other random numbers), at
#                  $CORPUS_AA0 plus the scene's extra options (index.tsv)
#   cNN_cache.txt  3 independent runs with the default cache settings ($CORPUS_CACHE), each
#                  its own process (clock-seeded, a second apart), one after the other
# and the frozen instance box.oct (oconv -f box.rad), which the scenes of family geometry read.
set -euo pipefail
: "${RADIANCE_BIN:?set RADIANCE_BIN to Radiance's bin folder}"
: "${RADIANCE_LIB:?set RADIANCE_LIB to Radiance's lib folder (skybright.cal)}"
CORPUS_AA0=${CORPUS_AA0:-"-ab 1 -aa 0 -ad 512 -lw 1e-4"}
CORPUS_CACHE=${CORPUS_CACHE:-"-ab 2"}
dir=$(cd "$(dirname "$0")/../data/corpus" && pwd)
cd "$dir"
mkdir -p results
export RAYPATH=.:$RADIANCE_LIB
"$RADIANCE_BIN/oconv" -f box.rad > box.oct
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
while IFS=$'\t' read -r scene family extra; do
  [[ $scene == \#* ]] && continue
  "$RADIANCE_BIN/oconv" "$scene.rad" > "$tmp/$scene.oct"
  for k in 1 2 3 4 5 6 7 8; do cat "$scene.pts"; done > "$tmp/rep.pts"
  # shellcheck disable=SC2086
  {
    echo "# Radiance: rtrace -h -I -u+ $CORPUS_AA0 $extra $scene.oct; 8 repetitions of $scene.pts"
    "$RADIANCE_BIN/rtrace" -h -I -u+ $CORPUS_AA0 $extra "$tmp/$scene.oct" < "$tmp/rep.pts"
  } > "results/${scene}_aa0.txt"
  {
    echo "# Radiance: rtrace -h -I -u+ $CORPUS_CACHE $extra $scene.oct, 3 runs a second apart"
    for k in 1 2 3; do
      sleep 1
      # shellcheck disable=SC2086
      "$RADIANCE_BIN/rtrace" -h -I -u+ $CORPUS_CACHE $extra "$tmp/$scene.oct" < "$scene.pts"
    done
  } > "results/${scene}_cache.txt"
  echo "$scene ($family) done" >&2
done < index.tsv
