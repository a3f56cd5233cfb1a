#include "radcl/render/compile/material_traits.h"

#include <array>

#include "radcl/render/compile/compiled_scene.h"
#include "radcl/render/compile/func_materials.h"

namespace radcl::render {
namespace {

using Through = MaterialTraits::SeenThrough;

MaterialTraits traits_of(rc_object_type t) {
  MaterialTraits m;
  switch (t) {
  case RC_OBJ_PLASTIC:
  case RC_OBJ_METAL:
    m.blocks_shadows = true;
    [[fallthrough]];
  case RC_OBJ_LIGHT:
  case RC_OBJ_GLOW:
  case RC_OBJ_ILLUM:
  case RC_OBJ_SPOTLIGHT:
  case RC_OBJ_MIRROR:
  case RC_OBJ_ANTIMATTER:
  case RC_OBJ_MIST:
    m.shaded = true;
    break;
  case RC_OBJ_TRANS:
    m.shaded = true;
    m.min_reals = m.max_reals = 7;
    m.seen_through = Through::ByArguments;
    break;
  case RC_OBJ_GLASS:
    m.shaded = true;
    m.min_reals = 3;
    m.max_reals = 4;
    m.seen_through = Through::Always;
    break;
  case RC_OBJ_DIELECTRIC:
    m.shaded = true;
    m.min_reals = m.max_reals = 5;
    m.seen_through = Through::WhenFlat;
    break;
  case RC_OBJ_INTERFACE:
    m.shaded = true;
    m.min_reals = m.max_reals = 8;
    m.seen_through = Through::WhenFlat;
    break;
  case RC_OBJ_TRANS2:
    m.min_reals = m.max_reals = 8;
    break;
  case RC_OBJ_ASHIK2:
    m.min_reals = m.max_reals = 8;
    m.blocks_shadows = true;
    break;
  case RC_OBJ_PLASTIC2:
  case RC_OBJ_METAL2:
    m.min_reals = m.max_reals = 6;
    m.blocks_shadows = true;
    break;
  case RC_OBJ_PLASFUNC:
  case RC_OBJ_METFUNC:
  case RC_OBJ_PLASDATA:
  case RC_OBJ_METDATA:
    m.blocks_shadows = true;
    break;
  default:
    break;
  }
  // The materials with a function record (BRDF, anisotropic, prisms, BSDF) are all shaded.
  if (has_func_record(t)) m.shaded = true;
  return m;
}

const std::array<MaterialTraits, RC_OBJ_COUNT> kTable = [] {
  std::array<MaterialTraits, RC_OBJ_COUNT> a{};
  for (int t = 0; t < RC_OBJ_COUNT; ++t)
    a[t] = traits_of(static_cast<rc_object_type>(t));
  return a;
}();

} // namespace

const MaterialTraits& material_traits(rc_object_type t) {
  static const MaterialTraits none{};
  return t >= 0 && t < RC_OBJ_COUNT ? kTable[t] : none;
}

bool real_count_ok(rc_object_type t, std::size_t n) {
  const MaterialTraits& m = material_traits(t);
  return m.min_reals < 0 ||
         (n >= static_cast<std::size_t>(m.min_reals) && n <= static_cast<std::size_t>(m.max_reals));
}

bool seen_through(const CompiledScene& cs, std::uint32_t material, bool flat) {
  if (material >= cs.materials.size()) return false;
  const rc_material& mat = cs.materials[material];
  switch (material_traits(static_cast<rc_object_type>(mat.type)).seen_through) {
  case Through::Always:
    return true;
  case Through::WhenFlat:
    return flat;
  case Through::ByArguments: { // trans, as Radiance's m_normal
    if (mat.nargs < 7) return false;
    const float* a = cs.args.data() + mat.args;
    double rspec = a[3], trans = a[5] * (1.0 - rspec), tspec = trans * a[6];
    double tdiff = trans - tspec, rdiff = 1.0 - trans - rspec;
    return a[4] <= 1e-6 && tspec > tdiff + rdiff;
  }
  case Through::No:
    break;
  }
  return false;
}

} // namespace radcl::render
