// The -o letters: which values, in which order, and what they imply (trace mode, cast-only).
#include "radcl/options/ray_io.h"

#include "radcl/util/error.h"

#include <cstring>

namespace radcl::options {

const char* format_name(char format) {
  switch (format) {
  case 'a':
    return "ascii";
  case 'f':
    return "float";
  case 'd':
    return "double";
  case 'c':
    return "32-bit_rle_rgbe";
  }
  return "unknown";
}

OutputSpec parse_output_spec(std::string_view spec) {
  if (spec.empty()) throw FatalError("empty output specification");
  OutputSpec os;
  std::string* table = &os.per_ray;
  for (std::size_t k = 0; k < spec.size(); ++k) {
    const char c = spec[k];
    switch (c) {
    case 'T':
      os.trace_sources = true;
      [[fallthrough]];
    case 't':
      if (k + 1 == spec.size()) break; // a final t/T asks for nothing
      // A second t restarts the traced list, as Radiance's table pointer does.
      table = &os.per_traced;
      table->clear();
      os.cast_only = false;
      break;
    case 'o':
    case 'd':
    case 'p':
    case 'N':
      *table += c;
      os.ncomp += 3;
      break;
    case 'c':
      *table += c;
      os.ncomp += 2;
      break;
    case 'L':
    case 's':
    case 'w':
    case 'm':
    case 'M':
      *table += c;
      os.ncomp += 1;
      break;
    case 'r':
    case 'x':
    case 'v':
    case 'V':
    case 'n':
    case 'W':
      *table += c;
      os.ncomp += 3;
      os.cast_only = false;
      break;
    case 'R':
    case 'X':
    case 'l':
      *table += c;
      os.ncomp += 1;
      os.cast_only = false;
      break;
    case 'e': // radcl's own: the value's standard error, once per input ray
      if (table != &os.per_ray) throw FatalError("-oe is not a traced ray's output");
      *table += c;
      os.ncomp += 3;
      os.cast_only = false;
      break;
    case '~':
      *table += c;
      break;
    default:
      throw FatalError(std::string("unrecognized output option '") + c + "'");
    }
  }
  if (os.trace_mode()) os.ncomp = 0;
  return os;
}

void check_output_spec(std::string_view spec, const OutputSpec& os, const RenderOptions& render,
                       bool immediate_irradiance) {
  // Radiance warns about V/W accuracy while scanning the letters, before its other checks.
  const bool inexact = render.ambient_bounces > 0 &&
                       (render.ambient_accuracy > 1e-6 || render.ambient_supersamples > 0);
  for (char c : spec)
    if (inexact && (c == 'V' || c == 'W'))
      warning(std::string("-ot") + c + " accuracy depends on -aa 0 -as 0");
  // The cache's error is a bias shared by neighbouring points, not a spread of samples.
  if (os.per_ray.find('e') != std::string::npos && render.ambient_bounces > 0 &&
      render.ambient_accuracy > 0)
    throw FatalError("-oe requires -aa 0 (no irradiance cache)");
  const bool irrad = render.irradiance || immediate_irradiance;
  if (irrad && os.cast_only) throw FatalError("-I+ and -i+ options require some value output");
  for (char c : os.per_ray) {
    if (c == 'V' || c == 'W') warning("-oVW options require trace mode");
    if (irrad && std::strchr("rRxX", c)) warning("-orRxX options incompatible with -I+ and -i+");
  }
}

void check_output_format(std::string_view spec, char out_format) {
  if (out_format == 'c' && (spec.size() != 1 || !std::strchr("vrx", spec[0])))
    throw FatalError("color format only with -ov, -or, -ox");
}

} // namespace radcl::options
