#!/usr/bin/env bash
# What accuracy costs in time on four scenes: `radcl cost` (docs/cost.md) on each, radcl's
# runs beside Radiance's (with RADIANCE_BIN set) in one go, every run timed and scored against
# the scene's converged or exact answer:
#   office_clear  77 sensors, -ab 5: the converged -ab 8 grid tests/data/results/office_clear_mc8.txt
#   luminaires    52 sensors, -ab 5: the converged -ab 7 grid luminaires_mc7.txt
# (converged in bounces too: the -ab 5 steps' errors include the light of bounces 6 to 8, 2.8% on
# the office and 1.4% in the luminaires room)
#   deep_plan    180 sensors, -ab 2: the exact answers deep_plan_exact.txt
#   sphere        24 sensors, -ab 4: the exact 4.2243 W/m2 of the integrating sphere
# Writes OUT_DIR/cost_<scene>.{md,tsv,svg} (OUT_DIR default .) and prints the tables.
# SCENES: a space-separated subset; TARGET: the error target (default 2%).
#
# usage: tests/bench/cost_study.sh [build-dir] [threads]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
threads=${2:-$(nproc)}
out=$(mkdir -p "${OUT_DIR:-.}" && cd "${OUT_DIR:-.}" && pwd)
data=$root/tests/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
radiance=()
[ -n "${RADIANCE_BIN:-}" ] && radiance=(-radiance "$RADIANCE_BIN")

# The exact answers as rtrace would print them (three channels per sensor).
grep -v '^#' "$data/results/deep_plan_exact.txt" | awk '{ print $1, $1, $1 }' > "$work/deep_plan.txt"
awk '{ print 4.2243111457229805, 4.2243111457229805, 4.2243111457229805 }' \
  "$data/scenes/sphere_wall.pts" > "$work/sphere.txt"

# Radiance reads octrees only: the deep plan's is made by its oconv (radcl reads either).
deep=deep_plan.rad
if [ -n "${RADIANCE_BIN:-}" ]; then
  (cd "$data/scenes" && "$RADIANCE_BIN/oconv" deep_plan.rad > "$work/deep_plan.oct")
  deep=$work/deep_plan.oct
fi

for s in ${SCENES:-office_clear luminaires deep_plan sphere}; do
  case $s in
    office_clear) args=(-ab 5 -ref "$data/results/office_clear_mc8.txt" office_clear.oct) grid=office_grid.pts ;;
    luminaires) args=(-ab 5 -ref "$data/results/luminaires_mc7.txt" luminaires.oct) grid=luminaires_grid.pts ;;
    # Exact answers at one -ab: the ladder keeps to it.
    deep_plan) args=(-ab 2 -ladder cache,mc,lw -ref "$work/deep_plan.txt" "$deep") grid=deep_plan_grid.pts ;;
    sphere) args=(-ab 4 -ladder cache,mc,lw -ref "$work/sphere.txt" sphere.oct) grid=sphere_wall.pts ;;
    *) echo "cost_study.sh: unknown scene $s" >&2; exit 2 ;;
  esac
  (cd "$data/scenes" && "$build/bin/radcl" cost -I -n "$threads" -target "${TARGET:-2%}" \
    "${radiance[@]}" -svg "$out/cost_$s.svg" -tsv "$out/cost_$s.tsv" "${args[@]}" < "$grid") |
    tee "$out/cost_$s.md"
  echo
done
