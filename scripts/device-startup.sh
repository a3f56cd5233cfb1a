#!/usr/bin/env bash
# Start-up on the device machine (issue 32, item 6): one sensor, warm (the scene's program
# compiled and cached by a first run), three times on each device, with where the time goes.
# Run by scripts/device-run.sh sh (DEVICE_SH='bash scripts/device-startup.sh').
set -uo pipefail
cd "$RADCL_TEST_DATA/scenes" || exit 1
for dev in nvidia pocl; do
  echo "2 2 0.8 0 0 1" | RADCL_DEVICE=$dev "$RADCL_BIN/rtrace" -h -I -ab 1 office_clear.oct > /dev/null 2>&1
  for k in 1 2 3; do
    echo "== $dev run $k"
    echo "2 2 0.8 0 0 1" | RADCL_DEVICE=$dev RADCL_PROFILE=1 /usr/bin/time -f "%e s wall, %U s user, %S s sys" \
      "$RADCL_BIN/rtrace" -h -I -ab 1 office_clear.oct 2>&1 >/dev/null | grep -E "wall|lifetime|build"
  done
done
# The same with the ICD loader given one driver's .icd file (it then opens only that driver):
# what loading every registered driver costs.
for f in "$OCL_ICD_VENDORS"/*.icd; do
  for k in 1 2 3; do
    echo "== only $(basename "$f") run $k"
    echo "2 2 0.8 0 0 1" | OCL_ICD_VENDORS=$f RADCL_PROFILE=1 /usr/bin/time -f "%e s wall, %U s user, %S s sys" \
      "$RADCL_BIN/rtrace" -h -I -ab 1 office_clear.oct 2>&1 >/dev/null | grep -E "wall|lifetime|build"
  done
done
