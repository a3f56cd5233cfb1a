#!/bin/sh
# Regenerates the reference bin numbers in tests/data/calc/bins/ that
# tests/calc/bin_functions.cpp compares radcl's lib/*.cal bin functions with.
#
#   RADIANCE_BIN=/path/to/radiance/bin \
#   RAYPATH=/path/to/Radiance/src/cal/cal:/path/to/Radiance/src/util \
#     sh tests/data/calc/make_bins.sh
#
# RADIANCE_BIN  folder holding Radiance's rcalc (already built: this script never builds
#               Radiance).
# RAYPATH       where Radiance's own tregenza.cal, reinhart.cal (src/cal/cal in the source,
#               lib/ once installed), reinhartb.cal, klems_full.cal, klems_half.cal,
#               klems_quarter.cal and disk2square.cal (src/util) are found. Each file is taken
#               from the first folder that has it, and must be Radiance's (its RCSid line),
#               not radcl's.
#
# The directions are made here with awk (deterministic: Halton points and points on and beside
# every patch edge); Radiance's rcalc evaluates its own .cal files on them. Each output file
# starts with '#' lines naming the file, the definitions made before and after loading it, the
# bin expressions and the bin count; then one line per direction: Dx Dy Dz and the bin of each
# expression. Needs a POSIX shell, awk, paste and an od that prints doubles with enough digits
# to read them back exactly (GNU coreutils 9 does; checked below).
#
# rcalc's warnings are summed up per file. Expected: "domain error"s for disk2square_sc16, whose
# normal is a little longer than 1 (Radiance's disk2square.cal takes a square root of a negative
# number next to it; lib/disk2square.cal explains what that does to the bin).
set -euf

here=$(cd "$(dirname "$0")" && pwd)
out="$here/bins"
: "${RADIANCE_BIN:?set RADIANCE_BIN to the folder of Radiance's rcalc}"
: "${RAYPATH:?set RAYPATH to the folders of Radiance's .cal files}"
rcalc="$RADIANCE_BIN/rcalc"
[ -x "$rcalc" ] || { echo "make_bins: no rcalc in $RADIANCE_BIN" >&2; exit 1; }
export RAYPATH
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case $("$rcalc" -n -od -e '$1=1/3' | od -A n -t f8 | tr -d ' ') in
  0.333333333333333[0-9]*) ;;
  *) echo "make_bins: od does not print doubles in full" >&2; exit 1 ;;
esac

# The path of Radiance's file $1 on RAYPATH.
radiance_file() {
  old_ifs=$IFS
  IFS=:
  for dir in $RAYPATH; do
    if [ -f "$dir/$1" ]; then
      IFS=$old_ifs
      if ! grep -q 'RCSid' "$dir/$1" || grep -q "radcl's own" "$dir/$1"; then
        echo "make_bins: $dir/$1 is not Radiance's file" >&2
        exit 1
      fi
      echo "$dir/$1"
      return
    fi
  done
  IFS=$old_ifs
  echo "make_bins: $1 not found on RAYPATH" >&2
  exit 1
}

