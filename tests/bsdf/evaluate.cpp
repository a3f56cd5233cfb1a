// The host reference evaluator on the reference files genBSDF made (shared/reference/README.md):
// hemispherical totals and the directions of their peaks.
#include "radcl/bsdf/evaluate.h"
#include "radcl/bsdf/xml_reader.h"

#include "test_env.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radcl::bsdf;
using radcl::vec::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 polar(double theta_deg, double phi_rad, double zsign = 1) {
  const double t = theta_deg * kPi / 180;
  return {std::sin(t) * std::cos(phi_rad), std::sin(t) * std::sin(phi_rad), zsign * std::cos(t)};
}

} // namespace

// Light from the room side (front) on every incident patch of the Klems blinds: reflectance
// plus transmittance lies in [0, 1], and equals the sum of the matrix column times lambda.
TEST(BsdfEvaluate, BlindsKlemsTotals) {
  const BsdfData d = read_bsdf_xml(radcl::test::data("scenes/blinds_klems.xml"));
  const KlemsMatrix& t = d.find(Part::TransmitFront)->klems;
  const KlemsMatrix& r = d.find(Part::ReflectFront)->klems;
  const KlemsBasis& b = t.in_basis;
  ASSERT_EQ(b.size(), 145);
  double lambda_sum = 0;
  for (int o = 0; o < b.size(); ++o)
    lambda_sum += b.lambda(o);
  EXPECT_NEAR(lambda_sum / kPi, 1, 1e-6);
  double lowest = 1, highest = 0;
  for (int i = 0; i < b.size(); ++i) {
    double tsum = 0, rsum = 0;
    for (int o = 0; o < b.size(); ++o) {
      tsum += t.value(i, o) * b.lambda(o);
      rsum += r.value(i, o) * b.lambda(o);
    }
    const Vec3 c = b.centre(i);
    const Vec3 in{-c[0], -c[1], c[2]}; // arriving through incident patch i
    const Xyz tt = hemispherical(d, in, false), rr = hemispherical(d, in, true);
    EXPECT_NEAR(tt.y, tsum, 1e-12 * tsum) << i;
    EXPECT_NEAR(rr.y, rsum, 1e-12 * rsum) << i;
    EXPECT_EQ(tt.x, tt.y); // grey
    EXPECT_GE(tsum, 0);
    EXPECT_GE(rsum, 0);
    EXPECT_LE(tsum + rsum, 1.0 + 1e-3) << i;
    lowest = std::min(lowest, tsum + rsum);
    highest = std::max(highest, tsum + rsum);
  }
  // Absorbing slats (reflectances .7 and .05 + .6 specular) take a third to three fifths
  // at the worst angles; looking along the slats almost everything passes.
  EXPECT_GT(lowest, 0.3);
  EXPECT_GT(highest, 0.95);
  // Light passing between the slats keeps its direction: for most incident patches the largest
  // transmission is straight through (-in), which Radiance's conventions put on the diagonal.
  int straight = 0;
  for (int i = 0; i < b.size(); ++i) {
    const Vec3 c = b.centre(i);
    const Vec3 in{-c[0], -c[1], c[2]};
    const double through = f(d, in, Vec3{-in[0], -in[1], -in[2]}).y;
    EXPECT_EQ(through, t.value(i, i));
    bool largest = true;
    for (int o = 0; o < b.size(); ++o) {
      const Vec3 e = b.centre(o);
      largest = largest && f(d, in, Vec3{e[0], e[1], -e[2]}).y <= through;
    }
    straight += largest;
  }
  EXPECT_GE(straight, 120);
  // From the back (outdoors): no reflection data; transmission by reciprocity.
  const Vec3 out_side = polar(40, 1.0, -1);
  EXPECT_EQ(hemispherical(d, out_side, true).y, 0);
  const double tb = hemispherical(d, out_side, false).y;
  EXPECT_GT(tb, 0);
  EXPECT_LT(tb, 2);
}

// The film (bsdf_film_src.rad): trans with reflectance .85, 80% of it transmitted, 60% of that
// unscattered: R = .17 and T = .68 at every angle and from both sides, with a sharp peak
// straight through.
TEST(BsdfEvaluate, FilmTensorTree) {
  const BsdfData d = read_bsdf_xml(radcl::test::data("scenes/film_t3.xml"));
  for (double theta : {0.0, 15.0, 40.0, 65.0})
    for (double zsign : {1.0, -1.0}) {
      const Vec3 in = polar(theta, 0.4 + theta, zsign);
      EXPECT_NEAR(hemispherical(d, in, true).y, 0.17, 0.005) << theta << " " << zsign;
      EXPECT_NEAR(hemispherical(d, in, false).y, 0.68, 0.01) << theta << " " << zsign;
    }
  for (double theta : {10.0, 30.0, 50.0}) {
    const Vec3 in = polar(theta, 2.0);
    const Vec3 through{-in[0], -in[1], -in[2]};
    const double peak = f(d, in, through).y;
    EXPECT_GT(peak, 10) << theta; // 60% of .68 in a leaf of the tree's finest size
    EXPECT_LT(f(d, in, polar(theta, 2.0 + 0.5, -1)).y, 0.2) << theta;
    EXPECT_LT(f(d, in, polar(theta + 20, 2.0 + kPi, -1)).y, 0.2) << theta;
  }
  // The grid of the integration is aligned with the leaves: 128 and 256 cells agree.
  const Vec3 in = polar(35, 0.3);
  EXPECT_NEAR(hemispherical(d, in, false, 128).y, hemispherical(d, in, false, 256).y, 1e-6);
}

// The glossy tile (bsdf_glossy_src.rad): plastic .45 .4 .35 (Y about .407), specular .08:
// R about .92 * .407 + .08 = .455 from the front, nothing from the back; a specular peak at
// the mirror direction. genBSDF left a little transmission near grazing incidence (rays past
// the tile's edge): at most 2%, none within 15 degrees of the normal.
TEST(BsdfEvaluate, GlossyTensorTree) {
  const BsdfData d = read_bsdf_xml(radcl::test::data("scenes/glossy_t3.xml"));
  for (double theta : {0.0, 10.0, 20.0, 45.0, 70.0, 85.0}) {
    const Vec3 in = polar(theta, 1.1);
    EXPECT_NEAR(hemispherical(d, in, true).y, 0.455, 0.01) << theta;
    const double t = hemispherical(d, in, false).y;
    EXPECT_GE(t, 0);
    EXPECT_LT(t, 0.02);
    if (theta < 15) {
      EXPECT_EQ(t, 0) << theta;
    }
    const Vec3 back{in[0], in[1], -in[2]};
    EXPECT_EQ(hemispherical(d, back, true).y, 0);
  }
  const Vec3 in = polar(30, -0.7);
  const Vec3 mirror{-in[0], -in[1], in[2]};
  const double peak = f(d, in, mirror).y;
  EXPECT_GT(peak, 0.6);                           // the lobe averaged over the tree's leaves
  EXPECT_LT(f(d, in, polar(30, -0.7, 1)).y, 0.2); // back towards the light
  EXPECT_LT(f(d, in, polar(10, -0.7 + kPi, 1)).y, 0.2);
  EXPECT_LT(f(d, in, polar(30, -0.7 + kPi / 2, 1)).y, 0.2);
  EXPECT_NEAR(f(d, in, polar(60, -0.7, 1)).y, 0.3745 / kPi, 0.02);
}
