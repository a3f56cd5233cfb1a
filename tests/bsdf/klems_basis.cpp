// Klems bases: the built-in LBNL bases, patch lookup, centres, projected solid angles, and the
// conventions that map a component's vectors to patches; read through a file-defined basis.
#include "radcl/bsdf/klems_basis.h"
#include "radcl/bsdf/evaluate.h"
#include "radcl/bsdf/xml_reader.h"
#include "radcl/util/error.h"

#include "files.h"
#include "test_env.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>

using namespace radcl::bsdf;
using radcl::vec::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

Vec3 polar(double theta_deg, double phi_deg) {
  const double t = theta_deg * kDeg, p = phi_deg * kDeg;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

} // namespace

TEST(KlemsBasis, StandardBasesHaveLbnlSizes) {
  const KlemsBasis* full = KlemsBasis::standard("LBNL/Klems Full");
  const KlemsBasis* half = KlemsBasis::standard("lbnl/klems half");
  const KlemsBasis* quarter = KlemsBasis::standard("LBNL/Klems Quarter");
  ASSERT_TRUE(full && half && quarter);
  EXPECT_EQ(full->size(), 145);
  EXPECT_EQ(full->rings(), 9);
  EXPECT_EQ(half->size(), 73);
  EXPECT_EQ(half->rings(), 7);
  EXPECT_EQ(quarter->size(), 41);
  EXPECT_EQ(quarter->rings(), 5);
  EXPECT_EQ(KlemsBasis::standard("LBNL/Klems Eighth"), nullptr);
  EXPECT_EQ(full->theta_upper(8), 90);
  EXPECT_EQ(full->nphis(4), 24);
  EXPECT_EQ(full->first_patch(2), 9);
}

TEST(KlemsBasis, LambdasSumToPiOverTheHemisphere) {
  for (const char* name : {"LBNL/Klems Full", "LBNL/Klems Half", "LBNL/Klems Quarter"}) {
    const KlemsBasis& b = *KlemsBasis::standard(name);
    double sum = 0;
    for (int p = 0; p < b.size(); ++p) {
      EXPECT_GT(b.lambda(p), 0) << name << " patch " << p;
      sum += b.lambda(p);
    }
    EXPECT_NEAR(sum / kPi, 1.0, 1e-6) << name;
  }
  // The cap of the full basis: pi (1 - cos^2 5 deg).
  const KlemsBasis& full = *KlemsBasis::standard("LBNL/Klems Full");
  EXPECT_NEAR(full.lambda(0), kPi * std::pow(std::sin(5 * kDeg), 2), 1e-15);
  // A patch of the 15-25 degree ring: pi (cos^2 15 - cos^2 25) / 16.
  const double c15 = std::cos(15 * kDeg), c25 = std::cos(25 * kDeg);
  EXPECT_NEAR(full.lambda(20), kPi * (c15 * c15 - c25 * c25) / 16, 1e-15);
  EXPECT_EQ(full.lambda(145), 0);
}

// Patch 0 of a ring straddles +x, and azimuth runs from +x towards +y.
TEST(KlemsBasis, PatchOfDirection) {
  const KlemsBasis& full = *KlemsBasis::standard("LBNL/Klems Full");
  EXPECT_EQ(full.patch({0, 0, 1}), 0);
  EXPECT_EQ(full.patch(polar(4.9, 200)), 0);
  EXPECT_EQ(full.patch(polar(10, 0)), 1); // ring 5-15, 8 patches of 45 deg
  EXPECT_EQ(full.patch(polar(10, 22)), 1);
  EXPECT_EQ(full.patch(polar(10, 23)), 2);
  EXPECT_EQ(full.patch(polar(10, 90)), 3);
  EXPECT_EQ(full.patch(polar(10, 337)), 8);
  EXPECT_EQ(full.patch(polar(10, 338)), 1); // wraps to the patch on +x
  EXPECT_EQ(full.patch(polar(10, -10)), 1);
  EXPECT_EQ(full.patch(polar(80, 180)), 133 + 6); // last ring starts at 133, 12 patches
  EXPECT_EQ(full.patch(polar(89.9, 0)), 133);
  EXPECT_EQ(full.patch(Vec3{2, 0, 0.01}), 133); // need not be unit
  EXPECT_EQ(full.patch(Vec3{1, 0, 0}), -1);     // the horizon is outside
  EXPECT_EQ(full.patch(Vec3{0, 0, -1}), -1);
}

