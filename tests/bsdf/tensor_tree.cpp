// Tensor trees: the flat layout, lookups through the Shirley-Chiu map in Radiance's
// coordinates, exact values from small hand-written TT3 and TT4 files, and syntax errors.
#include "radcl/bsdf/tensor_tree.h"
#include "radcl/bsdf/evaluate.h"
#include "radcl/bsdf/xml_reader.h"

#include "test_env.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radcl::bsdf;
using radcl::vec::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The unit vector whose (x, y) maps to square position (s, t), on the side of z's sign.
Vec3 from_square(double s, double t, double zsign) {
  const auto d = square_to_disk(s, t);
  return {d[0], d[1], zsign * std::sqrt(1 - d[0] * d[0] - d[1] * d[1])};
}

Vec3 turned(const Vec3& v, double a) {
  return {v[0] * std::cos(a) - v[1] * std::sin(a), v[0] * std::sin(a) + v[1] * std::cos(a), v[2]};
}

} // namespace

TEST(ShirleyChiu, KnownPointsAndRoundTrip) {
  auto near2 = [](std::array<double, 2> a, double x, double y) {
    EXPECT_NEAR(a[0], x, 1e-12);
    EXPECT_NEAR(a[1], y, 1e-12);
  };
  near2(disk_to_square(0, 0), 0.5, 0.5);
  near2(disk_to_square(1, 0), 1, 0.5);
  near2(disk_to_square(0, 1), 0.5, 1);
  near2(disk_to_square(-1, 0), 0, 0.5);
  near2(disk_to_square(0, -0.5), 0.5, 0.25);
  near2(disk_to_square(std::sqrt(0.5), std::sqrt(0.5)), 1, 1);
  near2(square_to_disk(0.5, 0.5), 0, 0);
  near2(square_to_disk(1, 0.5), 1, 0);
  near2(square_to_disk(0.75, 0.5), 0.5, 0);
  near2(square_to_disk(0, 0), -std::sqrt(0.5), -std::sqrt(0.5));
  // Concentric squares become circles; a square's side sweeps a quarter circle evenly.
  near2(square_to_disk(1, 0.75), std::cos(kPi / 8), std::sin(kPi / 8));
  for (double s = 0.01; s < 1; s += 0.0237)
    for (double t = 0.013; t < 1; t += 0.0311) {
      const auto d = square_to_disk(s, t);
      EXPECT_LT(d[0] * d[0] + d[1] * d[1], 1.0);
      near2(disk_to_square(d[0], d[1]), s, t);
    }
}

// The equal-area property: a square cell's share of the square is its share of the disk.
TEST(ShirleyChiu, KeepsAreas) {
  int inside = 0, total = 0;
  for (int i = 0; i < 400; ++i)
    for (int j = 0; j < 400; ++j) {
      const auto d = square_to_disk((i + 0.5) / 400, (j + 0.5) / 400);
      inside += d[0] * d[0] + d[1] * d[1] < 0.25; // the disk of radius 1/2
      ++total;
    }
  EXPECT_NEAR(static_cast<double>(inside) / total, 0.25, 2e-3);
}

