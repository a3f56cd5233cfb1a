#!/usr/bin/env bash
# What a change to the kernels does to the programs of scenes that do not use it: each program
# radcl dumped (RADCL_DUMP_PROGRAMS=DIR/<scene>, one folder per scene) is rebuilt from the
# kernels of git revision REV and from the working tree, with the dump's own options and its
# generated.cl, preprocessed by clang, and the two compared. Prints each scene's differing
# lines (none: the scene's program is the same code).
# usage: scripts/program-diff.sh DIR [REV] [CLANG]
set -euo pipefail
dir=$1
rev=${2:-HEAD}
cc=${3:-clang}
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/rev"
git -C "$root" archive "$rev" kernels include | tar -x -C "$tmp/rev"
# generated.cl back out of a flattened dump: its own lines, with #include where others began.
degenerate() {
  python3 - "$1" "$2" <<'PY'
import re, sys
lines = open(sys.argv[1]).read().split("\n")
files, stack, cur = {}, [], None
for l in lines[1:]:
    m = re.match(r'#line (\d+) "(.*)"$', l)
    if m:
        n, f = int(m.group(1)), m.group(2)
        if n == 1 and f not in stack:
            if cur is not None:
                files.setdefault(cur, []).append('#include "%s"' % f)
            stack.append(f)
        else:
            while stack and stack[-1] != f:
                stack.pop()
        cur = f
        files.setdefault(f, [])
        continue
    files.setdefault(cur, []).append(l)
open(sys.argv[2], "w").write("\n".join(files["generated.cl"]) + "\n")
PY
}
for s in "$dir"/*/; do
  for f in "$s"*.cl; do
    opts=$(head -1 "$f" | sed 's|^// options: ||')
    grep -q RADCL_HAS_ <<<"$opts" || continue
    for v in rev tree; do
      src=$tmp/$v-k
      rm -rf "$src"
      if [ $v = rev ]; then cp -r "$tmp/rev/kernels" "$src"; inc=$tmp/rev/include; else
        cp -r "$root/kernels" "$src"; inc=$root/include; fi
      degenerate "$f" "$src/generated.cl"
      # shellcheck disable=SC2086 # the options are words
      "$cc" -E -P -x cl $opts -I "$src" -I "$inc" "$src/render/shade.cl" | clang-format > "$tmp/$v.i"
    done
    echo "== $(basename "$s")"
    diff "$tmp/rev.i" "$tmp/tree.i" || true
  done
done
