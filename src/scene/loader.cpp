#include "radcl/scene/loader.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "radcl/scene/octree_reader.h"
#include "radcl/scene/portable_io.h"
#include "radcl/scene/rad_reader.h"
#include "radcl/scene/raypath.h"
#include "radcl/scene/transform.h"
#include "radcl/util/error.h"

namespace radcl::scene {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A .rad file can also begin with '#', so only a header that names the octree format (or
// the ".oct" suffix) makes an input an octree.
bool is_octree(const std::string& input) {
  if (input.empty() || input[0] == '!') return ends_with(input, ".oct");
  if (ends_with(input, ".oct")) return true;
  std::error_code ec;
  if (std::filesystem::is_directory(input, ec)) return false; // the scene reader says so
  std::ifstream f(input, std::ios::binary);
  if (!f) return false;
  std::string head(4096, '\0');
  f.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(f.gcount()));
  if (head.rfind("#?RADIANCE", 0) != 0) return false;
  const auto end = head.find("\n\n");
  return head.substr(0, end).find("\nFORMAT=Radiance_octree") != std::string::npos;
}

// Identity of a file for cycle detection: the same octree reached by different spellings
// of its path is still the same octree.
std::string file_key(const std::string& path) {
  std::error_code ec;
  auto p = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : p.string();
}

std::string describe(const Object& o) {
  return std::string(type_name(o.type)) + " \"" + o.name + "\"";
}

class Loader {
public:
  explicit Loader(LoadedScene& out) : out_(out) {}

  // Loads everything that the instances and meshes of `scene` reference.
  void resolve(const SceneDescription& scene) {
    for (const Object& o : scene.objects) {
      if (o.type != RC_OBJ_INSTANCE && o.type != RC_OBJ_MESH) continue;
      const bool inst = o.type == RC_OBJ_INSTANCE;
      if (o.sargs.empty()) throw FatalError("bad # of arguments for " + describe(o));
      try {
        parse_transform(o.sargs, 1);
      } catch (const FatalError&) {
        throw FatalError("bad transform for " + describe(o));
      }
      const std::string path = find_on_raypath(o.sargs[0]);
      if (path.empty())
        throw FatalError(std::string("cannot find ") + (inst ? "octree" : "mesh") + " file \"" +
                         o.sargs[0] + "\"");
      if (inst)
        load_instance_octree(path, o);
      else if (!out_.meshes.count(path))
        out_.meshes.emplace(path, std::make_shared<const TriangleMesh>(read_mesh(path)));
    }
  }

  void enter(const std::string& path) { active_.insert(file_key(path)); }

private:
  void load_instance_octree(const std::string& path, const Object& o) {
    const std::string key = file_key(path);
    if (active_.count(key))
      throw FatalError("recursive instance of octree \"" + o.sargs[0] + "\" in " + describe(o));
    if (out_.octrees.count(path)) return;
    active_.insert(key);
    auto scene = std::make_shared<SceneDescription>(read_octree(path));
    resolve(*scene);
    active_.erase(key);
    out_.octrees.emplace(path, std::move(scene));
  }

  LoadedScene& out_;
  std::set<std::string> active_; // octrees being loaded, outermost first
};

} // namespace

LoadedScene load_scene(const std::vector<std::string>& inputs) {
  if (inputs.empty()) throw FatalError("no scene input");
  LoadedScene result;
  Loader loader(result);

  // One "!command" whose output is an octree: rfluxmtx gives rcontrib
  // '!oconv -f -i system.oct receiver.rad', as Radiance's readoct() reads commands.
  if (inputs.size() == 1 && inputs[0].size() > 1 && inputs[0][0] == '!' &&
      !ends_with(inputs[0], ".oct")) {
    std::string bytes = read_input_bytes(inputs[0], "scene command");
    const auto end = bytes.find("\n\n");
    if (bytes.rfind("#?RADIANCE", 0) == 0 &&
        bytes.substr(0, end).find("\nFORMAT=Radiance_octree") != std::string::npos)
      return load_octree_data(std::move(bytes), inputs[0]);
    std::istringstream text(bytes);
    read_rad_stream(result.main, text, inputs[0]);
    loader.resolve(result.main);
    return result;
  }
  std::size_t octrees = 0;
  for (const auto& in : inputs)
    octrees += is_octree(in);
  if (octrees > 0) {
    if (inputs.size() != 1) throw FatalError("an octree must be the only scene input");
    loader.enter(inputs[0]);
    result.main = read_octree(inputs[0]);
  } else {
    for (const auto& in : inputs)
      read_rad_file(result.main, in);
  }
  loader.resolve(result.main);
  return result;
}

LoadedScene load_octree_data(std::string bytes, const std::string& name) {
  LoadedScene result;
  Loader loader(result);
  result.main = read_octree_data(std::move(bytes), name);
  loader.resolve(result.main);
  return result;
}

} // namespace radcl::scene
