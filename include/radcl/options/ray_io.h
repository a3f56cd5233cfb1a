// rtrace's ray input and output, the parts that need no renderer (Radiance's rtrace.c): the
// -o specification, reading rays in -fa/-ff/-fd, the values one ray reports (RayOutput) and
// their bytes in -fa/-ff/-fd/-fc, the information header, and the flush/count rules of -x/-y.
#pragma once

#include "radcl/options/render_options.h"

#include <array>
#include <ctime>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace radcl::options {

using Vec3 = std::array<double, 3>;

// "ascii", "float", "double", "32-bit_rle_rgbe" for 'a' 'f' 'd' 'c'; "unknown" otherwise.
const char* format_name(char format);

// -o<spec> split as setrtoutput() does.
struct OutputSpec {
  std::string per_ray;        // letters written once per input ray
  std::string per_traced;     // letters after t/T, written for every traced ray (trace mode)
  bool trace_sources = false; // a 'T' was given (shadow rays are traced too)
  bool cast_only = true;      // only geometric letters: no shading needed
  int ncomp = 0;              // NCOMP= value: reals per record, 0 in trace mode
  bool trace_mode() const { return !per_traced.empty(); }
};

// Throws FatalError "empty output specification" / "unrecognized output option 'q'".
OutputSpec parse_output_spec(std::string_view spec);

// The checks rtrace makes once options are known: FatalError "-oe requires -aa 0 (no
// irradiance cache)" (radcl's own letter); FatalError "-I+ and -i+ options require some
// value output"; warnings "-oVW options require trace mode", "-orRxX options incompatible
// with -I+ and -i+", "-otV accuracy depends on -aa 0 -as 0" (and -otW), in Radiance's order.
void check_output_spec(std::string_view spec, const OutputSpec& os, const RenderOptions& render,
                       bool immediate_irradiance);

// -fc is only for a spec that is exactly "v", "r" or "x": FatalError "color format only with
// -ov, -or, -ox".
void check_output_format(std::string_view spec, char out_format);

// Radiance's normalize(): scales `dir` to unit length (with its first-order shortcut near 1)
// and returns the old length; 0 for a zero vector (an rtrace flush request).
double normalize_direction(Vec3& dir);

// Reads rays (origin, direction: 6 numbers) in format 'a' (words, each a Radiance real of at
// most 31 characters; anything else ends the input), 'f' (host float32) or 'd' (host double).
class RayReader {
public:
  RayReader(std::istream& in, char format) : in_(in), format_(format) {}
  // False at the end of input (or a partial ray).
  bool read(Vec3& origin, Vec3& direction);

private:
  bool read_vec(Vec3& v);
  bool read_word(std::string& w);
  std::istream& in_;
  char format_;
};

// What one ray reports, in the units Radiance prints. A renderer fills it; the defaults are
// those of a ray that hit nothing (Radiance's rayclear()).
struct RayOutput {
  Vec3 origin{0, 0, 0};             // o
  Vec3 direction{0, 0, 0};          // d (normalized)
  Vec3 value{0, 0, 0};              // v: radiance, or irradiance with -i/-I
  Vec3 contribution{0, 0, 0};       // V: value times coefficient
  double weight = 1.0;              // w
  Vec3 coefficient{1, 1, 1};        // W
  double effective_length = 1e10;   // l
  double first_length = 1e10;       // L (1e10 = nothing hit)
  double u = 0, v = 0;              // c
  Vec3 point{0, 0, 0};              // p (= origin if nothing hit)
  Vec3 normal{0, 0, 0};             // n (perturbed; zero if nothing hit)
  Vec3 unperturbed_normal{0, 0, 0}; // N (zero if nothing hit)
  std::string surface = "*";        // s
  std::string modifier = "*";       // m ("void" for a void modifier)
  std::string material = "*";       // M
  Vec3 mirrored{0, 0, 0};           // r
  Vec3 unmirrored{0, 0, 0};         // x (Radiance: value - mirrored, computed in float)
  double mirrored_length = 1e10;    // R
  double unmirrored_length = 1e10;  // X
  Vec3 std_error{0, 0, 0};          // e (radcl's own): the standard error of v

  // The record Radiance prints for a flush request or a ray that hit nothing, given the ray.
  static RayOutput empty(const Vec3& origin, const Vec3& direction);
  // Sets `unmirrored` from value and mirrored as Radiance does (float colour channels).
  void derive_unmirrored();
};

// Appends one record: the values of `letters` in order, then '\n' in ascii. For 'f'/'d' reals
// are host-order binary; names (s m M) and '~' stay text followed by TAB. For 'c' each colour
// letter becomes one 4-byte RGBE value. `depth` TABs go first (trace-mode indentation).
void append_record(std::string& out, std::string_view letters, const RayOutput& r, char format,
                   int depth = 0);

// Radiance's setcolr(): 4-byte RGBE of a colour.
std::array<unsigned char, 4> to_rgbe(double r, double g, double b);

// printargs(): words separated by spaces, a word with whitespace or inner quotes quoted.
std::string format_command_line(const std::vector<std::string>& words);

// CAPDATE= (local time) and GMT= lines for `t`.
std::string format_capture_date(std::time_t t);

// The header rtrace writes unless -h-: the octree's header lines (without their FORMAT=
// line), the command line up to the octree, SOFTWARE=, CAPDATE=/GMT=, NCOMP= (when > 0),
// BigEndian= (for f/d), FORMAT=, empty line.
struct RtraceHeader {
  std::vector<std::string> octree_lines; // without newlines, e.g. "#?RADIANCE", "oconv x.rad"
  std::vector<std::string> command;      // argv[0] .. the word before the octree
  std::string software;                  // e.g. "RADIANCE 5.4a 2026-11-22 LBNL (5.2.Unknown)"
  std::time_t time = 0;
  int ncomp = 0;
  char out_format = 'a';
};
std::string format_rtrace_header(const RtraceHeader& h);

// "-Y <y> +X <x>\n", written after the header when both -x and -y are > 0.
std::string format_resolution(int xres, int yres);

// rtrace's -x/-y rules: how many rays to read and when to flush.
class RayFlow {
public:
  RayFlow(int xres, int yres);
  // A zero-direction record arrived (its empty record is written either way): true when the
  // output must be flushed now, i.e. rays were computed since the last flush.
  bool flush_request();
  // A ray was computed and written: true when the output must be flushed now.
  bool ray_done();
  // After every record: true when the -x/-y count is reached and reading must stop.
  bool record_done();
  // At end of input: true when a count was set and not reached ("unexpected EOF on input").
  bool incomplete() const { return remaining_ != 0; }
  // The flush interval used with -n (0 = none): rtrace lowers -n to it.
  long flush_interval() const { return interval_; }

private:
  int xres_;
  long interval_;
  long next_flush_;
  unsigned long remaining_;
  bool pending_ = false;
};

} // namespace radcl::options
