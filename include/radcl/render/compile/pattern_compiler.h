// Patterns and textures for the kernels (../shared/docs/radiance/scene-format.md §4,
// ../shared/docs/radiance/calc-language.md §5): each brightfunc, colorfunc or texfunc becomes an
// rc_pattern record whose expressions are compiled to OpenCL C by the calc module, reached through
// one generated dispatcher, rc_pattern_call(). brightdata, colordata, texdata and colorpict also
// pack their data (render/compile/pattern_data.h) into the argument buffer and call their functions
// of the interpolated values through a second dispatcher, rc_pattern_fcall(). brighttext, colortext
// and mixtext pack their text and font instead (render/compile/text_pattern.h).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "radcl/device_types.h"
#include "radcl/render/compile/text_pattern.h"
#include "radcl/scene/scene.h"

namespace radcl::calc {
class Program;
class CodeGenerator;
} // namespace radcl::calc

namespace radcl::render {

class PatternCompiler {
public:
  // `centre`: the scene's re-centring origin (device coordinates are world minus centre).
  explicit PatternCompiler(const std::array<double, 3>& centre);
  ~PatternCompiler();

  // The pattern record of object `obj` of `sd` placed by `to_world` (an instance's transform,
  // row-vector convention, with its scale); appends its arguments and transform to `args`.
  rc_pattern compile(const scene::SceneDescription& sd, std::int32_t obj,
                     const std::array<std::array<double, 4>, 4>& to_world, double scale,
                     std::vector<float>& args);

  // Whether nothing was compiled (no generated code, no dispatchers, no text).
  bool empty() const { return !gen_ && text_.empty(); }
  // Whether data were loaded (the kernels then need render/pattern_data.cl).
  bool has_data() const { return !fnames_.empty() || !data_.empty(); }
  // Whether a text pattern was compiled (render/text.cl).
  bool has_text() const { return !text_.empty(); }
  // Whether a BRDF material's record was compiled (render/func_materials.cpp).
  bool has_brdf() const { return brdf_used_; }
  // The generated functions and their dispatcher (nothing when no pattern was compiled).
  std::string source();

  // Whether the scene compiler can handle this modifier type as a pattern yet.
  static bool supported(rc_object_type t);

  // rcontrib's bin expressions, each in a context of its own parameter set: a function file
  // (found on RAYPATH) or statements loaded into `context`, a parameter set there (Radiance's
  // set_eparams: no redefinition warning), an expression evaluated there (its dispatcher
  // number).
  void load_into(const std::string& context, bool is_file, const std::string& text,
                 const std::string& where);
  void set_parameter(const std::string& context, const std::string& name, double value);
  std::uint32_t request_expression(const std::string& expr, const std::string& context,
                                   const std::string& where) {
    return request(expr, context, where);
  }

private:
  std::uint32_t request(const std::string& expr, const std::string& context,
                        const std::string& where);
  // Dispatcher number of function `name` called with `nargs` (1 or 3) values.
  std::uint32_t request_function(const std::string& name, int nargs, const std::string& context,
                                 const std::string& where);
  std::string load(const std::string& file, const std::string& where);
  // A data pattern: loads its data sets (appended to `args` once per file), sets p.func to its
  // functions and `transform` to the index of its first transform argument; returns the
  // descriptor that follows its 25 transform floats: coordinate count, their dispatcher
  // numbers, 3 data offsets.
  std::vector<std::uint32_t> compile_data(const scene::Object& o, const std::string& where,
                                          rc_pattern& p, std::vector<float>& args,
                                          std::size_t& transform);
  std::uint32_t data_file(const std::string& file, const std::string& where,
                          std::vector<float>& args, std::size_t& dims);
  std::array<std::uint32_t, 3> picture(const std::string& file, const std::string& where,
                                       std::vector<float>& args);
  // The BRDF materials (plasfunc .. transdata, BRTDfunc), in render/func_materials.cpp: their
  // string arguments, as compile_data, and their dispatcher rc_brdf_call().
  std::vector<std::uint32_t> compile_brdf(const scene::Object& o, const std::string& where,
                                          std::vector<float>& args, std::size_t& transform);
  // plastic2, metal2, trans2, ashik2 (render/func_materials.cpp): their orientation vector.
  std::vector<std::uint32_t> compile_orientation(const scene::Object& o, const std::string& where,
                                                 std::size_t& transform);
  // prism1, prism2 (same file): their redirections' coefficients and directions.
  std::vector<std::uint32_t> compile_redirect(const scene::Object& o, const std::string& where,
                                              std::size_t& transform);
  std::uint32_t request_brdf(const std::string& name, int nargs, const std::string& context,
                             const std::string& where);
  std::string brdf_source() const;
  // BSDF and aBSDF (src/render/compile/bsdf_materials.cpp): their thickness and up-vector
  // expressions, and their XML file's device tables (packed into `args` once per file).
  std::vector<std::uint32_t> compile_bsdf(const scene::Object& o, const std::string& where,
                                          std::vector<float>& args, std::size_t& transform);
  std::array<std::uint32_t, 4> bsdf_file(const std::string& file, const std::string& where,
                                         std::vector<float>& args);

  std::array<double, 3> centre_;
  std::unique_ptr<calc::Program> program_;
  std::unique_ptr<calc::CodeGenerator> gen_;
  std::map<std::string, std::string> contexts_;                      // function file -> its context
  std::map<std::pair<std::string, std::string>, std::uint32_t> ids_; // (expr, context) -> number
  std::vector<std::string> names_; // dispatcher number -> function
  std::map<std::tuple<std::string, int, std::string>, std::uint32_t> fids_; // (name, n, ctx)
  std::vector<std::pair<std::string, int>> fnames_; // rc_pattern_fcall number -> (function, n)
  std::map<std::string, std::pair<std::uint32_t, std::size_t>> data_; // file -> (offset, dims)
  std::map<std::string, std::array<std::uint32_t, 3>> pictures_;      // file -> channel offsets
  std::map<std::string, std::array<std::uint32_t, 4>> bsdf_files_;    // file -> table offsets
  TextPatterns text_;
  bool brdf_used_ = false;
  std::map<std::tuple<std::string, int, std::string>, std::uint32_t> bids_; // (name, n, ctx)
  std::vector<std::pair<std::string, int>> bnames_; // rc_brdf_call number -> (function, n)
};

} // namespace radcl::render