# Direction generator. Variables:
#   kind   alt: altitude from the surface plane, azimuth from the up direction towards
#               -RHS*(U x N) (tregenza.cal, reinhart.cal, reinhartb.cal)
#          pol: angle from the normal, azimuth from -RHS*(U x N) towards -U (klems_*.cal)
#          disk: Shirley-Chiu square cells (disk2square.cal)
#   frames "nx,ny,nz,ux,uy,uz,rhs;..." surface frames to put edge points in (the sky is
#          normal 0,0,-1, up 0,1,0, rhs 1)
#   edges  alt/pol: the rows' lower (alt) or upper (pol) limits in degrees, comma separated
#   counts alt/pol: patches per row, comma separated
#   scdim  disk: cells per side
#   nrand  Halton points over the whole sphere; as many again over each frame's hemisphere
gen_dirs() {
  awk -v kind="$1" -v frames="$2" -v edges="$3" -v counts="$4" -v scdim="$5" -v nrand="$6" '
function halton(i, b,    f, r) { f = 1; r = 0; while (i > 0) { f /= b; r += f * (i % b); i = int(i / b) } return r }
function asin(x) { return atan2(x, sqrt(1 - x * x)) }
function exact(x, y, z) { printf "%.17g %.17g %.17g\n", x, y, z; n_exact++ }
function rough(x, y, z) { printf "%.8g %.8g %.8g\n", x, y, z }
# local frame of frame f: ez against the normal, ey along (alt) or against (pol, disk) the
# up direction part in the plane, ex along -RHS*(U x N)
function set_frame(f,    p, nl, ul, cx, cy, cz, cl, un) {
  split(f, p, ",")
  nl = sqrt(p[1]*p[1] + p[2]*p[2] + p[3]*p[3])
  nx = p[1]/nl; ny = p[2]/nl; nz = p[3]/nl
  un = p[4]*nx + p[5]*ny + p[6]*nz
  uy_x = p[4] - un*nx; uy_y = p[5] - un*ny; uy_z = p[6] - un*nz
  ul = sqrt(uy_x*uy_x + uy_y*uy_y + uy_z*uy_z)
  uy_x /= ul; uy_y /= ul; uy_z /= ul
  cx = p[5]*nz - p[6]*ny; cy = p[6]*nx - p[4]*nz; cz = p[4]*ny - p[5]*nx
  cl = sqrt(cx*cx + cy*cy + cz*cz)
  exx = -p[7]*cx/cl; exy = -p[7]*cy/cl; exz = -p[7]*cz/cl
  sgn = (kind == "alt") ? 1 : -1
  eyx = sgn*uy_x; eyy = sgn*uy_y; eyz = sgn*uy_z
  ezx = -nx; ezy = -ny; ezz = -nz
}
# direction from local components
function local(a, b, c, how) {
  if (how == "exact") exact(a*exx + b*eyx + c*ezx, a*exy + b*eyy + c*ezy, a*exz + b*eyz + c*ezz)
  else rough(a*exx + b*eyx + c*ezx, a*exy + b*eyy + c*ezy, a*exz + b*eyz + c*ezz)
}
# elevation e (alt: from the plane; pol: from the normal) and azimuth a, in degrees
function angles(e, a, how,    s, c, ca, sa) {
  if (kind == "alt") { s = sin(e*D); c = cos(e*D); local(c*sin(a*D), c*cos(a*D), s, how) }
  else { s = sin(e*D); c = cos(e*D); local(s*cos(a*D), s*sin(a*D), c, how) }
}
# Shirley-Chiu: square point (x,y) in [0,1]^2 to the hemisphere
function square(x, y, how,    u, v, r, phi, dx, dy, z2) {
  u = 2*x - 1; v = 2*y - 1
  if (u*u > v*v) { r = u; phi = (PI/4)*(v/u) }
  else if (v != 0) { r = v; phi = PI/2 - (PI/4)*(u/v) }
  else { r = 0; phi = 0 }
  dx = r*cos(phi); dy = r*sin(phi); z2 = 1 - dx*dx - dy*dy
  local(dx, dy, sqrt(z2 > 0 ? z2 : 0), how)
}
BEGIN {
  PI = atan2(0, -1); D = PI/180
  nf = split(frames, fr, ";")
  ne = split(edges, ed, ","); nc = split(counts, cn, ",")
  # the whole sphere, quasi-random
  for (i = 1; i <= nrand; i++) {
    z = 2*halton(i, 2) - 1; a = 2*PI*halton(i, 3); s = sqrt(1 - z*z)
    rough(s*cos(a), s*sin(a), z)
  }
  # the axes, signed zeros, the diagonals
  exact(0, 0, 1); exact(0, 0, -1); exact(1, 0, 0); exact(-1, 0, 0); exact(0, 1, 0)
  exact(0, -1, 0)
  print "0 1 -0"; print "-0 1 0"; print "-0 -1 0"; print "0 -1 -0"; print "-0 -0 1"
  print "-0 -0 -1"; print "1 -0 -0"; print "-1 -0 0"
  for (i = 0; i < 8; i++) { a = i*PI/4; exact(cos(a)*sqrt(.5), sin(a)*sqrt(.5), sqrt(.5)) }
  for (f = 1; f <= nf; f++) {
    set_frame(fr[f])
    # the frame hemisphere, quasi-random
    for (i = 1; i <= nrand; i++) {
      c = halton(i + 7, 2); a = 2*PI*halton(i + 7, 3); s = sqrt(1 - c*c)
      local(s*cos(a), s*sin(a), c, "rough")
    }
    local(0, 0, 1, "exact"); local(0, 0, -1, "exact")
    if (kind == "disk") {
      # cell centres, cell edges, cell corners, the diagonals and the centre of the square
      for (i = 0; i < scdim; i++)
        for (j = 0; j < scdim; j++) square((i + .5)/scdim, (j + .5)/scdim, "rough")
      for (i = 0; i <= scdim; i++) {
        x = i/scdim
        for (j = 0; j < 4; j++) {
          y = halton(j + 1 + i*4, 2)
          square(x, y, "exact"); square(y, x, "exact")
          square(x + 1e-12, y, "exact"); square(y, x - 1e-12, "exact")
        }
        for (j = 0; j <= scdim; j++) square(x, j/scdim, "exact")
        square(x, x, "exact"); square(x, 1 - x, "exact")
      }
      # near the normal (the in-plane part below the 1e-7 threshold) and the plane
      for (i = 0; i < 8; i++) {
        a = i*PI/4 + .1
        t = 1e-4*(i + 1)
        local(t*cos(a), t*sin(a), sqrt(1 - t*t), "exact")
        local(cos(a), sin(a), 1e-9*i, "exact")
        local(cos(a), sin(a), -1e-9*i, "exact")
      }
      continue
    }
    # each row: every patch centre, azimuth edges (at most six, spread round the row), the wrap
    for (r = 1; r <= nc; r++) {
      if (kind == "alt") {
        lo = ed[r]; hi = (r < ne) ? ed[r + 1] : 90
      } else {
        lo = (r > 1) ? ed[r - 1] : 0; hi = ed[r]
      }
      mid = (lo + hi)/2
      w = 360/cn[r]
      for (k = 0; k < cn[r]; k++) angles(mid, k*w, "rough")
      step = int((cn[r] + 5)/6)
      for (k = 0; k < cn[r]; k += step) {
        a = (k + .5)*w
        angles(mid, a, "exact"); angles(mid, a + 1e-11, "exact"); angles(mid, a - 1e-11, "exact")
      }
      for (j = -2; j <= 2; j++) angles(mid, 360 - w/2 + j*4e-5, "exact")
      angles(mid, 0, "exact"); angles(mid, 360 - 1e-12, "exact"); angles(mid, 180, "exact")
    }
    # each row limit: a few azimuths, on the limit and a hair either side
    for (r = 1; r <= ne; r++) {
      for (j = 0; j < 3; j++) {
        a = 360*halton(j + 3*r, 2)
        angles(ed[r], a, "exact")
        angles(ed[r] + 1e-11, a, "exact"); angles(ed[r] - 1e-11, a, "exact")
      }
    }
    for (j = 0; j < 8; j++) {
      a = j*45
      angles(0, a, "exact"); angles(90, a, "exact"); angles(90 - 1e-9, a, "exact")
      if (kind == "pol") angles(90 + 1e-9, a, "exact")
      else angles(-1e-9, a, "exact")
    }
  }
}'
}

