#include "radcl/render/pattern_compiler.h"

#include <cmath>

#include "radcl/calc/codegen.h"
#include "radcl/calc/program.h"
#include "radcl/scene/object_type.h"
#include "radcl/scene/raypath.h"
#include "radcl/scene/transform.h"
#include "radcl/util/error.h"

namespace radcl::render {

namespace {

using Mat4 = std::array<std::array<double, 4>, 4>;

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        r[i][j] += a[i][k] * b[k][j];
  return r;
}

} // namespace

PatternCompiler::PatternCompiler(const std::array<double, 3>& centre)
    : centre_(centre), program_(std::make_unique<calc::Program>()) {}
PatternCompiler::~PatternCompiler() = default;

bool PatternCompiler::supported(rc_object_type t) {
  return t == RC_OBJ_BRIGHTFUNC || t == RC_OBJ_COLORFUNC || t == RC_OBJ_TEXFUNC;
}

std::string PatternCompiler::load(const std::string& file, const std::string& where) {
  if (file == ".") return "";
  auto it = contexts_.find(file);
  if (it != contexts_.end()) return it->second;
  if (contexts_.empty()) program_->load_rayinit();
  std::string path = scene::find_on_raypath(file);
  if (path.empty()) throw FatalError(where + ": cannot find function file \"" + file + "\"");
  std::string ctx = calc::Program::context_for_file(file);
  program_->load_file(path, ctx);
  contexts_[file] = ctx;
  return ctx;
}

std::uint32_t PatternCompiler::request(const std::string& expr, const std::string& context,
                                       const std::string& where) {
  auto key = std::make_pair(expr, context);
  if (auto it = ids_.find(key); it != ids_.end()) return it->second;
  if (contexts_.empty()) {
    program_->load_rayinit();
    contexts_["."] = "";
  }
  if (!gen_) gen_ = std::make_unique<calc::CodeGenerator>(*program_);
  std::string name;
  try {
    name = gen_->request_expression(program_->parse_expression(expr, context, where));
  } catch (const FatalError& e) {
    throw FatalError(where + ": " + e.what());
  }
  auto id = static_cast<std::uint32_t>(names_.size());
  names_.push_back(name);
  ids_[key] = id;
  return id;
}

rc_pattern PatternCompiler::compile(const scene::SceneDescription& sd, std::int32_t obj,
                                    const Mat4& to_world, double scale, std::vector<float>& args) {
  const scene::Object& o = sd.objects[obj];
  const auto type = static_cast<rc_object_type>(o.type);
  const std::string where = std::string(scene::type_name(o.type)) + " \"" + o.name + "\"";
  // mixfunc: foreground and background come before its coefficient.
  const std::size_t first = type == RC_OBJ_MIXFUNC ? 2 : 0;
  const std::size_t nexpr = type == RC_OBJ_BRIGHTFUNC || type == RC_OBJ_MIXFUNC ? 1 : 3;
  if (o.sargs.size() < first + nexpr + 1) throw FatalError("bad # arguments for " + where);
  std::string ctx = load(o.sargs[first + nexpr], where);
  scene::Transform xf;
  try {
    xf = scene::parse_transform(o.sargs, first + nexpr + 1);
  } catch (const FatalError&) {
    throw FatalError("bad transform for " + where);
  }
  rc_pattern p{};
  p.type = type;
  p.object = static_cast<std::uint32_t>(obj);
  for (std::size_t i = 0; i < 3; ++i)
    p.func[i] = i < nexpr ? request(o.sargs[first + i], ctx, where) : RC_NONE;
  p.args = static_cast<std::uint32_t>(args.size());
  p.nargs = static_cast<std::uint32_t>(o.fargs.size());
  args.insert(args.end(), o.fargs.begin(), o.fargs.end());

  // Function space -> world is the pattern's own transform, then the placement's. Device
  // coordinates are world minus the centre, so the device -> function map is the inverse of
  // (function -> world, then minus centre).
  Mat4 fwd = multiply(xf.m, to_world);
  for (int j = 0; j < 3; ++j)
    fwd[3][j] -= centre_[j];
  scene::Transform f;
  f.m = fwd;
  f.scale = xf.scale * scale;
  scene::Transform inv = f.inverse();
  const double s = 1.0 / f.scale; // distances in function space per world unit
  p.xform = static_cast<std::uint32_t>(args.size());
  for (int i = 0; i < 4; ++i) // rows of the affine inverse: p_f = p_d * inv
    for (int j = 0; j < 3; ++j)
      args.push_back(static_cast<float>(inv.m[i][j]));
  args.push_back(static_cast<float>(s));
  for (int i = 0; i < 3; ++i) // the rotation part of the forward map, for texture vectors
    for (int j = 0; j < 3; ++j)
      args.push_back(static_cast<float>(fwd[i][j] / f.scale));
  // Tx Ty Tz: the world origin (device point -centre) in function coordinates.
  std::array<double, 3> origin = inv.point({-centre_[0], -centre_[1], -centre_[2]});
  for (double v : origin)
    args.push_back(static_cast<float>(v));
  return p;
}

std::string PatternCompiler::source() {
  if (names_.empty()) return "";
  std::string out = gen_->source();
  out += "\nrc_calc_real rc_pattern_call(uint id, rc_calc_env* e) {\n  switch (id) {\n";
  for (std::size_t i = 0; i < names_.size(); ++i)
    out += "  case " + std::to_string(i) + "u:\n    return " + names_[i] + "(e);\n";
  out += "  }\n  return (rc_calc_real)0;\n}\n";
  return out;
}

} // namespace radcl::render
