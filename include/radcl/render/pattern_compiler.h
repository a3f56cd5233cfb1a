// Patterns and textures for the kernels (scene-format.md §4, calc-language.md §5): each
// brightfunc, colorfunc or texfunc becomes an rc_pattern record whose expressions are compiled
// to OpenCL C by the calc module, reached through one generated dispatcher, rc_pattern_call().
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "radcl/device_types.h"
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

  bool empty() const { return names_.empty(); }
  // The generated functions and their dispatcher (nothing when no pattern was compiled).
  std::string source();

  // Whether the scene compiler can handle this modifier type as a pattern yet.
  static bool supported(rc_object_type t);

private:
  std::uint32_t request(const std::string& expr, const std::string& context,
                        const std::string& where);
  std::string load(const std::string& file, const std::string& where);

  std::array<double, 3> centre_;
  std::unique_ptr<calc::Program> program_;
  std::unique_ptr<calc::CodeGenerator> gen_;
  std::map<std::string, std::string> contexts_;                      // function file -> its context
  std::map<std::pair<std::string, std::string>, std::uint32_t> ids_; // (expr, context) -> number
  std::vector<std::string> names_; // dispatcher number -> function
};

} // namespace radcl::render
