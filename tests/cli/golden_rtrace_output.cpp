// rtrace end to end on materials_plain (no function files needed) against Radiance 5.4a's
// stored outputs: geometric fields and names of -ooodLpnNsmM, values of -ov with -ab 0, binary
// -ff/-fd/-fac layouts, and the header written without -h.
#include "radcl/luminance.h"
#include <algorithm>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "reference_data.h"
#include "run_program.h"
#include "test_env.h"

using radcl::test::run_command;

namespace {

const std::string kDirect = "-ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1";

// Runs rtrace in the scene folder with `args`, input from `input` (a file in that folder).
std::string rtrace(const std::string& args, const std::string& input, int* rc = nullptr) {
  const radcl::test::ProgramRun r =
      radcl::test::Program("rtrace")
          .input(radcl::test::read_file(radcl::test::data("scenes/" + input)))
          .run(args + " materials_plain.oct");
  if (rc) *rc = r.rc;
  return r.out;
}

std::vector<std::vector<std::string>> rows(const std::string& text) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::size_t p = 0, q;
    while ((q = line.find('\t', p)) != std::string::npos) {
      f.push_back(line.substr(p, q - p));
      p = q + 1;
    }
    out.push_back(f);
  }
  return out;
}

double lum(double r, double g, double b) {
  return radcl::bright(r, g, b);
}

} // namespace

TEST(GoldenRtraceOutput, GeometricFieldsAndNames) {
  auto ours = rows(rtrace("-h -ooodLpnNsmM", "materials_rays.txt"));
  auto ref = rows(radcl::test::read_file(
      radcl::test::data("results/materials_plain_rays_oodvVwWlLcpnNsmMrxRX.txt")));
  ASSERT_EQ(ours.size(), 160u);
  ASSERT_EQ(ref.size(), 160u);
  // Column of each of our letters in the reference line (o o d v V w W l L c p n N s m M ...).
  const int ref_col[] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  20, 23,
                         24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34};
  for (std::size_t k = 0; k < ours.size(); ++k) {
    ASSERT_EQ(ours[k].size(), 22u) << "ray " << k;
    for (int c = 0; c < 22; ++c) {
      const std::string& a = ours[k][c];
      const std::string& b = ref[k][ref_col[c]];
      if (c >= 19) {
        EXPECT_EQ(a, b) << "ray " << k << " name column " << c;
      } else {
        double x = std::stod(a), y = std::stod(b);
        EXPECT_NEAR(x, y, 1e-5 * std::max(1.0, std::fabs(y))) << "ray " << k << " column " << c;
      }
    }
  }
}

// Every value letter of the long specification with -ab 0: weights and coefficients of primary
// rays, the mirrored part and the mirrored and unmirrored lengths.
TEST(GoldenRtraceOutput, ValueLettersEndToEnd) {
  auto ours = rows(rtrace("-h -u- " + kDirect + " -ooodvVwWlLcpnNsmMrxRX", "materials_rays.txt"));
  auto ref = rows(radcl::test::read_file(
      radcl::test::data("results/materials_plain_rays_oodvVwWlLcpnNsmMrxRX.txt")));
  ASSERT_EQ(ours.size(), ref.size());
  struct Letter {
    char name;
    int first, count;
  } letters[] = {{'v', 9, 3},  {'V', 12, 3}, {'w', 15, 1}, {'W', 16, 3}, {'l', 19, 1},
                 {'L', 20, 1}, {'r', 35, 3}, {'x', 38, 3}, {'R', 41, 1}, {'X', 42, 1}};
  for (const Letter& l : letters) {
    int off = 0;
    for (std::size_t k = 0; k < ref.size(); ++k) {
      for (int c = l.first; c < l.first + l.count; ++c) {
        double a = std::stod(ours[k][c]), b = std::stod(ref[k][c]);
        if (std::fabs(a - b) > 0.02 * std::max(std::fabs(b), 1e-3)) {
          ++off;
          break;
        }
      }
    }
    // Values carry the sampling noise of rough surfaces: one ray (the water sphere) is 2.2% off.
    EXPECT_LE(off, 1) << "rays off by more than 2% in -o" << l.name;
  }
}

TEST(GoldenRtraceOutput, DirectValuesEndToEnd) {
  auto ours = rows(rtrace("-h -u- " + kDirect + " -ov", "materials_rays.txt"));
  auto ref = radcl::test::read_rgb(radcl::test::data("results/materials_plain_rays_v.txt"));
  ASSERT_EQ(ours.size(), ref.size());
  double sum = 0;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    double a = lum(std::stod(ours[k][0]), std::stod(ours[k][1]), std::stod(ours[k][2]));
    double b = lum(ref[k][0], ref[k][1], ref[k][2]);
    double e = std::fabs(a - b) / std::max(b, 1e-6);
    sum += e;
    EXPECT_LE(e, 0.10) << "ray " << k;
  }
  EXPECT_LE(sum / ref.size(), 0.01);
}