# make NAME FILE BEFORE AFTER BINS COUNT KIND FRAMES EDGES COUNTS SCDIM NRAND
#   BEFORE/AFTER: definitions made before/after loading FILE ("" for none)
#   BINS: bin expressions, space separated (none may contain a space); COUNT: the bin count
make() {
  name=$1 file=$2 before=$3 after=$4 bins=$5 count=$6
  path=$(radiance_file "$file")
  gen_dirs "$7" "$8" "$9" "${10}" "${11}" "${12}" > "$work/dirs"
  set -- $bins
  outs='' n=1
  for b in "$@"; do
    outs="$outs\$$n=$b;"
    n=$((n + 1))
  done
  pre='' post=''
  [ -n "$before" ] && pre="-e $before"
  [ -n "$after" ] && post="-e $after"
  # shellcheck disable=SC2086
  "$rcalc" $pre -f "$path" $post -e 'Dx=$1;Dy=$2;Dz=$3' -e "$outs" < "$work/dirs" \
    2> "$work/warnings" | tr '\t' ' ' > "$work/bins"
  # shellcheck disable=SC2086
  nbins=$("$rcalc" -n $pre -f "$path" $post -e "\$1=$count")
  [ "$(wc -l < "$work/dirs")" -eq "$(wc -l < "$work/bins")" ] ||
    { echo "make_bins: rcalc lost lines for $name" >&2; exit 1; }
  {
    echo "# Radiance's bins for radcl's tests/calc/bin_functions.cpp, made by"
    echo "# tests/data/calc/make_bins.sh with Radiance's rcalc and its own $file."
    echo "# file: $file"
    echo "# before: $before"
    echo "# after: $after"
    echo "# bins: $bins"
    echo "# count: $count $nbins"
    echo "# columns: Dx Dy Dz, then the bin of each expression above"
    paste -d ' ' "$work/dirs" "$work/bins"
  } > "$out/$name.txt"
  echo "$name.txt: $(wc -l < "$work/dirs") directions, $count = $nbins"
  if [ -s "$work/warnings" ]; then
    echo "  rcalc warned:"
    sort "$work/warnings" | uniq -c
  fi
}

