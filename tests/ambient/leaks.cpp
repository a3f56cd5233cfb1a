// The irradiance cache's light-leak test on the host (ambient/leaks.h, Radiance's
// plugaleak): which records are tested, in which corral sector a lookup point lies, and where
// the test ray goes (20 degrees above the lookup's tangent plane, towards the point on the
// record's normal above its position).
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

#include "radcl/ambient/dircode.h"
#include "radcl/ambient/leaks.h"

using namespace radcl;
using radcl::ambient::LeakLookup;

namespace {

// One record at the origin facing +z, u along +x, radii 0.5 and 1, with corral bits `corral`.
ambient::AmbientRecord record(std::uint32_t corral, int level = 0) {
  ambient::AmbientRecord a;
  a.pos = {0, 0, 0};
  a.ndir = ambient::encode_dir({0, 0, 1});
  a.udir = ambient::encode_dir({1, 0, 0});
  a.rad = {0.5f, 1.0f};
  a.weight = level == 0 ? 1.0f : 0.5f;
  a.lvl = static_cast<std::int16_t>(level);
  a.val = {1, 1, 1};
  a.corral = corral;
  return a;
}

LeakLookup at(float x, float y, float z = 0) {
  LeakLookup q;
  q.point = {x, y, z};
  q.normal = {0, 0, 1};
  return q;
}

struct Segments {
  int calls = 0;
  bool answer = true;
  std::array<double, 3> org{}, dir{};
  double tmax = 0;
  ambient::SegmentBlocked fn() {
    return [this](const std::array<double, 3>& o, const std::array<double, 3>& d, double t,
                  const std::array<double, 3>&) {
      ++calls;
      org = o;
      dir = d;
      tmax = t;
      return answer;
    };
  }
};

constexpr float kAa = 0.2f, kMinarad = 0.01f;

} // namespace

TEST(AmbientLeaks, AtanMatchesTheSectorsOfAFullTurn) {
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < 64; ++k) {
    const double a = (k + 0.5) * pi / 32;
    double v =
        ambient::corral_atan2a(static_cast<float>(std::sin(a)), static_cast<float>(std::cos(a)));
    if (v < 0) v += 2 * pi;
    EXPECT_NEAR(v, a, 0.01) << k;
  }
}

TEST(AmbientLeaks, BlockedTestRayRulesTheRecordOut) {
  std::vector<ambient::AmbientRecord> recs = {record(1u)}; // sector 0: along +u
  ambient::AmbientCacheBuffers cache = ambient::build_ambient_cache(recs, {0, 0, 0}, kAa);
  ambient::LeakTester t(&cache, kAa, kMinarad);
  ASSERT_TRUE(t.active());
  Segments s;
  std::vector<std::uint32_t> out;
  EXPECT_EQ(t.find(at(0.05f, 0.001f), s.fn(), out), 1u);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0], 0u);
  // The ray leaves the point 20 degrees above its tangent plane and ends on the record's
  // normal line.
  EXPECT_NEAR(s.org[0], 0.05, 1e-7);
  EXPECT_NEAR(s.dir[2], std::cos(70 * 3.14159265358979323846 / 180), 1e-6);
  const double ex = s.org[0] + s.tmax * s.dir[0], ey = s.org[1] + s.tmax * s.dir[1];
  EXPECT_NEAR(ex, 0, 1e-6);
  EXPECT_NEAR(ey, 0, 1e-6);
  EXPECT_NEAR(s.org[2] + s.tmax * s.dir[2], 0.05 * std::tan(20 * 3.14159265358979323846 / 180),
              1e-4);
  // A clear test ray keeps it.
  s.answer = false;
  out.clear();
  EXPECT_EQ(t.find(at(0.05f, 0.001f), s.fn(), out), 1u);
  EXPECT_TRUE(out.empty());
}

TEST(AmbientLeaks, OnlyMarkedSectorsAreTested) {
  // Bit 8: angles pi/2 .. 9pi/16 (towards +v, slightly past it).
  std::vector<ambient::AmbientRecord> recs = {record(1u << 8)};
  ambient::AmbientCacheBuffers cache = ambient::build_ambient_cache(recs, {0, 0, 0}, kAa);
  ambient::LeakTester t(&cache, kAa, kMinarad);
  Segments s;
  std::vector<std::uint32_t> out;
  t.find(at(0.05f, 0.0f), s.fn(), out);   // sector 0
  t.find(at(-0.05f, 0.0f), s.fn(), out);  // sector 16
  t.find(at(0.001f, -0.1f), s.fn(), out); // sector 23 or 24
  EXPECT_EQ(s.calls, 0);
  t.find(at(-0.01f, 0.1f), s.fn(), out); // just past pi/2
  EXPECT_EQ(s.calls, 1);
  EXPECT_EQ(out.size(), 1u);
}

