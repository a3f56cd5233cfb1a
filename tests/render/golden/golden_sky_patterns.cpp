// Skies through the kernels: gensky/gendaylit output (Radiance's own, tests/data/skies) shaded
// by radcl's skybright.cal/perezlum.cal as compiled brightfunc patterns, against the sky
// formulas in C++ (radcl/sky) along 200 directions: within 1e-4.
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "files.h"
#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/sky/cie_sky.h"
#include "radcl/sky/perez.h"
#include "temp_dir.h"
#include "test_env.h"

using namespace radcl;

namespace {

// The sky file plus a white glow dome above and below, so a ray's value is the pattern's.
scene::LoadedScene sky_scene(const std::string& sky, std::vector<double>* a) {
  std::string text = test::read_file(test::data("skies/" + sky + ".rad"));
  std::size_t at = text.find("brightfunc skyfunc");
  std::istringstream rest(text.substr(at));
  std::string w;
  int n = 0;
  rest >> w >> w >> n;
  for (int i = 0; i < n; ++i)
    rest >> w;
  rest >> n >> n;
  a->resize(n);
  for (double& v : *a)
    rest >> v;
  // compare() reads up to a[9]: an overcast sky's 3 arguments have no f2 and no sun (zeros).
  if (a->size() < 10) a->resize(10, 0.0);
  text += "\nskyfunc glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n"
          "sky_glow source ground 0 0 4 0 0 -1 180\n";
  const test::TempFolder dir("sky");
  const std::string file = (dir / (sky + ".rad")).string();
  std::ofstream(file) << text;
  return scene::load_scene({file});
}

// 200 directions spread over the sphere (a Fibonacci lattice).
std::vector<std::array<double, 3>> directions() {
  std::vector<std::array<double, 3>> d;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < 200; ++i) {
    double z = 1 - (i + 0.5) / 100.0, r = std::sqrt(1 - z * z), phi = golden * i;
    d.push_back({r * std::cos(phi), r * std::sin(phi), z});
  }
  return d;
}

void compare(const std::string& sky, bool perez) {
  std::vector<double> a;
  scene::LoadedScene ls = sky_scene(sky, &a);
  render::RenderSettings st;
  st.ab = 0;
  render::Renderer r(ls, st, device::default_context());
  std::vector<render::PrimaryRay> rays;
  auto dirs = directions();
  for (const auto& d : dirs)
    rays.push_back({{0, 0, 0}, d, 0});
  std::vector<render::PrimaryResult> res(rays.size());
  r.render(rays, res);
  std::array<double, 3> sun =
      perez ? std::array<double, 3>{a[7], a[8], a[9]} : std::array<double, 3>{a[4], a[5], a[6]};
  int compared = 0;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const auto& d = dirs[i];
    // Directions inside the sun's disc see the sun.
    if (d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2] > std::cos(2 * M_PI / 180)) continue;
    double want;
    if (perez) {
      sky::PerezSkyParams p;
      p.diffnorm = a[0];
      p.ground = a[1];
      p.k = {a[2], a[3], a[4], a[5], a[6]};
      p.sun = sun;
      want = sky::perez_skybright(p, d);
    } else {
      sky::CieSkyParams p;
      p.type = static_cast<sky::CieSky>(static_cast<int>(a[0]));
      p.zenith = a[1];
      p.ground = a[2];
      p.f2 = a[3];
      p.sun = sun;
      want = sky::cie_skybright(p, d);
    }
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(res[i].value[c], want, 1e-4 * std::abs(want))
          << sky << " direction " << i << " (" << d[0] << " " << d[1] << " " << d[2] << ")";
    ++compared;
  }
  EXPECT_GT(compared, 190);
}

} // namespace

TEST(GoldenSkyPatterns, CieClear) {
  compare("sky00", false);
}
TEST(GoldenSkyPatterns, CieOvercast) {
  compare("sky02", false);
}
TEST(GoldenSkyPatterns, CieIntermediate) {
  compare("sky03", false);
}
TEST(GoldenSkyPatterns, PerezAllWeather) {
  compare("sky27", true);
}