TEST(KlemsBasis, CentresLieInTheirPatches) {
  for (const char* name : {"LBNL/Klems Full", "LBNL/Klems Half", "LBNL/Klems Quarter"}) {
    const KlemsBasis& b = *KlemsBasis::standard(name);
    for (int p = 0; p < b.size(); ++p) {
      const Vec3 c = b.centre(p);
      EXPECT_NEAR(radcl::vec::length(c), 1.0, 1e-12);
      EXPECT_EQ(b.patch(c), p) << name;
    }
  }
  const KlemsBasis& full = *KlemsBasis::standard("LBNL/Klems Full");
  const Vec3 c0 = full.centre(0), c3 = full.centre(3), c133 = full.centre(133);
  EXPECT_EQ(c0[2], 1.0);
  EXPECT_NEAR(std::acos(c3[2]) / kDeg, 10, 1e-12); // middle of the 5-15 ring
  EXPECT_NEAR(std::atan2(c3[1], c3[0]) / kDeg, 90, 1e-12);
  EXPECT_NEAR(std::acos(c133[2]) / kDeg, 82.5, 1e-12);
  EXPECT_NEAR(c133[1], 0, 1e-15);
}

TEST(KlemsBasis, InvalidDefinitionsAreFatal) {
  using radcl::FatalError;
  EXPECT_THROW(KlemsBasis("x", {0}, {}), FatalError);
  EXPECT_THROW(KlemsBasis("x", {0, 30, 20}, {1, 4}), FatalError); // decreasing theta
  EXPECT_THROW(KlemsBasis("x", {0, 30, 95}, {1, 4}), FatalError); // past the horizon
  EXPECT_THROW(KlemsBasis("x", {5, 30, 90}, {1, 4}), FatalError); // no polar start
  EXPECT_THROW(KlemsBasis("x", {0, 30, 90}, {1, 1}), FatalError); // one patch off the pole
  EXPECT_THROW(KlemsBasis("x", {0, 30, 90}, {1, 0}), FatalError);
  // A basis may stop short of the horizon; beyond it there is no patch.
  const KlemsBasis part("x", {0, 30, 60}, {4, 8});
  EXPECT_EQ(part.size(), 12);
  EXPECT_EQ(part.patch(polar(70, 0)), -1);
  EXPECT_EQ(part.patch(polar(10, 90)), 1); // a first ring of 4 patches has no cap
  EXPECT_NEAR(std::acos(part.centre(1)[2]) / kDeg, 15, 1e-12);
}

// Radiance's conventions: an incident vector is indexed by the direction light travels across
// the surface, an outgoing one as it is, each on its own side.
TEST(KlemsBasis, IncidentAndOutgoingPatches) {
  const KlemsBasis& full = *KlemsBasis::standard("LBNL/Klems Full");
  const Vec3 in = polar(10, 180); // light from -x, travelling towards +x
  EXPECT_EQ(incident_patch(full, in, true), 1);
  EXPECT_EQ(incident_patch(full, in, false), -1);
  const Vec3 in_back{in[0], in[1], -in[2]};
  EXPECT_EQ(incident_patch(full, in_back, false), 1);
  EXPECT_EQ(outgoing_patch(full, polar(10, 0), true), 1); // the mirror direction
  const Vec3 through{-in[0], -in[1], -in[2]};
  EXPECT_EQ(outgoing_patch(full, through, false), 1); // straight through
  EXPECT_EQ(outgoing_patch(full, through, true), -1);
}

