// The materials with function files: the BRDF materials plasfunc, metfunc, transfunc,
// plasdata, metdata, transdata and BRTDfunc (../shared/docs/radiance/scene-format.md §3.11, §3.12),
// and the anisotropic plastic2, metal2, trans2 and ashik2 (§3.3, §3.4), whose orientation vector is
// three expressions, and prism1 and prism2 (§3.10), whose redirections are four expressions each.
// Each compiled material carries a function record in the pattern buffer (rc_material::func): its
// real arguments, its function-space transform and a descriptor of its functions, written by
// PatternCompiler (src/render/compile/func_materials.cpp) and read by
// kernels/materials/brdf_func.cl and kernels/materials/aniso.cl.
#pragma once

#include "radcl/device_types.h"

namespace radcl::render {

// Whether materials of type t are BRDF materials (they need a function record).
bool is_func_material(rc_object_type t);
// Whether t is plastic2, metal2, trans2 or ashik2 (a record of their orientation vector).
bool is_aniso_material(rc_object_type t);
// Whether t is prism1 or prism2 (a record of their redirections' expressions).
inline bool is_prism_material(rc_object_type t) {
  return t == RC_OBJ_PRISM1 || t == RC_OBJ_PRISM2;
}
// Whether t is BSDF or aBSDF (a record of their thickness, up vector and XML file's tables).
inline bool is_bsdf_material(rc_object_type t) {
  return t == RC_OBJ_BSDF || t == RC_OBJ_ABSDF;
}
// Whether materials of type t carry a function record.
inline bool has_func_record(rc_object_type t) {
  return is_func_material(t) || is_aniso_material(t) || is_prism_material(t) || is_bsdf_material(t);
}

} // namespace radcl::render
