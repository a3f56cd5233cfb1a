// Render tests that write their own small scenes: a fixture that moves the current directory
// into a fresh temporary folder for each test (Radiance finds files through RAYPATH's "."),
// and renders of primary rays through a scene file there (the load, renderer and render that
// every such test would otherwise repeat).
#pragma once

#include <array>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>
#include <vector>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/irradiance_meter.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/loader.h"
#include "temp_dir.h"

namespace radcl::test {

// Deterministic direct light only (-ab 0 -dj 0 -ds 0 -dt 0), with -I meters if `meters`.
inline render::RenderSettings direct_light_settings(bool meters) {
  render::RenderSettings st;
  st.ab = 0;
  st.dj = 0;
  st.ds = 0;
  st.dt = 0;
  st.irradiance_I = meters;
  return st;
}

// A TempDir that is also the current directory while the test runs.
class SceneDir : public TempDir {
protected:
  void SetUp() override {
    TempDir::SetUp();
    ASSERT_NE(getcwd(cwd_, sizeof cwd_), nullptr);
    ASSERT_EQ(chdir(dir.c_str()), 0);
  }
  void TearDown() override {
    EXPECT_EQ(chdir(cwd_), 0);
    TempDir::TearDown();
  }

  // The results of `rays` through scene file `file` (in the folder) with settings `st`.
  static std::vector<render::PrimaryResult> render_rays(const std::string& file,
                                                        const std::vector<render::PrimaryRay>& rays,
                                                        const render::RenderSettings& st) {
    scene::LoadedScene ls = scene::load_scene({file});
    render::Renderer r(ls, st, device::default_context());
    std::vector<render::PrimaryResult> res(rays.size());
    r.render(rays, res);
    return res;
  }

  // The value (radiance, or irradiance with -i/-I) of each of `rays`, as render_rays.
  static std::vector<render::Vec3d> render_values(const std::string& file,
                                                  const std::vector<render::PrimaryRay>& rays,
                                                  const render::RenderSettings& st) {
    std::vector<render::Vec3d> v;
    for (const render::PrimaryResult& r : render_rays(file, rays, st))
      v.push_back(r.value);
    return v;
  }

  // Rays straight down (-z) from height `z` over each (x, y) of `at`.
  static std::vector<render::PrimaryRay> rays_down(const std::vector<std::array<double, 2>>& at,
                                                   double z) {
    std::vector<render::PrimaryRay> rays;
    for (const auto& p : at)
      rays.push_back({{p[0], p[1], z}, {0, 0, -1}, 0});
    return rays;
  }

  // Where -I meters along `rays` measure in scene file `file` (render/pipeline/irradiance_meter.h).
  static std::vector<render::Vec3d> meter_points(const std::string& file,
                                                 const std::vector<render::PrimaryRay>& rays) {
    scene::LoadedScene ls = scene::load_scene({file});
    geometry::SceneGeometry g(ls);
    std::vector<render::Vec3d> p;
    for (const render::PrimaryRay& r : rays) {
      const double n = std::sqrt(r.dir[0] * r.dir[0] + r.dir[1] * r.dir[1] + r.dir[2] * r.dir[2]);
      p.push_back(render::meter_point(g, r.org, {r.dir[0] / n, r.dir[1] / n, r.dir[2] / n}));
    }
    return p;
  }

private:
  char cwd_[4096];
};

} // namespace radcl::test
