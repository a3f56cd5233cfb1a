#!/usr/bin/env bash
# Turns the result files of one or more tests/bench/peers.sh runs (TSV: "# run: ..." lines
# describing each run, then one row per case: case, what, radcl s, Radiance s, speed-up, radcl
# error, Radiance error) into OUT.md (a table) and OUT.svg (a bar chart of the speed-ups on a
# log scale, with lines at 1x, 2x, 5x and 10x), so that runs made in separate calls on one
# machine read as one record.
#
# usage: tests/bench/peers_report.sh OUT title run.tsv...
set -euo pipefail
out=$1 title=$2
shift 2
tag=$(basename "$out")
{
  echo "# $title"
  echo
  echo "Made by \`tests/bench/peers.sh\` (cases and settings in its header). Runs:"
  echo
  grep -h '^# run: ' "$@" | sed 's/^# run: /- /'
  echo
  echo "![speed-ups]($tag.svg)"
  echo
  echo "| case | what | radcl s | Radiance s | speed-up | radcl error | Radiance error |"
  echo "|---|---|---:|---:|---:|---|---|"
  grep -hv '^#' "$@" | awk -F'\t' '{ printf "| %s | %s | %s | %s | %sx | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7 }'
  echo
  echo "Errors: P1 on office_grid.pts's 77 points against the converged -ab 5 answer (mean, worst"
  echo "luminance error); P5 against the exact answer; \"differ\" is the two renderers' mean"
  echo "difference where no converged answer exists (sampling noise of both, at these settings,"
  echo "dominates it). Times are wall-clock seconds of warm runs (the scene's device program"
  echo "compiled and cached beforehand)."
} > "$out.md"
grep -hv '^#' "$@" | awk -F'\t' '{ print $1, $5 }' | awk -v title="$title" '
  function y(v) { return 40 + 260 * (1 - (log(v) / log(10) + 1) / 3) }
  { c[NR] = $1; s[NR] = ($2 > 0.1 ? $2 : 0.1) }
  END {
    w = 80 + 90 * NR; if (w < 640) w = 640
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"340\" font-family=\"sans-serif\" font-size=\"12\">\n", w
    printf "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n"
    printf "<text x=\"10\" y=\"20\" font-size=\"14\">%s: radcl speed-up over Radiance (log scale)</text>\n", title
    split("0.1 1 2 5 10 100", g, " ")
    for (k = 1; k <= 6; k++) {
      printf "<line x1=\"60\" x2=\"%d\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"/>\n", w - 10, y(g[k]), y(g[k]), g[k] == 1 ? "black" : "#ccc"
      printf "<text x=\"10\" y=\"%.1f\">%sx</text>\n", y(g[k]) + 4, g[k]
    }
    for (k = 1; k <= NR; k++) {
      x = 70 + 90 * (k - 1); top = y(s[k]); base = y(1)
      col = s[k] >= 1 ? "#2a7" : "#c43"
      if (top < base) printf "<rect x=\"%d\" y=\"%.1f\" width=\"60\" height=\"%.1f\" fill=\"%s\"/>\n", x, top, base - top, col
      else printf "<rect x=\"%d\" y=\"%.1f\" width=\"60\" height=\"%.1f\" fill=\"%s\"/>\n", x, base, top - base, col
      printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"middle\">%.2fx</text>\n", x + 30, (top < base ? top - 4 : top + 14), s[k]
      printf "<text x=\"%d\" y=\"325\" text-anchor=\"middle\">%s</text>\n", x + 30, c[k]
    }
    print "</svg>"
  }' > "$out.svg"
echo "wrote $out.md and $out.svg"
