// choose_spread picks exactly what the plain sequential rule picks (each miss against every
// miss chosen before it), across levels, facings, dense clusters, cell borders and negative
// coordinates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "radcl/ambient/spread_choice.h"

using radcl::ambient::choose_spread;

namespace {

std::vector<std::uint32_t> plain_rule(const std::vector<rc_ray>& miss, double sep) {
  std::vector<std::uint32_t> chosen;
  for (std::size_t i = 0; i < miss.size(); ++i) {
    const rc_ray& m = miss[i];
    bool near = false;
    for (std::uint32_t j : chosen) {
      const rc_ray& o = miss[j];
      const double ex = m.org.x - o.org.x, ey = m.org.y - o.org.y, ez = m.org.z - o.org.z;
      const double facing = m.dir.x * o.dir.x + m.dir.y * o.dir.y + m.dir.z * o.dir.z;
      if (o.ambient_depth == m.ambient_depth && facing > 0.5 &&
          ex * ex + ey * ey + ez * ez < sep * sep)
        near = true;
    }
    if (!near) chosen.push_back(static_cast<std::uint32_t>(i));
  }
  return chosen;
}

rc_ray miss_at(float x, float y, float z, float nx, float ny, float nz, std::uint32_t level) {
  rc_ray r{};
  const float l = std::sqrt(nx * nx + ny * ny + nz * nz);
  r.org.x = x;
  r.org.y = y;
  r.org.z = z;
  r.dir.x = nx / l;
  r.dir.y = ny / l;
  r.dir.z = nz / l;
  r.ambient_depth = level;
  return r;
}

} // namespace

TEST(SpreadChoice, MatchesThePlainSequentialRule) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  for (double sep : {0.05, 0.3, 2.0}) {
    std::vector<rc_ray> miss;
    for (int k = 0; k < 3000; ++k) {
      // A third in a dense cluster, the rest spread over [-5, 5]^3; three levels, normals
      // mostly up with some sideways and down.
      const float s = k % 3 == 0 ? 0.2f : 5.0f;
      const float nz = k % 7 == 0 ? -1.0f : k % 5 == 0 ? 0.2f : 1.0f;
      miss.push_back(miss_at(s * u(rng), s * u(rng), s * u(rng), u(rng) * 0.5f, u(rng) * 0.5f, nz,
                             static_cast<std::uint32_t>(k % 3)));
    }
    const std::vector<std::uint32_t> want = plain_rule(miss, sep);
    EXPECT_EQ(choose_spread(miss, sep), want) << "sep " << sep;
    EXPECT_GT(want.size(), 10u);
    EXPECT_LT(want.size(), miss.size());
  }
}

TEST(SpreadChoice, NeighboursAcrossCellBordersCount) {
  // With sep 1 the cells are unit cubes; each rejection below comes from a neighbouring cell.
  std::vector<rc_ray> miss = {miss_at(-0.01f, 0, 0, 0, 0, 1, 0), // cell -1: chosen
                              miss_at(0.01f, 0, 0, 0, 0, 1, 0),  // cell 0, 0.02 from the first
                              miss_at(1.5f, 0, 0, 0, 0, 1, 0),   // cell 1, 1.51 from it: chosen
                              miss_at(0.9f, 0, 0, 0, 0, 1, 0),   // cell 0, 0.91 from the first
                              miss_at(2.2f, 0, 0, 0, 0, 1, 0),   // cell 2, 0.7 from the third
                              miss_at(0.5f, 0, 0, 0, 0, -1, 0),  // facing away: chosen
                              miss_at(0.5f, 0, 0, 0, 0, 1, 1)};  // another level: chosen
  EXPECT_EQ(choose_spread(miss, 1.0), (std::vector<std::uint32_t>{0, 2, 5, 6}));
  EXPECT_TRUE(choose_spread({}, 1.0).empty());
}