TEST(TensorTree, FlatLayout) {
  const TensorTree t = parse_tensor_tree(
      "{ {1} {2}, {3} {4} { {5} {6} {7} {8} {9} {10} {11} {12} } {0.5 1.5 2.5 3.5 4.5 5.5 6.5 "
      "7.5} {-7} {8e-1} }",
      3);
  EXPECT_EQ(t.ndim, 3);
  ASSERT_FALSE(t.empty());
  EXPECT_EQ(t.nodes[0], -1); // the root branches
  // Child 4 is a branch; child 5 a grid of 8 values (log2 resolution 1).
  const int32_t b4 = t.nodes[1 + 4], g5 = t.nodes[1 + 5], l0 = t.nodes[1];
  EXPECT_EQ(t.nodes[b4], -1);
  EXPECT_EQ(t.nodes[g5], 1);
  EXPECT_EQ(t.values[t.nodes[g5 + 1]], 0.5f);
  EXPECT_EQ(t.nodes[l0], 0);
  EXPECT_EQ(t.values[t.nodes[l0 + 1]], 1.0f);
  EXPECT_EQ(t.values.size(), 4u + 8u + 8u + 2u);
  EXPECT_EQ(t.values[t.nodes[t.nodes[1 + 6] + 1]], 0.0f); // negative reads as 0
  // Lookups: child c covers the upper half of dimension d where bit d is set.
  auto at = [&](double a, double b, double c) {
    const double p[3] = {a, b, c};
    return t.lookup(p);
  };
  EXPECT_EQ(at(0.1, 0.1, 0.1), 1);
  EXPECT_EQ(at(0.9, 0.1, 0.1), 2);
  EXPECT_EQ(at(0.1, 0.9, 0.1), 3);
  EXPECT_EQ(at(0.6, 0.9, 0.1), 4);
  EXPECT_EQ(at(0.2, 0.2, 0.7), 5);  // child 4, then its child 0
  EXPECT_EQ(at(0.3, 0.2, 0.7), 6);  // its child 1 (upper quarter of dimension 0)
  EXPECT_EQ(at(0.3, 0.3, 0.9), 12); // its child 7
  // Grid of child 5: dimension 0 slowest, dimension 2 fastest.
  EXPECT_EQ(at(0.6, 0.1, 0.6), 0.5f);
  EXPECT_EQ(at(0.6, 0.1, 0.8), 1.5f);
  EXPECT_EQ(at(0.6, 0.3, 0.6), 2.5f);
  EXPECT_EQ(at(0.8, 0.1, 0.6), 4.5f);
  EXPECT_EQ(at(0.99, 0.49, 0.99), 7.5f);
  EXPECT_EQ(at(0.9, 0.9, 0.9), 0.8f);
  EXPECT_EQ(at(1.0, 1.0, 1.0), 0.8f); // clamped inside
  EXPECT_EQ(at(-1, 0, 0), 1);

  // A single leaf and a single grid are trees too.
  const TensorTree one = parse_tensor_tree(" { 0.25 } ", 4);
  EXPECT_EQ(one.nodes, (std::vector<int32_t>{0, 0}));
  const double p[4] = {0.3, 0.9, 0.1, 0.5};
  EXPECT_EQ(one.lookup(p), 0.25f);
  std::string grid = "{";
  for (int k = 0; k < 256; ++k) {
    grid += ' ';
    grid += std::to_string(k);
  }
  const TensorTree g = parse_tensor_tree(grid + "}", 4);
  EXPECT_EQ(g.nodes, (std::vector<int32_t>{2, 0}));
  const double q[4] = {0.3, 0.9, 0.1, 0.5}; // cells 1, 3, 0, 2 of 4
  EXPECT_EQ(g.lookup(q), ((1 * 4 + 3) * 4 + 0) * 4 + 2);
}

TEST(TensorTree, SyntaxErrors) {
  auto offset_of = [](const char* text, int nd) -> long {
    try {
      parse_tensor_tree(text, nd);
    } catch (const TreeSyntaxError& e) {
      return static_cast<long>(e.offset());
    }
    return -1;
  };
  EXPECT_EQ(offset_of("1 2 3", 3), 0);        // missing '{'
  EXPECT_EQ(offset_of("{ 1 2 3 }", 3), 0);    // 3 values
  EXPECT_EQ(offset_of("{ }", 3), 0);          // none
  EXPECT_EQ(offset_of("{ {1} {2} }", 3), 10); // 2 subtrees of 8
  EXPECT_EQ(offset_of("{ 1 ", 3), 4);         // missing '}'
  EXPECT_EQ(offset_of("{ 1 x }", 3), 4);      // bad number
  EXPECT_EQ(offset_of("{ 1e }", 3), 2);
  EXPECT_EQ(offset_of("{ nan }", 3), 2);
  EXPECT_EQ(offset_of("{ 1e999 }", 3), 2); // overflows
  EXPECT_EQ(offset_of("{ 1 } }", 3), 6);   // extra characters
  EXPECT_EQ(offset_of("{ 1 }{ 1 }", 3), 5);
  EXPECT_EQ(offset_of("{ 0x10 }", 3), 2);
  EXPECT_EQ(offset_of("{ 1 } ,", 3), -1); // a trailing comma is allowed
  EXPECT_EQ(offset_of("{ +1, -2, .5, 5., 1E+2, 3e-2, 7, 8 }", 3), -1);
  std::string deep;
  for (int k = 0; k < 40; ++k)
    deep += "{ ";
  EXPECT_GE(offset_of(deep.c_str(), 3), 0); // nesting is bounded
}

