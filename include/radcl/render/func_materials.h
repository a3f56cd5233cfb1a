// The BRDF materials plasfunc, metfunc, transfunc, plasdata, metdata, transdata and BRTDfunc
// (scene-format.md §3.11, §3.12). Each compiled material carries a function record in the
// pattern buffer (rc_material::func): its real arguments, its function-space transform and a
// descriptor of its functions, written by PatternCompiler (src/render/func_materials.cpp) and
// read by kernels/materials/brdf_func.cl.
#pragma once

#include "radcl/device_types.h"

namespace radcl::render {

// Whether materials of type t are BRDF materials (they need a function record).
bool is_func_material(rc_object_type t);

} // namespace radcl::render
