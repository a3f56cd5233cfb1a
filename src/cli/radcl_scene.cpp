// radcl scene: what radcl makes of a scene (octree or .rad files): object counts by type, the
// surfaces placed for ray tracing, light sources and the bounding box; --list prints every
// object in Radiance's order; --time adds the wall-clock seconds of loading the scene and of
// building its ray-tracing geometry (for tests/bench/scene_load.sh).
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "radcl/geometry/scene_geometry.h"
#include "radcl/scene/loader.h"
#include "radcl/scene/material_chain.h"
#include "radcl/util/error.h"
#include "radcl_commands.h"

namespace radcl::cli {
namespace {

void print_counts(const char* title, const std::map<std::string, std::size_t>& counts) {
  std::printf("%-15s", title);
  if (counts.empty()) std::printf(" none");
  const char* sep = " ";
  for (const auto& [name, n] : counts) {
    std::printf("%s%s %zu", sep, name.c_str(), n);
    sep = ", ";
  }
  std::printf("\n");
}

void list_objects(const scene::SceneDescription& sd) {
  for (std::size_t i = 0; i < sd.objects.size(); ++i) {
    const scene::Object& o = sd.objects[i];
    std::string mod = o.modifier == scene::kVoid ? "void" : sd.objects[o.modifier].name;
    std::printf("%zu\t%s\t%s\t%s\n", i, std::string(scene::type_name(o.type)).c_str(),
                o.name.c_str(), mod.c_str());
  }
}

} // namespace

int cmd_scene(int argc, char** argv) {
  bool list = false, timed = false;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--list")
      list = true;
    else if (a == "--time")
      timed = true;
    else if (a.size() > 1 && a[0] == '-' && a[1] == '-')
      throw FatalError("scene: unknown option \"" + a + "\"");
    else
      inputs.push_back(a);
  }
  if (inputs.empty())
    throw FatalError("scene: usage: radcl scene [--list] [--time] octree|file.rad ...");

  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  scene::LoadedScene loaded = scene::load_scene(inputs);
  const auto t1 = Clock::now();
  const scene::SceneDescription& sd = loaded.main;
  if (list) {
    list_objects(sd);
    return 0;
  }

  std::map<std::string, std::size_t> surfaces, materials, patterns;
  std::size_t lights = 0, distant_lights = 0;
  for (std::size_t i = 0; i < sd.objects.size(); ++i) {
    const scene::Object& o = sd.objects[i];
    std::string name(scene::type_name(o.type));
    if (scene::is_surface(o.type)) {
      ++surfaces[name];
      if (scene::is_light_source(sd, static_cast<std::int32_t>(i)))
        ++(o.type == RC_OBJ_SOURCE ? distant_lights : lights);
    } else if (scene::is_material(o.type)) {
      ++materials[name];
    } else if (o.type != RC_OBJ_ALIAS) {
      ++patterns[name];
    }
  }
  const auto t2 = Clock::now();
  geometry::SceneGeometry geom(loaded);
  const auto t3 = Clock::now();
  const geometry::SurfaceCounts& c = geom.counts();

  std::printf("%-15s %zu\n", "objects", sd.objects.size());
  print_counts("surfaces", surfaces);
  print_counts("materials", materials);
  print_counts("patterns etc.", patterns);
  std::printf("%-15s %zu local, %zu distant\n", "light sources", lights, distant_lights);
  std::printf("%-15s %zu triangles from %zu polygons, %zu quadrics/rings, %zu instances, "
              "%zu meshes (%zu triangles); %zu without material, %zu degenerate\n",
              "ray tracing", c.triangles, c.polygons,
              c.spheres + c.bubbles + c.cones + c.cups + c.cylinders + c.tubes + c.rings,
              c.instances, c.meshes, c.mesh_triangles, c.skipped_void, c.skipped_degenerate);
  for (const auto& [path, oct] : loaded.octrees)
    std::printf("%-15s %s (%zu objects)\n", "instanced", path.c_str(), oct->objects.size());
  for (const auto& [path, mesh] : loaded.meshes)
    std::printf("%-15s %s (%zu triangles)\n", "mesh", path.c_str(), mesh->triangles.size());
  auto b = geom.bounds();
  std::printf("%-15s %.6g %.6g %.6g .. %.6g %.6g %.6g\n", "bounding box", b[0][0], b[0][1], b[0][2],
              b[1][0], b[1][1], b[1][2]);
  if (timed) {
    const std::chrono::duration<double> load = t1 - t0, build = t3 - t2;
    std::printf("%-15s%.3f s\n", "load time", load.count());
    std::printf("%-15s%.3f s\n", "build time", build.count());
  }
  return 0;
}

} // namespace radcl::cli
