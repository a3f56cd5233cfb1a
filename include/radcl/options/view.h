// Radiance views as options see them (image.c): the -v* options, view lines in headers and
// view files, the canonical " -vt? -vp ..." form, and setview()'s checks and derived vectors.
#pragma once

#include "radcl/options/args.h"

#include <array>
#include <iosfwd>
#include <string>
#include <string_view>

namespace radcl::options {

using Vec3 = std::array<double, 3>;

struct View {
  char type = 'v';         // -vt: v l c h a s
  Vec3 point{0, 0, 0};     // -vp
  Vec3 direction{0, 1, 0}; // -vd (unit after setup_view)
  Vec3 up{0, 0, 1};        // -vu (unit after setup_view)
  double focal = 1.0;      // |-vd| after setup_view; -vd resets it to 1 before that
  double horiz = 45;       // -vh
  double vert = 45;        // -vv
  double fore = 0;         // -vo
  double aft = 0;          // -va
  double shift = 0;        // -vs
  double lift = 0;         // -vl
  // Set by setup_view(): image-plane vectors (scaled per type) and squared extents.
  Vec3 hvec{0, 0, 0}, vvec{0, 0, 0};
  double hn2 = 0, vn2 = 0;
};

// Radiance's getviewopt() on args[i]: returns the number of values consumed, or -1 when it is
// not a well-formed view option (including -vf, which the program handles itself).
int parse_view_option(View& v, const ArgList& args, std::size_t i);

// sscanview(): applies every view option found in `line`, skipping other words; returns the
// number applied.
int scan_view_line(View& v, std::string_view line);

// isview(): the line's first word, less any directory prefix, starts with "VIEW=", the
// program's own name (basename of `progname`), "rpict", "rview", "rvu", "rpiece" or "pinterp".
bool is_view_line(std::string_view line, std::string_view progname);

// viewfile(): reads header lines (until an empty line or EOF) from `name` ("-" = `stdin_in`)
// and applies every view line. Returns -1 if the file cannot be opened, else the number of view
// lines that set something (0 means "bad view file").
int read_view_file(const std::string& name, View& v, std::string_view progname,
                   std::istream* stdin_in = nullptr);
int read_view_header(std::istream& in, View& v, std::string_view progname);

// fprintview(): " -vt%c -vp %.6g %.6g %.6g -vd ... -vl %.6g" (leading space included);
// -vd is the direction times the focal distance.
std::string format_view(const View& v);

// setview(): checks the view and computes its derived fields. Returns "" or Radiance's message
// ("illegal fore/aft clipping plane", "zero view direction", "unknown view type", ...).
std::string setup_view(View& v);

} // namespace radcl::options
