#include "radcl/render/compile/pattern_compiler.h"

#include <bit>
#include <cmath>

#include "radcl/calc/codegen.h"
#include "radcl/calc/library.h"
#include "radcl/calc/program.h"
#include "radcl/render/compile/func_materials.h"
#include "radcl/render/compile/pattern_data.h"
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

bool is_data(rc_object_type t) {
  return t == RC_OBJ_BRIGHTDATA || t == RC_OBJ_COLORDATA || t == RC_OBJ_TEXDATA ||
         t == RC_OBJ_COLORPICT || t == RC_OBJ_MIXDATA || t == RC_OBJ_MIXPICT;
}

bool is_picture(rc_object_type t) {
  return t == RC_OBJ_COLORPICT || t == RC_OBJ_MIXPICT;
}

float bits(std::uint32_t u) {
  return std::bit_cast<float>(u);
}

} // namespace

PatternCompiler::PatternCompiler(const std::array<double, 3>& centre)
    : centre_(centre), program_(std::make_unique<calc::Program>()) {}
PatternCompiler::~PatternCompiler() = default;

bool PatternCompiler::supported(rc_object_type t) {
  return t == RC_OBJ_BRIGHTFUNC || t == RC_OBJ_COLORFUNC || t == RC_OBJ_TEXFUNC || is_data(t) ||
         t == RC_OBJ_BRIGHTTEXT || t == RC_OBJ_COLORTEXT || t == RC_OBJ_MIXFUNC ||
         t == RC_OBJ_MIXTEXT;
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

void PatternCompiler::load_into(const std::string& context, bool is_file, const std::string& text,
                                const std::string& where) {
  if (contexts_.empty()) {
    program_->load_rayinit();
    contexts_["."] = "";
  }
  if (!is_file) {
    program_->load_string(text, where, context);
    return;
  }
  std::string path = scene::find_on_raypath(text);
  if (path.empty()) throw FatalError(where + ": cannot find function file \"" + text + "\"");
  program_->load_file(path, context);
}

void PatternCompiler::set_parameter(const std::string& context, const std::string& name,
                                    double value) {
  program_->set_parameter(name, context, value);
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

std::uint32_t PatternCompiler::request_function(const std::string& name, int nargs,
                                                const std::string& context,
                                                const std::string& where) {
  auto key = std::make_tuple(name, nargs, context);
  if (auto it = fids_.find(key); it != fids_.end()) return it->second;
  if (!gen_) gen_ = std::make_unique<calc::CodeGenerator>(*program_);
  std::string fn;
  try {
    fn = gen_->request_function(name, nargs, context);
  } catch (const FatalError& e) {
    throw FatalError(where + ": " + e.what());
  }
  auto id = static_cast<std::uint32_t>(fnames_.size());
  fnames_.emplace_back(fn, nargs);
  fids_[key] = id;
  return id;
}

std::uint32_t PatternCompiler::data_file(const std::string& file, const std::string& where,
                                         std::vector<float>& args, std::size_t& dims) {
  if (auto it = data_.find(file); it != data_.end()) {
    dims = it->second.second;
    return it->second.first;
  }
  std::string path = scene::find_on_raypath(file);
  if (path.empty()) throw FatalError(where + ": cannot find data file \"" + file + "\"");
  DataSet d = read_data_file(path, file);
  dims = d.axes.size();
  std::uint32_t off = pack_data(d, args);
  data_[file] = {off, dims};
  return off;
}

std::array<std::uint32_t, 3> PatternCompiler::picture(const std::string& file,
                                                      const std::string& where,
                                                      std::vector<float>& args) {
  if (auto it = pictures_.find(file); it != pictures_.end()) return it->second;
  std::string path = scene::find_on_raypath(file);
  if (path.empty()) throw FatalError(where + ": cannot find picture file \"" + file + "\"");
  std::array<DataSet, 3> d = read_picture_data(path, file);
  std::array<std::uint32_t, 3> off{};
  for (int c = 0; c < 3; ++c)
    off[c] = pack_data(d[c], args);
  pictures_[file] = off;
  return off;
}

std::vector<std::uint32_t> PatternCompiler::compile_data(const scene::Object& o,
                                                         const std::string& where, rc_pattern& p,
                                                         std::vector<float>& args,
                                                         std::size_t& transform) {
  const auto type = static_cast<rc_object_type>(o.type);
  // String arguments (../shared/docs/radiance/calc-language.md §5.4): a mixture's two sides,
  // functions, data files, function file, coordinates.
  const bool mix = type == RC_OBJ_MIXDATA || type == RC_OBJ_MIXPICT;
  const std::size_t first = mix ? 2 : 0;
  const std::size_t nfunc = type == RC_OBJ_BRIGHTDATA || mix ? 1 : 3;
  const std::size_t ndata = is_picture(type) ? 1 : nfunc;
  const std::size_t file = first + nfunc + ndata;
  if (o.sargs.size() < file + (type == RC_OBJ_MIXPICT ? 3 : 2))
    throw FatalError("bad # arguments for " + where);
  std::array<std::uint32_t, 3> data{};
  std::size_t dims = 2;
  if (is_picture(type)) {
    data = picture(o.sargs[first + nfunc], where, args);
  } else {
    for (std::size_t i = 0; i < ndata; ++i) {
      std::size_t n = 0;
      data[i] = data_file(o.sargs[first + nfunc + i], where, args, n);
      if (i == 0)
        dims = n;
      else if (n != dims)
        throw FatalError(where + ": dimension error");
    }
    for (std::size_t i = ndata; i < 3; ++i)
      data[i] = data[0];
  }
  std::string ctx = load(o.sargs[file], where);
  if (o.sargs.size() < file + 1 + dims)
    throw FatalError(where + ": too few string arguments (" + std::to_string(dims) +
                     " coordinates needed)");
  std::vector<std::uint32_t> desc{static_cast<std::uint32_t>(dims)};
  std::vector<std::size_t> coord(dims);
  for (std::size_t i = 0; i < dims; ++i)
    coord[i] = file + 1 + i;
  if (is_picture(type)) std::swap(coord[0], coord[1]); // v (vertical) is the first axis
  for (std::size_t c : coord)
    desc.push_back(request(o.sargs[c], ctx, where));
  desc.insert(desc.end(), data.begin(), data.end());
  // Functions of the interpolated values: 1 value (own channel; mixpict's red) or, for texdata
  // and functions of pictures or colour data taking 3 parameters, all three.
  for (std::size_t i = 0; i < 3; ++i) {
    if (i >= nfunc) {
      p.func[i] = RC_NONE;
      continue;
    }
    const std::string& fn = o.sargs[first + i];
    int nargs = type == RC_OBJ_TEXDATA ? 3 : 1;
    if (type == RC_OBJ_COLORDATA || is_picture(type)) {
      int params = 0;
      if (const calc::Definition* d = program_->lookup(fn, ctx); d && d->function)
        params = static_cast<int>(d->params.size());
      else if (const calc::LibraryFunction* lf = calc::find_library(fn))
        params = lf->args;
      nargs = params < 3 ? 1 : 3;
    }
    p.func[i] = request_function(fn, nargs, ctx, where);
  }
  // Arguments past the coordinates up to the first starting with '-' are ignored, as Radiance does.
  transform = file + 1 + dims;
  while (transform < o.sargs.size() && o.sargs[transform].rfind('-', 0) != 0)
    ++transform;
  return desc;
}

rc_pattern PatternCompiler::compile(const scene::SceneDescription& sd, std::int32_t obj,
                                    const Mat4& to_world, double scale, std::vector<float>& args) {
  const scene::Object& o = sd.objects[obj];
  const auto type = static_cast<rc_object_type>(o.type);
  const std::string where = std::string(scene::type_name(o.type)) + " \"" + o.name + "\"";
  rc_pattern p{};
  p.type = type;
  p.object = static_cast<std::uint32_t>(obj);
  std::size_t first_xf = 0;
  std::vector<std::uint32_t> desc;
  std::vector<float> text; // text patterns: their descriptor; they take no transform arguments
  if (TextPatterns::is_text(type)) {
    text = text_.compile(o, where, args);
    first_xf = o.sargs.size();
  } else if (is_data(type)) {
    desc = compile_data(o, where, p, args, first_xf);
  } else if (is_func_material(type)) {
    desc = compile_brdf(o, where, args, first_xf);
  } else if (is_aniso_material(type)) {
    desc = compile_orientation(o, where, first_xf);
  } else if (is_prism_material(type)) {
    desc = compile_redirect(o, where, first_xf);
  } else if (is_bsdf_material(type)) {
    desc = compile_bsdf(o, where, args, first_xf);
  } else {
    // mixfunc: foreground and background come before its coefficient.
    const std::size_t first = type == RC_OBJ_MIXFUNC ? 2 : 0;
    const std::size_t nexpr = type == RC_OBJ_BRIGHTFUNC || type == RC_OBJ_MIXFUNC ? 1 : 3;
    if (o.sargs.size() < first + nexpr + 1) throw FatalError("bad # arguments for " + where);
    std::string ctx = load(o.sargs[first + nexpr], where);
    for (std::size_t i = 0; i < 3; ++i)
      p.func[i] = i < nexpr ? request(o.sargs[first + i], ctx, where) : RC_NONE;
    first_xf = first + nexpr + 1;
  }
  scene::Transform xf;
  try {
    xf = scene::parse_transform(o.sargs, first_xf);
  } catch (const FatalError&) {
    throw FatalError("bad transform for " + where);
  }
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
  for (std::uint32_t u : desc) // data patterns: their descriptor follows
    args.push_back(bits(u));
  args.insert(args.end(), text.begin(), text.end());
  return p;
}

std::string PatternCompiler::source() {
  if (empty()) return "";
  if (!gen_) gen_ = std::make_unique<calc::CodeGenerator>(*program_); // text patterns alone
  std::string out = gen_->source() + brdf_source();
  out += "\nrc_calc_real rc_pattern_call(uint id, rc_calc_env* e) {\n  switch (id) {\n";
  for (std::size_t i = 0; i < names_.size(); ++i)
    out += "  case " + std::to_string(i) + "u:\n    return " + names_[i] + "(e);\n";
  out += "  }\n  return (rc_calc_real)0;\n}\n";
  if (!has_data()) return out;
  // Functions of interpolated data: own channel value v, or all three (a, b, c).
  out += "\nrc_calc_real rc_pattern_fcall(uint id, rc_calc_env* e, rc_calc_real v, rc_calc_real "
         "a,\n                              rc_calc_real b, rc_calc_real c) {\n  switch (id) {\n";
  for (std::size_t i = 0; i < fnames_.size(); ++i)
    out += "  case " + std::to_string(i) + "u:\n    return " + fnames_[i].first +
           (fnames_[i].second == 1 ? "(e, v);\n" : "(e, a, b, c);\n");
  out += "  }\n  return (rc_calc_real)0;\n}\n";
  return out;
}

} // namespace radcl::render
