// Argument counts per primitive type. Radiance checks these only when a primitive is used
// (oconv for surfaces, rtrace/rpict when a modifier is first evaluated); radcl checks every
// primitive once, when it is read, against the same limits (../shared/docs/radiance/scene-format.md
// §2-§4; the string minimums are those of each type's reader, including getfunc()'s "file name must
// exist"). Geometry checks that need values (radius 0, negative radii becoming bubbles/cups/tubes,
// zero-area or non-planar polygons) are not made here: Radiance makes them at oconv/render
// time, and so does radcl's geometry module.
#include "radcl/scene/rad_reader.h"

#include <climits>

#include "radcl/scene/transform.h"

namespace radcl::scene {
namespace {

constexpr int kAny = INT_MAX;
constexpr int kNoXf = -1;   // no transform arguments
constexpr int kDataXf = -2; // transform after data coordinates whose count the data file gives

struct Rule {
  int min_s = 0, max_s = kAny;
  int min_r = 0, max_r = kAny;
  int r_multiple = 1;  // reals must be a multiple of this
  int xf_from = kNoXf; // first string that may start the transform (first '-' word from here)
};

Rule exact_reals(int n, int max_s = kAny) {
  return {0, max_s, n, n, 1, kNoXf};
}
Rule func(int min_s, int xf_from, int min_r = 0, int max_r = kAny) {
  return {min_s, kAny, min_r, max_r, 1, xf_from};
}

Rule rule_for(ObjectType t) {
  switch (t) {
  // Surfaces: only the reals are checked (oconv ignores strings on them).
  case RC_OBJ_POLYGON:
    return {0, kAny, 9, kAny, 3, kNoXf};
  case RC_OBJ_CONE:
  case RC_OBJ_CUP:
  case RC_OBJ_RING:
    return exact_reals(8);
  case RC_OBJ_CYLINDER:
  case RC_OBJ_TUBE:
    return exact_reals(7);
  case RC_OBJ_SPHERE:
  case RC_OBJ_BUBBLE:
  case RC_OBJ_SOURCE:
    return exact_reals(4);
  case RC_OBJ_INSTANCE:
  case RC_OBJ_MESH:
    return {1, kAny, 0, kAny, 1, 1};
  // Materials with fixed arguments (../shared/docs/radiance/scene-format.md §3: no strings unless
  // an alternate).
  case RC_OBJ_PLASTIC:
  case RC_OBJ_METAL:
    return exact_reals(5, 0);
  case RC_OBJ_TRANS:
    return exact_reals(7, 0);
  case RC_OBJ_GLASS:
    return {0, 0, 3, 4, 1, kNoXf};
  case RC_OBJ_DIELECTRIC:
    return exact_reals(5, 0);
  case RC_OBJ_INTERFACE:
    return exact_reals(8, 0);
  case RC_OBJ_LIGHT:
    return exact_reals(3, 0);
  case RC_OBJ_GLOW:
    return exact_reals(4, 0);
  case RC_OBJ_SPOTLIGHT:
    return exact_reals(7, 0);
  case RC_OBJ_ILLUM:
  case RC_OBJ_MIRROR:
    return exact_reals(3, 1);
  case RC_OBJ_MIST:
    return {0, kAny, 0, 7, 1, kNoXf};
  case RC_OBJ_ANTIMATTER:
    return {1, 511, 0, kAny, 1, kNoXf};
  // Function-file materials: strings up to the file name, then optional transform.
  case RC_OBJ_PLASTIC2:
  case RC_OBJ_METAL2:
    return func(4, 4, 6, 6);
  case RC_OBJ_TRANS2:
  case RC_OBJ_ASHIK2:
    return func(4, 4, 8, 8);
  case RC_OBJ_PLASFUNC:
  case RC_OBJ_METFUNC:
    return func(2, 2, 4);
  case RC_OBJ_TRANSFUNC:
    return func(2, 2, 6);
  case RC_OBJ_PLASDATA:
  case RC_OBJ_METDATA:
    return func(4, kDataXf, 4);
  case RC_OBJ_TRANSDATA:
    return func(4, kDataXf, 6);
  case RC_OBJ_BRTDFUNC:
    return func(10, 10, 9);
  case RC_OBJ_BSDF:
    return {6, kAny, 0, 9, 3, 6};
  case RC_OBJ_ABSDF:
    return {5, kAny, 0, 9, 3, 5};
  case RC_OBJ_PRISM1:
    return func(5, 5);
  case RC_OBJ_PRISM2:
    return func(9, 9);
  // Patterns, textures, mixtures.
  case RC_OBJ_BRIGHTFUNC:
    return func(2, 2);
  case RC_OBJ_COLORFUNC:
    return func(4, 4);
  case RC_OBJ_BRIGHTDATA:
    return func(4, kDataXf);
  case RC_OBJ_COLORDATA:
    return func(8, kDataXf);
  case RC_OBJ_COLORPICT:
    return func(7, 7); // u v expressions precede the transform
  case RC_OBJ_BRIGHTTEXT:
    return {2, kAny, 11, kAny, 1, kNoXf};
  case RC_OBJ_COLORTEXT:
    return {2, kAny, 15, kAny, 1, kNoXf};
  case RC_OBJ_TEXFUNC:
    return func(4, 4);
  case RC_OBJ_TEXDATA:
    return func(8, kDataXf);
  case RC_OBJ_MIXFUNC:
    return func(4, 4);
  case RC_OBJ_MIXDATA:
    return func(6, kDataXf);
  case RC_OBJ_MIXPICT:
    return func(7, 7);
  case RC_OBJ_MIXTEXT:
    return {4, kAny, 9, kAny, 1, kNoXf};
  case RC_OBJ_ALIAS:
    return {0, 1, 0, 0, 1, kNoXf}; // written by the reader itself
  default:
    return {};
  }
}

} // namespace

std::string check_arguments(const Object& obj) {
  const Rule r = rule_for(obj.type);
  const long ns = static_cast<long>(obj.sargs.size());
  const long nr = static_cast<long>(obj.fargs.size());
  if (ns < r.min_s || ns > r.max_s || nr < r.min_r || nr > r.max_r || nr % r.r_multiple)
    return "bad # arguments";
  if (r.xf_from >= 0) {
    // As getfunc(): the transform starts at the first word beginning with '-'.
    // An instance or mesh has nothing but the transform after its file name.
    bool whole = obj.type == RC_OBJ_INSTANCE || obj.type == RC_OBJ_MESH;
    std::size_t i = static_cast<std::size_t>(r.xf_from);
    while (!whole && i < obj.sargs.size() && obj.sargs[i][0] != '-')
      ++i;
    Transform t;
    if (i < obj.sargs.size() && transform_prefix(obj.sargs, i, t) != obj.sargs.size())
      return "bad transform";
  }
  return "";
}

} // namespace radcl::scene
