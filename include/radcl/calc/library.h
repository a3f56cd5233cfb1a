// The names the .cal language knows without definitions: library functions
// (../shared/docs/radiance/calc-language.md §4, §4.1) and the renderer's ray variables (§5.1,
// §5.2).
#pragma once

#include <string_view>

namespace radcl::calc {

enum class Lib {
  If,
  Select,
  Min,
  Max,
  Rand,
  Floor,
  Ceil,
  Sqrt,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Atan2,
  Exp,
  Log,
  Log10,
  Erf,
  Erfc,
  Noise3,
  Noise3x,
  Noise3y,
  Noise3z,
  Fnoise3,
  Arg
};

struct LibraryFunction {
  const char* name;
  Lib id;
  int args;      // parameters it reads (min/max/select: at least this many)
  bool variadic; // min, max, select
  bool constant; // foldable when its arguments are constant (all but arg)
};

// The library function of that name, or nullptr.
const LibraryFunction* find_library(std::string_view name);

// Slot (rc_calc_slot) of a ray variable name such as "Dx" or "RdotP", or -1.
int ray_slot(std::string_view name);
// Name of a slot ("Dx"), for messages and generated code comments.
const char* ray_slot_name(int slot);

// Rounds a selector or argument index the way Radiance does ((int)(x + .5)), saturating so
// huge values stay defined.
inline long round_index(double x) {
  double r = x + 0.5;
  if (r >= 1e9) return 1000000000L;
  if (r <= -1e9) return -1000000000L;
  return static_cast<long>(r);
}

} // namespace radcl::calc