sky='0,0,-1,0,1,0,1'
treg_alt='0,12,24,36,48,60,72,84'
treg_n='30,30,24,24,18,12,6,1'

# Reinhart rows for MF: lower limits k*90/(7*MF+.5) and patches per row
reinhart_rows() {
  awk -v mf="$1" 'BEGIN {
    split("30,30,24,24,18,12,6", t, ",")
    h = 90/(7*mf + .5); e = ""; c = ""
    for (r = 0; r <= 7*mf; r++) {
      e = e (r ? "," : "") sprintf("%.17g", r*h)
      c = c (r ? "," : "") (r < 7*mf ? mf*t[int(r/mf) + 1] : 1)
    }
    print e " " c
  }'
}

make tregenza tregenza.cal '' '' tbin Ntbins alt "$sky" "$treg_alt" "$treg_n" 0 300

for mf in 1 2 4; do
  set -- $(reinhart_rows $mf)
  make "reinhart_mf$mf" reinhart.cal "MF:$mf" '' rbin Nrbins alt "$sky" "$1" "$2" 0 $((200 / mf))
done

# reinhartb.cal as rfluxmtx sets it up (-p after the file): the defaults; a wall, left-handed;
# a tilted surface with normal and up as rfluxmtx prints them (%g)
set -- $(reinhart_rows 1)
make reinhartb_mf1 reinhartb.cal '' '' rbin Nrbins alt "$sky" "$1" "$2" 0 150
set -- $(reinhart_rows 2)
make reinhartb_mf2 reinhartb.cal '' 'MF=2;rNx=0;rNy=1;rNz=0;Ux=0;Uy=0;Uz=1;RHS=-1' rbin Nrbins \
  alt '0,1,0,0,0,1,-1' "$1" "$2" 0 100
set -- $(reinhart_rows 4)
make reinhartb_mf4 reinhartb.cal '' \
  'MF=4;rNx=0.707107;rNy=0;rNz=-0.707107;Ux=0;Uy=0;Uz=1;RHS=+1' rbin Nrbins \
  alt '0.707107,0,-0.707107,0,0,1,1' "$1" "$2" 0 50

klems_f_lim='5,15,25,35,45,55,65,75,90'
klems_f_n='1,8,16,20,24,24,24,16,12'
make klems_full klems_full.cal '' '' \
  'kbinN kbinE kbinS kbinW kbinD kbin(0,0,1,0,1,0) kbin(0.707107,0,-0.707107,0,0,1)' Nkbins \
  pol '0,-1,0,0,0,1,1;0.707107,0,-0.707107,0,0,1,1' "$klems_f_lim" "$klems_f_n" 0 150
make klems_full_lh klems_full.cal '' 'RHS=-1' 'kbinS kbin(0,0,1,0,1,0)' Nkbins \
  pol '0,1,0,0,0,1,-1;0,0,1,0,1,0,-1' "$klems_f_lim" "$klems_f_n" 0 150
