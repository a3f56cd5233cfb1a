#include "render_settings.h"

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <unistd.h>

#include "pipeline_tuning.h"
#include "radcl/ambient/ambient_file.h"
#include "radcl/ambient/cache.h"
#include "radcl/ambient/format.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/util/error.h"

namespace radcl::cli {

render::RenderSettings render_settings(const options::RenderOptions& r) {
  render::RenderSettings s;
  // The global medium: its albedo, eccentricity and sampling distance do nothing without an
  // extinction, as in Radiance.
  for (int c = 0; c < 3; ++c) {
    s.me[c] = r.mist_extinction[c];
    s.ma[c] = r.mist_albedo[c];
  }
  s.mg = r.mist_eccentricity;
  s.ms = r.mist_sampling;
  s.ds = r.direct_sampling;
  s.dj = r.direct_jitter;
  s.dt = r.direct_threshold;
  s.dc = r.direct_certainty;
  s.dv = r.direct_visible;
  s.bv = r.back_visible;
  s.dr = r.direct_relays;
  s.dp = r.direct_pretest;
  s.ss = r.specular_sampling;
  s.st = r.specular_threshold;
  s.av = r.ambient_value;
  s.aw = r.ambient_value_weight;
  s.ab = r.ambient_bounces;
  s.ad = r.ambient_divisions;
  s.as = r.ambient_supersamples;
  s.aa = r.ambient_accuracy;
  if (r.ambient_list.kind != options::ModifierList::Kind::None) {
    s.ambient_list = r.ambient_list.kind == options::ModifierList::Kind::Include
                         ? render::RenderSettings::AmbientList::Include
                         : render::RenderSettings::AmbientList::Exclude;
    s.ambient_names = r.ambient_list.names;
  }
  s.lr = r.max_depth;
  s.lw = r.min_weight;
  // Radiance's rayorigin() stops at the first child ray with this; nearly every render makes
  // one, so the settings are refused before any output.
  if (s.lr <= 0 && s.lw <= 0) throw FatalError("zero ray weight in Russian roulette");
  s.irradiance_i = r.irradiance;
  s.tuning = tuning_from_environment();
  s.seed =
      r.uncorrelated ? static_cast<std::uint32_t>(std::time(nullptr) ^ (::getpid() << 16)) : 0u;
  // RADCL_SEED fixes -u+'s seed, so independent renders can be repeated (tests, averaging).
  if (const char* seed = std::getenv("RADCL_SEED"); seed && r.uncorrelated)
    s.seed = static_cast<std::uint32_t>(std::strtoul(seed, nullptr, 10));
  return s;
}

std::unique_ptr<ambient::AmbientFile> setup_ambient(render::RenderSettings& s,
                                                    const options::RenderOptions& r,
                                                    const scene::LoadedScene& ls,
                                                    const std::string& progname,
                                                    const std::string& octree) {
  if (r.ambient_accuracy <= 0 || r.ambient_bounces <= 0) return nullptr;
  // Radiance's cube is the octree's; scenes given as files get their bounding box's
  // largest side, as oconv starts from.
  double cube = ls.main.cube_size;
  if (!(cube > 0)) {
    geometry::SceneGeometry g(ls);
    auto b = g.bounds();
    cube = std::max({b[1][0] - b[0][0], b[1][1] - b[0][1], b[1][2] - b[0][2]});
  }
  s.cube_size = cube;
  s.ambient_min_radius = ambient::ambient_min_radius(cube, r.ambient_resolution);
  s.ambient_max_radius = ambient::ambient_max_radius(cube, r.ambient_resolution);
  s.make_records = true;
  if (r.ambient_file.empty()) return nullptr;
  ambient::AmbientSettings as;
  as.progname = progname;
  as.av = r.ambient_value;
  as.aw = r.ambient_value_weight;
  as.ab = r.ambient_bounces;
  as.aa = r.ambient_accuracy;
  as.ad = r.ambient_divisions;
  as.as = r.ambient_supersamples;
  as.ar = r.ambient_resolution;
  if (!octree.empty()) as.octree = octree;
  as.software = std::string("radcl ") + RADCL_VERSION;
  as.time = std::time(nullptr);
  auto file = std::make_unique<ambient::AmbientFile>();
  s.ambient_records = file->open(r.ambient_file, ambient::new_file_header(as));
  return file;
}

void sync_ambient(ambient::AmbientFile* file, render::Renderer& renderer) {
  std::vector<ambient::AmbientRecord> made = renderer.take_new_records();
  if (!file || !file->is_open()) return;
  renderer.add_records(file->append(made));
}

} // namespace radcl::cli