// -ab 1 -aa 0 -ad 2048 -lw 1e-5: indirect light by hemisphere sampling, against Radiance's run
// with the same settings, over the rays whose first hit is a diffuse (plastic) surface.
TEST(GoldenRtraceOutput, AmbientWithoutCache) {
  auto ours = rows(rtrace("-h -ab 1 -aa 0 -ad 2048 -lw 1e-5 -ov", "materials_rays.txt"));
  auto ref = radcl::test::read_rgb(radcl::test::data("results/materials_plain_rays_aa0.txt"));
  auto names = rows(radcl::test::read_file(
      radcl::test::data("results/materials_plain_rays_oodvVwWlLcpnNsmMrxRX.txt")));
  ASSERT_EQ(ours.size(), ref.size());
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    const std::string& m = names[k][34]; // M: the material reached
    if (m != "grey_floor" && m != "red_plastic" && m != "blue_plastic") continue;
    double a = lum(std::stod(ours[k][0]), std::stod(ours[k][1]), std::stod(ours[k][2]));
    double b = lum(ref[k][0], ref[k][1], ref[k][2]);
    sum += std::fabs(a - b) / b;
    ++n;
  }
  ASSERT_GT(n, 80);
  EXPECT_LE(sum / n, 0.03) << "mean relative error over " << n << " diffuse hits";
}

TEST(GoldenRtraceOutput, BinaryFormats) {
  // Float and double in, float and double out: 3 host-order numbers per ray, nothing else.
  std::string ff = rtrace("-h -u- " + kDirect + " -ff -ov", "materials_rays.f32");
  std::string fd = rtrace("-h -u- " + kDirect + " -fd -ov", "materials_rays.f64");
  std::string ref_ff =
      radcl::test::read_file(radcl::test::data("results/materials_plain_rays_ff.f32"));
  std::string ref_fd =
      radcl::test::read_file(radcl::test::data("results/materials_plain_rays_fd.f64"));
  ASSERT_EQ(ff.size(), ref_ff.size());
  ASSERT_EQ(fd.size(), ref_fd.size());
  std::vector<float> a(ff.size() / 4), b(ff.size() / 4);
  std::memcpy(a.data(), ff.data(), ff.size());
  std::memcpy(b.data(), ref_ff.data(), ff.size());
  std::vector<double> c(fd.size() / 8), d(fd.size() / 8);
  std::memcpy(c.data(), fd.data(), fd.size());
  std::memcpy(d.data(), ref_fd.data(), fd.size());
  int far_f = 0, far_d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    far_f += std::fabs(a[i] - b[i]) > 0.02 * std::max(std::fabs(b[i]), 1e-3f);
    far_d += std::fabs(c[i] - d[i]) > 0.02 * std::max(std::fabs(d[i]), 1e-3);
  }
  // Same rays and values as the -ov text test: nearly every value within 2%.
  EXPECT_LE(far_f, static_cast<int>(a.size() / 20));
  EXPECT_LE(far_d, static_cast<int>(c.size() / 20));
  // Ascii in, 4-byte RGBE out.
  std::string fac = rtrace("-h -u- " + kDirect + " -fac -ov", "materials_rays.txt");
  std::string ref_fac =
      radcl::test::read_file(radcl::test::data("results/materials_plain_rays_fac.bin"));
  ASSERT_EQ(fac.size(), ref_fac.size());
  int same_exponent = 0;
  for (std::size_t i = 0; i < fac.size(); i += 4)
    same_exponent += fac[i + 3] == ref_fac[i + 3];
  EXPECT_GE(same_exponent, static_cast<int>(fac.size() / 4 * 9 / 10));
}

TEST(GoldenRtraceOutput, HeaderWithoutDashH) {
  std::string out = rtrace("-u- " + kDirect + " -ov", "materials_rays.txt");
  std::string ref =
      radcl::test::read_file(radcl::test::data("results/materials_plain_rays_header.txt"));
  auto lines = [](const std::string& s) {
    std::vector<std::string> v;
    std::istringstream in(s);
    std::string l;
    while (std::getline(in, l) && !l.empty())
      v.push_back(l);
    return v;
  };
  auto a = lines(out), b = lines(ref);
  ASSERT_EQ(a.size(), b.size()) << out.substr(0, 400);
  EXPECT_EQ(a[0], "#?RADIANCE");
  EXPECT_EQ(a[1], b[1]); // the octree's own header line
  EXPECT_NE(a[2].find("rtrace -u- -ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1 -ov"), std::string::npos)
      << a[2];
  EXPECT_EQ(a[3].rfind("SOFTWARE= ", 0), 0u);
  EXPECT_EQ(a[4].rfind("CAPDATE= ", 0), 0u);
  EXPECT_EQ(a[5].rfind("GMT= ", 0), 0u);
  EXPECT_EQ(a[6], b[6]); // NCOMP=3
  EXPECT_EQ(a[7], b[7]); // FORMAT=ascii
}

TEST(GoldenRtraceOutput, BadInputIsFatal) {
  int rc = 0;
  std::string out;
  rc = run_command("cd " + radcl::test::data("scenes") + " && " + radcl::test::bin_dir() +
                       "/rtrace -oq materials_plain.oct < /dev/null",
                   &out);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("rtrace: fatal - unrecognized output option"), std::string::npos) << out;
  out.clear();
  rc = run_command(radcl::test::bin_dir() + "/rtrace -h no_such.oct < /dev/null", &out);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("rtrace: fatal - "), std::string::npos) << out;
}