make klems_half klems_half.cal '' 'RHS=+1' 'khbin(0,0,1,0,1,0) khbin(0,-1,0,0,0,1)' Nkhbins \
  pol '0,0,1,0,1,0,1;0,-1,0,0,0,1,1' '6.5,19.5,32.5,46.5,61.5,76.5,90' '1,8,12,16,20,12,4' 0 200
make klems_quarter klems_quarter.cal '' 'RHS=-1' 'kqbin(0,0,1,0,1,0) kqbin(0,-1,0,0,0,1)' Nkqbins \
  pol '0,0,1,0,1,0,-1;0,-1,0,0,0,1,-1' '9,27,46,66,90' '1,8,12,12,8' 0 200

make disk2square_sc4 disk2square.cal '' 'SCdim=4;rNx=0;rNy=0;rNz=-1;Ux=0;Uy=1;Uz=0;RHS=+1' \
  scbin 'SCdim*SCdim' disk '0,0,-1,0,1,0,1' '' '' 4 200
make disk2square_sc7 disk2square.cal '' 'SCdim=7;rNx=0;rNy=1;rNz=0;Ux=0;Uy=0;Uz=1;RHS=-1' \
  scbin 'SCdim*SCdim' disk '0,1,0,0,0,1,-1' '' '' 7 200
make disk2square_sc16 disk2square.cal '' \
  'SCdim=16;rNx=0.707107;rNy=0;rNz=-0.707107;Ux=0;Uy=0;Uz=1;RHS=+1' \
  scbin 'SCdim*SCdim' disk '0.707107,0,-0.707107,0,0,1,1' '' '' 16 150

# disk2square.cal's two maps on their own: square -> disk and disk -> square, full precision
# (rcalc -od, decoded by od)
path=$(radiance_file disk2square.cal)
awk 'function halton(i, b,    f, r) { f = 1; r = 0; while (i > 0) { f /= b; r += f * (i % b); i = int(i / b) } return r }
BEGIN {
  for (i = 0; i <= 8; i++) for (j = 0; j <= 8; j++) printf "%.17g %.17g\n", i/8, j/8
  for (i = 1; i <= 200; i++) printf "%.9g %.9g\n", halton(i, 2), halton(i, 3)
}' > "$work/square"
"$rcalc" -od -f "$path" -e 'in_square_x=$1;in_square_y=$2;$1=out_disk_x;$2=out_disk_y' \
  < "$work/square" | od -A n -v -t f8 -w16 | awk '{ print $1, $2 }' > "$work/disk"
awk 'function halton(i, b,    f, r) { f = 1; r = 0; while (i > 0) { f /= b; r += f * (i % b); i = int(i / b) } return r }
BEGIN {
  PI = atan2(0, -1)
  print "0 0"
  for (i = 0; i < 16; i++) printf "%.17g %.17g\n", cos(i*PI/8), sin(i*PI/8)
  for (i = 0; i < 16; i++) printf "%.17g %.17g\n", .5*cos(i*PI/8), .5*sin(i*PI/8)
  for (i = 1; i <= 200; i++) {
    r = sqrt(halton(i, 2)); a = 2*PI*halton(i, 3); printf "%.9g %.9g\n", r*cos(a), r*sin(a)
  }
}' > "$work/indisk"
"$rcalc" -od -f "$path" -e 'in_disk_x=$1;in_disk_y=$2;$1=out_square_x;$2=out_square_y' \
  < "$work/indisk" | od -A n -v -t f8 -w16 | awk '{ print $1, $2 }' > "$work/outsquare"
{
  echo "# Radiance's Shirley-Chiu maps for radcl's tests/calc/bin_functions.cpp, made by"
  echo "# tests/data/calc/make_bins.sh with Radiance's rcalc (-od, decoded by od) and its own"
  echo "# disk2square.cal."
  echo "# square: in_square_x in_square_y out_disk_x out_disk_y"
  paste -d ' ' "$work/square" "$work/disk"
  echo "# disk: in_disk_x in_disk_y out_square_x out_square_y"
  paste -d ' ' "$work/indisk" "$work/outsquare"
} > "$out/disk2square_maps.txt"
echo "disk2square_maps.txt: $(wc -l < "$work/square") square points, $(wc -l < "$work/indisk") disk points"