// Radiance's coordinates for TT3: dimension 0 from the incident polar angle (only its lower
// half is used), 1-2 from the outgoing vector turned so that the light travels along +x.
TEST(TensorTree, Tt3Position) {
  TensorTree t;
  t.ndim = 3;
  const double a = 0.7; // incident azimuth, away from the axes
  const Vec3 in{0.6 * std::cos(a), 0.6 * std::sin(a), 0.8};
  const auto p = t.position(in, {0, 0, 1});
  EXPECT_NEAR(p[0], 0.5 - 1e-6 - 0.3, 1e-15);
  EXPECT_NEAR(p[1], 0.5, 1e-12);
  // The mirror direction lands on +x of the disk: radius 0.6.
  const auto m = t.position(in, {-in[0], -in[1], in[2]});
  EXPECT_NEAR(m[1], 0.8, 1e-12);
  EXPECT_NEAR(m[2], 0.5, 1e-12);
  // So does straight-through transmission.
  const auto s = t.position(in, {-in[0], -in[1], -in[2]});
  EXPECT_NEAR(s[1], 0.8, 1e-12);
  // Grazing incidence is at 0, normal incidence just below 1/2, where atan2 of the signed zeros
  // turns the outgoing vector by pi.
  EXPECT_NEAR(t.position({1, 0, 0}, {0, 0, 1})[0], 0, 1e-5);
  const auto n = t.position({0, 0, 1}, {0.5, 0, 0.866});
  EXPECT_EQ(n[0], 0.5 - 1e-6);
  EXPECT_NEAR(n[1], 0.25, 1e-12);
}

TEST(TensorTree, Tt4Position) {
  TensorTree t;
  t.ndim = 4;
  const auto p = t.position({0.5, 0, 0.866}, {0, -1, 0});
  EXPECT_NEAR(p[0], 0.25, 1e-12); // -in.x
  EXPECT_NEAR(p[1], 0.5, 1e-12);
  EXPECT_NEAR(p[2], 0.5, 1e-12);
  EXPECT_NEAR(p[3], 0, 1e-12);
}

// Every leaf of the TT3 file at cell centres of a 1/16 grid, through the whole evaluator.
TEST(TensorTree, Tt3FileValuesComeBackExactly) {
  const BsdfData d = read_bsdf_xml(radcl::test::data("bsdf/tt3_small.xml"));
  EXPECT_EQ(d.format, Format::TensorTree3);
  ASSERT_EQ(d.components.size(), 2u);
  const Component& r = d.components[0];
  EXPECT_EQ(r.part, Part::ReflectFront);
  EXPECT_EQ(r.scattering_type, "BRDF");
  EXPECT_TRUE(r.colour());
  EXPECT_EQ(d.components[1].part, Part::TransmitBack);
  EXPECT_FALSE(d.components[1].colour());

  // The value the file gives at hypercube position (p0, s, t), worked out by hand.
  auto expected = [](double p0, double s, double t) -> float {
    const int c = (p0 >= 0.5) | (s >= 0.5) << 1 | (t >= 0.5) << 2;
    const double q0 = 2 * p0 - (c & 1), q1 = 2 * s - (c >> 1 & 1), q2 = 2 * t - (c >> 2);
    switch (c) {
    case 0:
      return static_cast<float>(0.1 * (1 + ((q0 >= 0.5) * 4 + (q1 >= 0.5) * 2 + (q2 >= 0.5))));
    case 2:
      return 2;
    case 4: {
      const int k = (q0 >= 0.5) | (q1 >= 0.5) << 1 | (q2 >= 0.5) << 2;
      return k == 7 ? 0.0f : static_cast<float>(4 + k / 10.0);
    }
    case 6:
      return 6;
    default:
      return 99;
    }
  };
  int checked = 0;
  for (int i0 = 0; i0 < 8; i0 += 1) {
    const double p0 = (2 * i0 + 1) / 32.0; // centres of 1/16 cells of the lower half
    const double sin_in = 2 * (0.5 - 1e-6 - p0);
    const double az = 0.3 + i0; // any azimuth
    const Vec3 in{sin_in * std::cos(az), sin_in * std::sin(az), std::sqrt(1 - sin_in * sin_in)};
    for (int i = 0; i < 16; ++i)
      for (int j = 0; j < 16; ++j) {
        const double s = (i + 0.5) / 16, t = (j + 0.5) / 16;
        // Undo the turn the lookup makes: the light's direction of travel is at azimuth `az`+pi.
        const Vec3 out = turned(from_square(s, t, 1), std::atan2(-in[1], -in[0]));
        const float e = expected(p0, s, t);
        ASSERT_NE(e, 99);
        const Xyz v = f(d, in, out);
        EXPECT_EQ(v.y, e) << p0 << " " << s << " " << t;
        EXPECT_NEAR(v.x, v.y * 9 * 0.2 / (4 * 0.45), 1e-6 * v.y); // u' 0.2, v' 0.45
        EXPECT_NEAR(v.z, v.y * (12 - 3 * 0.2 - 20 * 0.45) / (4 * 0.45), 1e-6 * v.y);
        ++checked;
      }
  }
  EXPECT_EQ(checked, 8 * 256);
  // Normal incidence: dimension 0 just below 1/2, and the outgoing vector turned by pi.
  const Vec3 out = from_square(0.1, 0.3, 1);
  EXPECT_EQ(f(d, {0, 0, 1}, out).y, expected(0.5 - 1e-6, 0.9, 0.7));
  // Reflection from the back and front transmission: only back transmission is in the file,
  // one value, also used the other way round.
  EXPECT_EQ(f(d, {0, 0.6, -0.8}, {0.3, 0, -0.95}).y, 0);
  EXPECT_EQ(f(d, {0, 0.6, -0.8}, {0.3, 0, 0.95}).y, 0.25f);
  EXPECT_EQ(f(d, {0, 0.6, 0.8}, {0.3, 0, -0.95}).y, 0.25f);
  EXPECT_EQ(f(d.components[1], {0, 0.6, 0.8}, {0.3, 0, 0.95}).y, 0); // reflection pair
  // Hemispherical totals: the transmission is one leaf, 0.25 pi.
  EXPECT_NEAR(hemispherical(d, {0, 0.6, -0.8}, false, 64).y, 0.25 * kPi, 1e-6);
  EXPECT_NEAR(hemispherical(d, {0, 0.6, 0.8}, false, 64).y, 0.25 * kPi, 1e-6);
}

