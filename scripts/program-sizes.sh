#!/usr/bin/env bash
# Sizes of the scene programs radcl dumped (RADCL_DUMP_PROGRAMS=DIR/<scene>, one folder per
# scene): each program compiled offline to NVIDIA PTX by clang (-O2), the scene program's size
# in bytes. Shows what a change to the kernels costs scenes that do not use it.
# usage: scripts/program-sizes.sh DIR [CLANG]
set -euo pipefail
dir=$1
cc=${2:-clang}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for s in "$dir"/*/; do
  for f in "$s"*.cl; do
    opts=$(head -1 "$f" | sed 's|^// options: ||')
    # The shared set-up program (no scene options) is left out: it is the same for every scene.
    grep -q RADCL_HAS_ <<<"$opts" || continue
    # shellcheck disable=SC2086 # the options are words
    "$cc" -x cl $opts -target nvptx64-nvidia-nvcl -O2 -S -o "$tmp/p.ptx" "$f"
    printf '%s\t%s\n' "$(basename "$s")" "$(stat -c %s "$tmp/p.ptx")"
  done
done
