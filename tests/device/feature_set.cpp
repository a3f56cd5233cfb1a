// Feature sets specialise programs: different sets give different programs, and a program
// built without a material has none of its code — while the code it has computes the right
// values.
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

#include "device_fixture.h"
#include "radcl/device/buffer.h"
#include "radcl/device/feature_set.h"
#include "radcl/device/program.h"

using namespace radcl::device;

namespace {

constexpr float kSentinel = -12345.0f;

std::vector<float> probe(const FeatureSet& fs, const std::vector<float>& in) {
  Context& ctx = test_context();
  Program prog(ctx, fs.program({"probe/features.cl"}));
  Kernel k = prog.kernel("rc_feature_probe");
  Buffer bin = Buffer::from(ctx, in);
  Buffer bout = Buffer::from(ctx, std::vector<float>(RC_OBJ_COUNT, kSentinel));
  k.arg(0, bin).arg(1, bout);
  ctx.run(k, 1);
  return bout.to_vector<float>(RC_OBJ_COUNT);
}

struct V {
  double x, y, z;
};
V norm(V a) {
  double l = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
  return {a.x / l, a.y / l, a.z / l};
}
double dot(V a, V b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// scene-format.md §3.1 evaluated in double for the probe's fixed geometry (red channel).
double expected_red(bool metal, double r, double spec, double rough) {
  V n{0, 0, 1}, d = norm({0.3, 0, -1}), l = norm({-0.2, 0.1, 1});
  double ls = 1000, omega = 1e-3, a2 = rough * rough, ldot = dot(n, l);
  double sp = metal ? r * spec : spec;
  double out = ls * r * (1 - spec) * ldot * omega / M_PI;
  V h{l.x - d.x, l.y - d.y, l.z - d.z};
  double hn = dot(h, n), hh = dot(h, h), ae = a2 + omega / (4 * M_PI);
  double tan2 = (hh - hn * hn) / (hn * hn);
  out += ls * sp * std::exp(-tan2 / ae) * hh / (M_PI * ae * std::pow(hn, 4)) * ldot * omega;
  return out;
}

} // namespace

TEST(FeatureSet, OptionsAndSourcesDifferBetweenSets) {
  FeatureSet a, b;
  a.add(RC_OBJ_PLASTIC);
  a.add(RC_OBJ_POLYGON);
  b.add(RC_OBJ_METAL);
  b.add(RC_OBJ_POLYGON);
  b.define("RADCL_AMBIENT_CACHE");
  EXPECT_NE(a.options(), b.options());
  EXPECT_NE(a.options().find("-DRADCL_HAS_PLASTIC=1"), std::string::npos);
  EXPECT_EQ(a.options().find("RADCL_HAS_METAL"), std::string::npos);
  EXPECT_NE(b.options().find("-DRADCL_AMBIENT_CACHE=1"), std::string::npos);

  std::string sa = a.program({"probe/features.cl"}).assemble();
  std::string sb = b.program({"probe/features.cl"}).assemble();
  EXPECT_NE(sa, sb);
  // Absent materials contribute no code at all.
  const std::string plastic_file = "#line 1 \"materials/plastic.cl\"";
  const std::string metal_file = "#line 1 \"materials/metal.cl\"";
  EXPECT_NE(sa.find(plastic_file), std::string::npos);
  EXPECT_EQ(sa.find(metal_file), std::string::npos);
  EXPECT_NE(sb.find(metal_file), std::string::npos);
  EXPECT_EQ(sb.find(plastic_file), std::string::npos);
  EXPECT_EQ(sb.find("static inline rc_ward_iso rc_plastic_setup"), std::string::npos);
  // The shared lobe is included once even when both materials are present.
  FeatureSet both = a;
  both.add(RC_OBJ_METAL);
  std::string s = both.program({"probe/features.cl"}).assemble();
  EXPECT_EQ(s.find("typedef struct rc_ward_iso"), s.rfind("typedef struct rc_ward_iso"));
}

TEST(FeatureSet, EmptySetCarriesNoMaterialCode) {
  std::string s = FeatureSet().program({"probe/features.cl"}).assemble();
  EXPECT_EQ(s.find("materials/"), std::string::npos);
  EXPECT_EQ(s.find("static inline float3 rc_ward_iso_direct"), std::string::npos);
  std::vector<float> out = probe(FeatureSet(), {0.5f, 0.4f, 0.3f, 0.05f, 0.1f});
  for (float v : out)
    EXPECT_EQ(v, kSentinel);
}

TEST(FeatureSet, BuiltProgramsRunOnlyTheirMaterials) {
  const std::vector<float> in = {0.6f, 0.4f, 0.3f, 0.05f, 0.1f};
  FeatureSet plastic, metal;
  plastic.add(RC_OBJ_PLASTIC);
  metal.add(RC_OBJ_METAL);
  std::vector<float> p = probe(plastic, in), m = probe(metal, in);
  EXPECT_NEAR(p[RC_OBJ_PLASTIC], expected_red(false, 0.6, 0.05, 0.1),
              1e-4 * expected_red(false, 0.6, 0.05, 0.1));
  EXPECT_EQ(p[RC_OBJ_METAL], kSentinel);
  EXPECT_NEAR(m[RC_OBJ_METAL], expected_red(true, 0.6, 0.05, 0.1),
              1e-4 * expected_red(true, 0.6, 0.05, 0.1));
  EXPECT_EQ(m[RC_OBJ_PLASTIC], kSentinel);
}
