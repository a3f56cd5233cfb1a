// The BRDF materials' string arguments (../shared/docs/radiance/scene-format.md §3.11, §3.12;
// ../shared/docs/radiance/calc-language.md §5.4): plasfunc, metfunc, transfunc (a reflection
// function of (dx, dy, dz, omega)), plasdata, metdata, transdata (a data file whose coordinates are
// such functions, and a function of (value, dx, dy, dz, omega)) and BRTDfunc (six coefficient
// expressions and three functions). The functions are reached on the device through the dispatcher
// rc_brdf_call() generated here; kernels/materials/brdf_func.cl reads the descriptor this returns.
#include "radcl/render/compile/func_materials.h"
#include "radcl/calc/codegen.h"
#include "radcl/calc/program.h"
#include "radcl/render/compile/pattern_compiler.h"
#include "radcl/scene/object_type.h"
#include "radcl/util/error.h"

namespace radcl::render {

namespace {

bool is_data_material(rc_object_type t) {
  return t == RC_OBJ_PLASDATA || t == RC_OBJ_METDATA || t == RC_OBJ_TRANSDATA;
}

bool is_trans_material(rc_object_type t) {
  return t == RC_OBJ_TRANSFUNC || t == RC_OBJ_TRANSDATA;
}

} // namespace

bool is_func_material(rc_object_type t) {
  return t == RC_OBJ_PLASFUNC || t == RC_OBJ_METFUNC || t == RC_OBJ_TRANSFUNC ||
         is_data_material(t) || t == RC_OBJ_BRTDFUNC;
}

bool is_aniso_material(rc_object_type t) {
  return t == RC_OBJ_PLASTIC2 || t == RC_OBJ_METAL2 || t == RC_OBJ_TRANS2 || t == RC_OBJ_ASHIK2;
}

// Descriptor of plastic2 .. ashik2 (after the 25 transform floats): flags (0), then the
// orientation vector's three expressions (rc_pattern_call), evaluated in function space.
std::vector<std::uint32_t> PatternCompiler::compile_orientation(const scene::Object& o,
                                                                const std::string& where,
                                                                std::size_t& transform) {
  if (o.sargs.size() < 4) throw FatalError("bad # arguments for " + where);
  const std::string ctx = load(o.sargs[3], where);
  std::vector<std::uint32_t> desc{0u};
  for (std::size_t i = 0; i < 3; ++i)
    desc.push_back(request(o.sargs[i], ctx, where));
  transform = 4;
  return desc;
}

// Descriptor of prism1 and prism2: flags (0), then each redirection's coefficient and
// direction (four expressions; prism2 has two redirections).
std::vector<std::uint32_t> PatternCompiler::compile_redirect(const scene::Object& o,
                                                             const std::string& where,
                                                             std::size_t& transform) {
  const std::size_t nexpr = o.type == RC_OBJ_PRISM2 ? 8 : 4;
  if (o.sargs.size() < nexpr + 1) throw FatalError("bad # arguments for " + where);
  const std::string ctx = load(o.sargs[nexpr], where);
  std::vector<std::uint32_t> desc{0u};
  for (std::size_t i = 0; i < nexpr; ++i)
    desc.push_back(request(o.sargs[i], ctx, where));
  transform = nexpr + 1;
  return desc;
}

std::uint32_t PatternCompiler::request_brdf(const std::string& name, int nargs,
                                            const std::string& context, const std::string& where) {
  auto key = std::make_tuple(name, nargs, context);
  if (auto it = bids_.find(key); it != bids_.end()) return it->second;
  std::string fn;
  try {
    fn = gen_->request_function(name, nargs, context);
  } catch (const FatalError& e) {
    throw FatalError(where + ": " + e.what());
  }
  auto id = static_cast<std::uint32_t>(bnames_.size());
  bnames_.emplace_back(fn, nargs);
  bids_[key] = id;
  return id;
}

// Descriptor (after the record's 25 transform floats), integers as float bit patterns:
//   func and data materials: flags, function, data offset (RC_NONE: none), n, n coordinates;
//   BRTDfunc: flags, 6 expressions (rc_pattern_call), 3 functions (RC_NONE for a literal 0).
// flags bit 0 (BRTDfunc): the direct part is computed even without diffuse components, as
// Radiance does when the red function is not the literal 0.
std::vector<std::uint32_t> PatternCompiler::compile_brdf(const scene::Object& o,
                                                         const std::string& where,
                                                         std::vector<float>& args,
                                                         std::size_t& transform) {
  const auto type = static_cast<rc_object_type>(o.type);
  brdf_used_ = true;
  if (contexts_.empty()) { // rayinit.cal first, as for patterns
    program_->load_rayinit();
    contexts_["."] = "";
  }
  if (!gen_) gen_ = std::make_unique<calc::CodeGenerator>(*program_);
  std::vector<std::uint32_t> desc;
  if (type == RC_OBJ_BRTDFUNC) {
    if (o.sargs.size() < 10 || o.fargs.size() < 9) throw FatalError("bad # arguments for " + where);
    std::string ctx = load(o.sargs[9], where);
    desc.push_back(o.sargs[6][0] != '0' ? 1u : 0u);
    for (std::size_t i = 0; i < 6; ++i)
      desc.push_back(request(o.sargs[i], ctx, where));
    for (std::size_t i = 6; i < 9; ++i)
      desc.push_back(o.sargs[i] == "0" ? RC_NONE : request_brdf(o.sargs[i], 4, ctx, where));
    transform = 10;
  } else {
    const bool data = is_data_material(type);
    if (o.sargs.size() < (data ? 4u : 2u) || o.fargs.size() < (is_trans_material(type) ? 6u : 4u))
      throw FatalError("bad # arguments for " + where);
    desc.push_back(0u);
    if (data) {
      std::size_t dims = 0;
      std::uint32_t off = data_file(o.sargs[1], where, args, dims);
      std::string ctx = load(o.sargs[2], where);
      if (o.sargs.size() < 3 + dims)
        throw FatalError(where + ": too few string arguments (" + std::to_string(dims) +
                         " coordinates needed)");
      desc.push_back(request_brdf(o.sargs[0], 5, ctx, where));
      desc.push_back(off);
      desc.push_back(static_cast<std::uint32_t>(dims));
      for (std::size_t i = 0; i < dims; ++i)
        desc.push_back(request_brdf(o.sargs[3 + i], 4, ctx, where));
      transform = 3 + dims;
    } else {
      std::string ctx = load(o.sargs[1], where);
      desc.push_back(request_brdf(o.sargs[0], 4, ctx, where));
      desc.push_back(RC_NONE);
      desc.push_back(0u);
      transform = 2;
    }
  }
  // As Radiance's getfunc: the transform starts at the first argument beginning with '-'.
  while (transform < o.sargs.size() && o.sargs[transform].rfind('-', 0) != 0)
    ++transform;
  return desc;
}

// rc_brdf_call(id, e, x): x = {value, dx, dy, dz, omega}; functions of 4 arguments get x[1..4].
std::string PatternCompiler::brdf_source() const {
  if (!brdf_used_) return "";
  std::string out = "\nrc_calc_real rc_brdf_call(uint id, rc_calc_env* e, const rc_calc_real* x) "
                    "{\n  switch (id) {\n";
  for (std::size_t i = 0; i < bnames_.size(); ++i)
    out += "  case " + std::to_string(i) + "u:\n    return " + bnames_[i].first +
           (bnames_[i].second == 5 ? "(e, x[0], x[1], x[2], x[3], x[4]);\n"
                                   : "(e, x[1], x[2], x[3], x[4]);\n");
  out += "  }\n  return (rc_calc_real)0;\n}\n";
  return out;
}

} // namespace radcl::render