// Every leaf of the TT4 file: 4^4 combinations of quarter-cell centres.
TEST(TensorTree, Tt4FileValuesComeBackExactly) {
  const BsdfData d = read_bsdf_xml(radcl::test::data("bsdf/tt4_small.xml"));
  EXPECT_EQ(d.format, Format::TensorTree4);
  ASSERT_EQ(d.components.size(), 1u);
  const Component& c = d.components[0];
  EXPECT_EQ(c.part, Part::TransmitFront);
  EXPECT_EQ(c.tree.y.ndim, 4);
  int checked = 0;
  for (int k = 0; k < 256; ++k) {
    double p[4];
    for (int dim = 0; dim < 4; ++dim)
      p[dim] = ((k >> (2 * dim) & 3) + 0.5) / 4;
    int child = 0;
    for (int dim = 0; dim < 4; ++dim)
      child |= (p[dim] >= 0.5) << dim;
    float e = static_cast<float>(child + 1);
    if (child == 5) {
      int cell = 0;
      for (int dim = 0; dim < 4; ++dim)
        cell = cell * 2 + (2 * p[dim] - (child >> dim & 1) >= 0.5);
      e = static_cast<float>(5 + cell / 100.0);
    }
    // Dimensions 0-1 come from the reversed incident vector, 2-3 from the outgoing one.
    const Vec3 rin = from_square(p[0], p[1], 1);
    const Vec3 in{-rin[0], -rin[1], rin[2]};
    const Vec3 out = from_square(p[2], p[3], -1);
    EXPECT_EQ(f(d, in, out).y, e) << k;
    EXPECT_EQ(f(d, in, out).x, e); // grey
    // Light from the back uses the same data with in and out exchanged.
    EXPECT_EQ(f(d, out, in).y, e) << k;
    EXPECT_EQ(f(d, in, Vec3{out[0], out[1], -out[2]}).y, 0); // no reflection
    ++checked;
  }
  EXPECT_EQ(checked, 256);
  // The hemispherical transmittance is exact on a grid aligned with the leaves: for incident
  // cell (0, 0) children 0, 4, 8 and 12 each fill a quarter of the output square.
  const Vec3 rin = from_square(0.25, 0.25, 1);
  EXPECT_NEAR(hemispherical(d, {-rin[0], -rin[1], rin[2]}, false, 16).y,
              kPi * (1 + 5 + 9 + 13) / 4.0, 1e-12);
}