// A file-defined basis and every element of its matrices come back exactly, for every pair of
// patch centres.
TEST(KlemsBasis, FileDefinedBasisReadsExactly) {
  const BsdfData d = read_bsdf_xml(radcl::test::data("bsdf/klems_3ring.xml"));
  EXPECT_EQ(d.format, Format::Klems);
  ASSERT_EQ(d.components.size(), 2u);
  const Component& t = d.components[0];
  const Component& r = d.components[1];
  EXPECT_EQ(t.part, Part::TransmitFront);
  EXPECT_EQ(t.direction, "Transmission Back");
  EXPECT_EQ(r.part, Part::ReflectFront);
  const KlemsBasis& b = t.klems.in_basis;
  EXPECT_EQ(b.name(), "Test 3-ring");
  ASSERT_EQ(b.size(), 9);
  EXPECT_EQ(b.rings(), 3);
  EXPECT_EQ(b.theta_upper(1), 60);
  EXPECT_EQ(b.nphis(2), 4);
  EXPECT_NEAR(b.lambda(0), kPi / 4, 1e-15);
  EXPECT_EQ(t.klems.out_basis.size(), 9);
  EXPECT_TRUE(t.colour());
  EXPECT_FALSE(r.colour());

  for (int i = 0; i < 9; ++i)
    for (int o = 0; o < 9; ++o) {
      const float expect = static_cast<float>((o + 1) + (i + 1) / 100.0);
      EXPECT_EQ(t.klems.value(i, o), expect);
      EXPECT_EQ(t.klems.y[o * 9 + i], expect);
      EXPECT_EQ(t.klems.x[o * 9 + i], static_cast<float>(20 + (o + 1) + (i + 1) / 100.0));
      EXPECT_EQ(t.klems.z[o * 9 + i], static_cast<float>(30 + (o + 1) + (i + 1) / 100.0));
      EXPECT_EQ(r.klems.value(i, o), static_cast<float>(10 + (o + 1) + (i + 1) / 100.0));

      // Through the evaluator: incident i from the front, out o through the back / mirrored.
      const Vec3 ci = b.centre(i), co = b.centre(o);
      const Vec3 in{-ci[0], -ci[1], ci[2]};
      const Xyz ft = f(d, in, Vec3{co[0], co[1], -co[2]});
      EXPECT_EQ(ft.y, expect);
      EXPECT_EQ(ft.x, t.klems.x[o * 9 + i]);
      EXPECT_EQ(ft.z, t.klems.z[o * 9 + i]);
      const Xyz fr = f(d, in, co);
      EXPECT_EQ(fr.y, r.klems.value(i, o));
      EXPECT_EQ(fr.x, fr.y); // grey
      // Light from the back: no back transmission in the file, so the front one is used by
      // reciprocity (in and out exchanged); no back reflection at all.
      const Vec3 in_back{co[0], co[1], -co[2]};
      EXPECT_EQ(f(d, in_back, in).y, expect);
      EXPECT_EQ(f(d, in_back, Vec3{-co[0], -co[1], -co[2]}).y, 0);
    }
}

// "Rows" puts the incident direction on the file's rows: the same text read that way is the
// transpose.
TEST(KlemsBasis, RowsAreTheTranspose) {
  std::string text = radcl::test::read_file(radcl::test::data("bsdf/klems_3ring.xml"));
  const size_t at = text.find("<IncidentDataStructure>Columns");
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 23, 7, "Rows");
  const BsdfData d = parse_bsdf_xml(text, "rows.xml");
  const KlemsMatrix& m = d.components[0].klems;
  for (int i = 0; i < 9; ++i)
    for (int o = 0; o < 9; ++o)
      EXPECT_EQ(m.value(i, o), static_cast<float>((i + 1) + (o + 1) / 100.0));
}