TEST(AmbientLeaks, RecordsTheKernelRejectsAreNotTested) {
  std::vector<ambient::AmbientRecord> recs = {record(~0u), record(~0u, 1)};
  ambient::AmbientCacheBuffers cache = ambient::build_ambient_cache(recs, {0, 0, 0}, kAa);
  ambient::LeakTester t(&cache, kAa, kMinarad);
  Segments s;
  std::vector<std::uint32_t> out;
  t.find(at(0.2f, 0.0f), s.fn(), out);        // outside the ellipse (aa x rad[0] = 0.1 along u)
  t.find(at(0.0f, 0.0f, -0.5f), s.fn(), out); // behind
  LeakLookup side = at(0.05f, 0);
  side.normal = {1, 0, 0}; // facing 90 degrees away
  t.find(side, s.fn(), out);
  EXPECT_EQ(s.calls, 0);
  // Level 0 meets only the level-0 record; level 1 both.
  LeakLookup q = at(0.05f, 0.05f);
  t.find(q, s.fn(), out);
  EXPECT_EQ(s.calls, 1);
  q.level = 1;
  q.weight = 0.5f;
  t.find(q, s.fn(), out);
  EXPECT_EQ(s.calls, 3);
}

// Without a texture the tester knows the kernel's normal: it tests every record the kernel's
// direction test accepts (a chord 2 - 2 cos(angle) below maxangle^2, so angles a little past
// maxangle) and skips the orientation trees of surfaces facing elsewhere.
TEST(AmbientLeaks, ExactNormalsTestEveryRecordTheKernelAccepts) {
  std::vector<ambient::AmbientRecord> recs = {record(~0u)};
  ambient::AmbientCacheBuffers cache = ambient::build_ambient_cache(recs, {0, 0, 0}, kAa);
  ambient::LeakTester t(&cache, kAa, kMinarad);
  const double maxangle = 10 * 3.14159265358979323846 / 180 + kAa;
  const double reach = 2 * std::asin(maxangle / 2); // the kernel's widest accepted angle
  auto tilted = [&](double ang) {
    LeakLookup q = at(0.05f, 0.05f);
    q.normal = {std::sin(ang), 0, std::cos(ang)};
    q.exact_normal = true;
    Segments s;
    std::vector<std::uint32_t> out;
    t.find(q, s.fn(), out);
    return s.calls;
  };
  EXPECT_EQ(tilted(maxangle + 0.5 * (reach - maxangle)), 1);
  EXPECT_EQ(tilted(reach + 0.01), 0);
  EXPECT_EQ(tilted(1.2), 0);
}

TEST(AmbientLeaks, UnmarkedCacheIsInactive) {
  std::vector<ambient::AmbientRecord> recs = {record(0)};
  ambient::AmbientCacheBuffers cache = ambient::build_ambient_cache(recs, {0, 0, 0}, kAa);
  ambient::LeakTester t(&cache, kAa, kMinarad);
  EXPECT_FALSE(t.active());
  Segments s;
  std::vector<std::uint32_t> out;
  EXPECT_EQ(t.find(at(0.05f, 0.0f), s.fn(), out), 0u);
  EXPECT_EQ(s.calls, 0);
}

// A record at the lookup point itself (a ray shaded again where its record was just made) is
// never a leak: Radiance's test would meet a double root there and plug it.
TEST(AmbientLeaks, RecordAtThePointIsNoLeak) {
  std::vector<ambient::AmbientRecord> recs = {record(~0u)};
  ambient::AmbientCacheBuffers cache = ambient::build_ambient_cache(recs, {0, 0, 0}, kAa);
  ambient::LeakTester t(&cache, kAa, kMinarad);
  Segments s;
  std::vector<std::uint32_t> out;
  t.find(at(0.0f, 0.0f), s.fn(), out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(s.calls, 0);
}
