#include "radcl/calc/library.h"

#include <array>

#include "radcl/calc/device_context.h"

namespace radcl::calc {
namespace {

constexpr LibraryFunction kLibrary[] = {
    {"if", Lib::If, 3, false, true},           {"select", Lib::Select, 1, true, true},
    {"min", Lib::Min, 1, true, true},          {"max", Lib::Max, 1, true, true},
    {"rand", Lib::Rand, 1, false, true},       {"floor", Lib::Floor, 1, false, true},
    {"ceil", Lib::Ceil, 1, false, true},       {"sqrt", Lib::Sqrt, 1, false, true},
    {"sin", Lib::Sin, 1, false, true},         {"cos", Lib::Cos, 1, false, true},
    {"tan", Lib::Tan, 1, false, true},         {"asin", Lib::Asin, 1, false, true},
    {"acos", Lib::Acos, 1, false, true},       {"atan", Lib::Atan, 1, false, true},
    {"atan2", Lib::Atan2, 2, false, true},     {"exp", Lib::Exp, 1, false, true},
    {"log", Lib::Log, 1, false, true},         {"log10", Lib::Log10, 1, false, true},
    {"erf", Lib::Erf, 1, false, true},         {"erfc", Lib::Erfc, 1, false, true},
    {"noise3", Lib::Noise3, 3, false, true},   {"noise3x", Lib::Noise3x, 3, false, true},
    {"noise3y", Lib::Noise3y, 3, false, true}, {"noise3z", Lib::Noise3z, 3, false, true},
    {"fnoise3", Lib::Fnoise3, 3, false, true}, {"arg", Lib::Arg, 1, false, false},
};

#define RC_CALC_SLOT_NAME(id, name) name,
constexpr const char* kSlotNames[] = {RC_CALC_RAY_VARS(RC_CALC_SLOT_NAME)};
#undef RC_CALC_SLOT_NAME

} // namespace

const LibraryFunction* find_library(std::string_view name) {
  for (const LibraryFunction& f : kLibrary)
    if (name == f.name) return &f;
  return nullptr;
}

int ray_slot(std::string_view name) {
  for (int i = 0; i < RC_CALC_NSLOTS; ++i)
    if (name == kSlotNames[i]) return i;
  return -1;
}

const char* ray_slot_name(int slot) {
  return slot >= 0 && slot < RC_CALC_NSLOTS ? kSlotNames[slot] : "?";
}

} // namespace radcl::calc
