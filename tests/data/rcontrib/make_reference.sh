#!/usr/bin/env bash
# Makes the Radiance rcontrib outputs tests/cli/golden_rcontrib.cpp compares radcl's with, on
# office_clear's room under a unit sky dome (office_dome.oct) and six unit suns
# (office_suns.oct), for the 12 sensors of office_sensors12.pts. Needs Radiance's programs in
# RADIANCE_BIN and its function files on RAYPATH; run by hand, never by the tests.
#   suns_radiance.txt        -I -ab 0 -dc 1 -dt 0 -dj 0 -M office_suns.mod (deterministic)
#   dome_mf1_{mean,se}.txt   -I -ab 1 -ad 2048 -lw 1e-5, Reinhart MF:1 (146 bins)
#   dome_mf2_{mean,se}.txt   -I -ab 2 -ad 512 -lw 1e-5, Reinhart MF:2 (578 bins)
#   vmx_kf_{mean,se}.txt     a view matrix to the window in Klems' full basis (145 bins), with
#                            the rcontrib command line rfluxmtx makes for
#     rfluxmtx -v -ab 1 -ad 2048 -lw 1e-4 -I - office_window_kf.rad -i office_open.oct
#                            on the octree it makes (oconv -f -i office_open.oct
#                            office_window_kf.rad > office_vmx.oct)
#   view_sky_{mean,se}.txt   a 16 x 12 picture's sky coefficients, -x 16 -y 12 -ab 1 -ad 256,
#                            from office_view_rays.f32 (vwrays -ff -pj 0 -x 16 -y 12 -vf
#                            office.vf)
# The Monte-Carlo cases are the mean and standard error of 8 independent runs (Radiance
# seeds its random numbers from the clock: the runs start a second apart); the picture's
# resolution string is left out.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rc=${RADIANCE_BIN:?set RADIANCE_BIN to Radiance\'s bin folder}/rcontrib
cd "$here/../scenes"
pts=$here/office_sensors12.pts
"$rc" -h -I -ab 0 -dc 1 -dt 0 -dj 0 -M office_suns.mod office_suns.oct < "$pts" > "$here/suns_radiance.txt"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dome="-f reinhart.cal -b rbin -bn Nrbins -m skyglow office_dome.oct"
vmx="-fo+ -ab 1 -ad 2048 -lw 1e-4 -I -faa -c 1 -f klems_full.cal -p RHS=+1 -bn Nkbins -b kbin(0,1,0,0,0,1) -m windowglow office_vmx.oct"
for c in "dome_mf1:-I -ab 1 -ad 2048 -lw 1e-5 -e MF:1 $dome" "dome_mf2:-I -ab 2 -ad 512 -lw 1e-5 -e MF:2 $dome" \
  "vmx_kf:$vmx" "view_sky:-ffa -x 16 -y 12 -ld- -ab 1 -ad 256 -lw 1e-4 -m skyglow office_dome.oct"; do
  name=${c%%:*}
  for k in 1 2 3 4 5 6 7 8; do
    # shellcheck disable=SC2086 # the options are words
    in=$pts
    [ "$name" = view_sky ] && in=$here/office_view_rays.f32
    "$rc" -h ${c#*:} < "$in" | sed '/^-Y /d' > "$work/$k.txt"
    sleep 1.1
  done
  # Per number: the mean over the runs and its standard error.
  awk -v out="$here/${name}" '
    FNR == 1 { f++ }
    { for (j = 1; j <= NF; j++) { s[FNR, j] += $j; q[FNR, j] += $j * $j }; nf[FNR] = NF; n = FNR }
    END {
      for (i = 1; i <= n; i++) {
        m = ""; e = ""
        for (j = 1; j <= nf[i]; j++) {
          mean = s[i, j] / f; var = (q[i, j] - f * mean * mean) / (f - 1); if (var < 0) var = 0
          m = m sprintf("%.6e\t", mean); e = e sprintf("%.6e\t", sqrt(var / f))
        }
        print m > (out "_mean.txt"); print e > (out "_se.txt")
      }
    }' "$work"/?.txt
  rm -f "$work"/?.txt
done
