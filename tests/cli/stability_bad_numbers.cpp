// NaN, Inf and denormal numbers in rtrace's ray input and in scene files. Scene numbers that are
// not finite are fatal; rays holding one get an all-zero record (Radiance traces them to
// undefined results, and a NaN direction ends its input); nothing non-finite is ever written.
// Denormals are ordinary numbers.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "run_program.h"
#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::read_file;
using radcl::test::run_command;
using radcl::test::write_file;

namespace {

// Files of this process's runs, in one folder removed at exit.
fs::path temp(const std::string& name) {
  static const radcl::test::TempFolder dir("bad_numbers");
  return dir / name;
}

struct Result {
  int rc;
  std::string out, log;
};

// rtrace `opts` `scene` with standard input `input`.
Result rtrace(const std::string& opts, const std::string& scene, const std::string& input) {
  const radcl::test::ProgramRun r =
      radcl::test::Program("rtrace").input(input).run("-h " + opts + " " + scene);
  return {r.rc, r.out, r.err};
}

std::vector<double> words(const std::string& text) {
  std::istringstream s(text);
  std::vector<double> v;
  std::string w;
  while (s >> w)
    v.push_back(std::strtod(w.c_str(), nullptr));
  return v;
}

template <typename T> std::string binary(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

template <typename T> std::vector<T> unpack(const std::string& s) {
  std::vector<T> v(s.size() / sizeof(T));
  std::memcpy(v.data(), s.data(), v.size() * sizeof(T));
  return v;
}

template <typename T> void expect_finite(const std::vector<T>& v, const std::string& what) {
  for (std::size_t i = 0; i < v.size(); ++i)
    EXPECT_TRUE(std::isfinite(static_cast<double>(v[i]))) << what << " value " << i;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDenorm = 1e-310;

// A lit floor under the luminaires: the first ray reads a positive irradiance.
const std::vector<double> kGood = {2, 2, 0.5, 0, 0, 1};

} // namespace

// Words that are not Radiance reals end ascii input, as in Radiance (fgetword + isflt).
TEST(StabilityBadNumbers, AsciiNanWordEndsInput) {
  for (const char* bad : {"nan", "inf", "-inf", "NaN", "infinity"}) {
    Result r = rtrace("-ab 0 -I -ov", "luminaires.oct",
                      "2 2 0.5 0 0 1\n2 2 0.5 0 0 " + std::string(bad) + "\n2 2 0.5 0 0 1\n");
    EXPECT_EQ(r.rc, 0) << r.log;
    auto v = words(r.out);
    ASSERT_EQ(v.size(), 3u) << bad << ": " << r.out;
    EXPECT_GT(v[0], 0);
  }
}

// Reals that overflow to Inf ("1e999") are read by atof as in Radiance; such rays give a
// record of zeros in every field, counted as a ray, and the rays after them go on normally.
TEST(StabilityBadNumbers, AsciiOverflowGivesZeroRecord) {
  Result r = rtrace("-ab 0 -I -ovodpn", "luminaires.oct",
                    "2 2 0.5 0 0 1\n1e999 2 0.5 0 0 1\n2 2 0.5 0 0 -1e999\n2 2 0.5 0 0 1\n");
  EXPECT_EQ(r.rc, 0) << r.log;
  EXPECT_NE(r.log.find("rtrace: warning - "), std::string::npos) << r.log;
  auto v = words(r.out);
  ASSERT_EQ(v.size(), 4u * 15) << r.out;
  expect_finite(v, "ascii");
  for (int k = 15; k < 45; ++k)
    EXPECT_EQ(v[k], 0.0) << "field " << k;
  for (int k = 0; k < 15; ++k)
    EXPECT_EQ(v[k], v[45 + k]) << "field " << k << " of the last ray";
  EXPECT_GT(v[0], 0);
}

// Binary float and double input: NaN and Inf in origin or direction give zero records; the
// -x count includes them.
TEST(StabilityBadNumbers, BinaryNanInfGiveZeroRecords) {
  std::vector<std::vector<double>> rays = {kGood,
                                           {kNaN, 2, 0.5, 0, 0, 1},
                                           {2, 2, 0.5, 0, 0, kNaN},
                                           {2, kInf, 0.5, 0, 0, 1},
                                           {2, 2, 0.5, -kInf, 0, 1},
                                           {2, 2, 0.5, kNaN, kNaN, kNaN},
                                           kGood};
  std::vector<double> d;
  std::vector<float> f;
  for (const auto& ray : rays)
    for (double x : ray) {
      d.push_back(x);
      f.push_back(static_cast<float>(x));
    }
  for (char fmt : {'f', 'd'}) {
    std::string opts = std::string("-ab 0 -I -x 7 -y 0 -f") + fmt + fmt + " -ovodpn";
    Result r = rtrace(opts, "luminaires.oct", fmt == 'f' ? binary(f) : binary(d));
    EXPECT_EQ(r.rc, 0) << r.log;
    std::vector<double> v;
    if (fmt == 'f')
      for (float x : unpack<float>(r.out))
        v.push_back(x);
    else
      v = unpack<double>(r.out);
    ASSERT_EQ(v.size(), 7u * 15) << fmt;
    expect_finite(v, std::string(1, fmt));
    for (int k = 15; k < 6 * 15; ++k)
      EXPECT_EQ(v[k], 0.0) << fmt << " field " << k;
    EXPECT_GT(v[0], 0) << fmt;
    for (int k = 0; k < 15; ++k)
      EXPECT_EQ(v[k], v[6 * 15 + k]) << fmt << " field " << k;
  }
}

// Shading paths too (-ab 1, not -I; a ray into the sky): nothing non-finite.
TEST(StabilityBadNumbers, ShadedBadRaysStayFinite) {
  std::vector<double> d = {kNaN, kNaN, kNaN, 0, 0, 1,   2, 2, 0.5,
                           kInf, kInf, kInf, 2, 2, 0.5, 0, 0, -1};
  Result r = rtrace("-ab 1 -ad 16 -fdd -ov", "luminaires.oct", binary(d));
  EXPECT_EQ(r.rc, 0) << r.log;
  auto v = unpack<double>(r.out);
  ASSERT_EQ(v.size(), 9u);
  expect_finite(v, "shaded");
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(v[k], 0.0);
}

// Denormal numbers are ordinary: in an origin they move nothing visible; a direction whose
// squared length underflows is a zero vector (a flush request, as in Radiance); denormal parts
// of a real direction do nothing.
TEST(StabilityBadNumbers, DenormalsWorkNormally) {
  std::vector<double> d = {
      2, 2, 0.5,     0,       0,       1, // reference
      2, 2, 0.5,     kDenorm, kDenorm, 1, // denormal parts of a real direction
      2, 2, kDenorm, 0,       0,       1, // denormal origin ...
      2, 2, 0,       0,       0,       1, // ... reads as zero does
      2, 2, 0.5,     kDenorm, 0,       0, // squared length underflows: flush request
  };
  Result r = rtrace("-ab 0 -I -fdd -ov", "luminaires.oct", binary(d));
  EXPECT_EQ(r.rc, 0) << r.log;
  auto v = unpack<double>(r.out);
  ASSERT_EQ(v.size(), 15u);
  expect_finite(v, "denormal");
  EXPECT_GT(v[0], 0);
  EXPECT_GT(v[6], 0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(v[3 + k], v[k]) << "denormal direction parts";
    EXPECT_EQ(v[6 + k], v[9 + k]) << "denormal origin";
    EXPECT_EQ(v[12 + k], 0.0) << "underflowing direction";
  }
}

namespace {

const char* kRoom = "void light lamp 0 0 3 10 10 10\n"
                    "lamp sphere bulb 0 0 4 0 0 2 0.2\n"
                    "void plastic grey 0 0 5 .5 .5 .5 0 0\n";

// rtrace on a scene of kRoom plus `extra`: a fatal error naming the object, and no output.
void expect_fatal(const std::string& extra, const std::string& object) {
  fs::path rad = temp("scene.rad");
  write_file(rad, std::string(kRoom) + extra);
  Result r = rtrace("-ab 0 -ov", rad.string(), "0 0 0 0 0 1\n");
  fs::remove(rad);
  EXPECT_NE(r.rc, 0) << extra;
  EXPECT_NE(r.log.find("rtrace: fatal - "), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("bad arguments for " + object), std::string::npos) << r.log;
  EXPECT_EQ(r.out, "") << extra;
}

} // namespace

TEST(StabilityBadNumbers, SceneNanInfAreFatal) {
  for (const char* v : {"nan", "inf", "-inf", "1e999", "-1e400"}) {
    std::string x(v);
    expect_fatal("grey sphere ball 0 0 4 1 1 0 " + x + "\n", "sphere \"ball\"");
    expect_fatal("grey sphere ball 0 0 4 " + x + " 1 0 0.5\n", "sphere \"ball\"");
    expect_fatal("grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 " + x + " 0 -5 5 0\n",
                 "polygon \"floor\"");
    expect_fatal("void light hot 0 0 3 " + x + " 1 1\n", "light \"hot\"");
    expect_fatal("void plastic odd 0 0 5 .5 .5 .5 " + x + " 0\n", "plastic \"odd\"");
  }
}

// Denormal scene numbers are accepted and behave as the numbers they are.
TEST(StabilityBadNumbers, SceneDenormalsWork) {
  auto floor = [](const std::string& z) {
    fs::path rad = temp("floor.rad");
    write_file(rad, std::string(kRoom) + "grey polygon floor 0 0 12 -5 -5 " + z + " 5 -5 " + z +
                        " 5 5 " + z + " -5 5 " + z + "\n");
    Result r = rtrace("-ab 0 -ov", rad.string(), "0 0 1 0 0 -1\n");
    fs::remove(rad);
    EXPECT_EQ(r.rc, 0) << r.log;
    return words(r.out);
  };
  auto zero = floor("0"), denorm = floor("1e-310");
  ASSERT_EQ(zero.size(), 3u);
  ASSERT_EQ(denorm.size(), 3u);
  EXPECT_GT(zero[0], 0);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(denorm[k], zero[k], 1e-6 * zero[k]);
}

// Option values that overflow to Inf ("1e999", which Radiance's atof takes) are command line
// errors, as "nan" and "inf" words are: an ambient value or a view point of Inf would reach
// every output.
TEST(StabilityBadNumbers, OverflowingOptionValuesAreCommandLineErrors) {
  for (const std::string opt : {"-av 1e999 1 1", "-lw 1e999", "-dj -1e400"}) {
    Result r = rtrace("-ab 1 " + opt, "luminaires.oct", "2 2 0.5 0 0 1\n");
    EXPECT_NE(r.rc, 0) << opt;
    EXPECT_NE(r.log.find("rtrace: fatal - command line error at '" + opt.substr(0, 3) + "'"),
              std::string::npos)
        << r.log;
    EXPECT_EQ(r.out, "") << opt;
  }
  fs::path pic = temp("view.hdr"), err = temp("view.err");
  for (const std::string view : {"-vp 1e999 0 0", "-vd 1e999 0 0", "-vu 0 0 -1e999", "-vs 1e999"}) {
    int rc = run_command("(cd " + radcl::test::data("scenes") + " && " + radcl::test::bin_dir() +
                         "/rpict -x 8 -y 8 -ab 0 -vf luminaires.vf " + view + " luminaires.oct > " +
                         pic.string() + " 2> " + err.string() + ")");
    EXPECT_NE(rc, 0) << view;
    EXPECT_NE(
        read_file(err).find("rpict: fatal - command line error at '" + view.substr(0, 3) + "'"),
        std::string::npos)
        << view << ": " << read_file(err);
  }
  fs::remove(pic);
  fs::remove(err);
}

// Instance and mesh transforms: a number that overflows, or a product that does (-s 1e300
// -s 1e300), is a bad transform as "nan" is. A scale that puts the scene's rays past what the
// float traversal holds inside the instance (Embree's limit is 1.8e18; its assertion ended the
// program) is a bad transform too, with the reason; ordinary small scales work. (The grey
// modifier shows the mesh, whose own materials this scene lacks.)
TEST(StabilityBadNumbers, NonFiniteAndUntraceableTransformsAreFatal) {
  const std::string chair = radcl::test::data("scenes") + "/chair.oct";
  const std::string mesh = radcl::test::data("scenes") + "/octa.rtm";
  auto run = [&](const std::string& type, const std::string& file, const std::string& xf) {
    fs::path rad = temp("xf.rad");
    const int n = 1 + static_cast<int>(std::count(xf.begin(), xf.end(), ' ')) + 1;
    write_file(rad, std::string(kRoom) + "grey " + type + " c " + std::to_string(n) + " " + file +
                        " " + xf + "\n0\n0\n");
    Result r = rtrace("-ab 0 -ov", rad.string(), "0 -5 0.5 0 1 0\n");
    fs::remove(rad);
    return r;
  };
  for (const std::string& type : {std::string("instance"), std::string("mesh")}) {
    const std::string& file = type == "instance" ? chair : mesh;
    for (const char* xf : {"-s 1e999", "-t 1e999 0 0", "-rx -1e999", "-s 1e300 -s 1e300",
                           "-s 1e-200 -s 1e-200", "-s 1e-30", "-s 1e-320"}) {
      Result r = run(type, file, xf);
      EXPECT_NE(r.rc, 0) << type << " " << xf;
      EXPECT_NE(r.log.find("rtrace: fatal - "), std::string::npos) << r.log;
      EXPECT_NE(r.log.find("bad transform for " + type + " \"c\""), std::string::npos)
          << type << " " << xf << ": " << r.log;
      EXPECT_EQ(r.out, "") << type << " " << xf;
    }
    for (const char* xf : {"-s 1e-6", "-s 1e6 -t 0 1e7 0"}) {
      Result r = run(type, file, xf);
      EXPECT_EQ(r.rc, 0) << type << " " << xf << ": " << r.log;
      auto v = words(r.out);
      ASSERT_EQ(v.size(), 3u) << r.out;
      expect_finite(v, type + " " + xf);
    }
  }
}

// Ray origins far outside the scene start the traversal where the ray meets the scene's
// bounding sphere: a view 1e12 away hits a 1 m ball at the right distance with the value a
// near ray gets; origins 1e19 and 1e30 away stay finite (Embree's float traversal had ended the
// program past 1.8e18), one 1e300 away, which double cannot bring to the scene, misses.
TEST(StabilityBadNumbers, FarRayOriginsStayFinite) {
  fs::path rad = temp("far.rad");
  write_file(rad, "void light lamp 0 0 3 10 10 10\n"
                  "lamp sphere bulb 0 0 4 0 -3 3 0.2\n"
                  "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                  "grey sphere ball 0 0 4 0 0 0 1\n");
  std::string in;
  for (const char* d : {"5", "1e6", "1e12", "1e15", "1e19", "1e30", "1e300"})
    in += std::string("0 -") + d + " 0 0 1 0\n";
  Result r = rtrace("-ab 0 -ovl", rad.string(), in);
  fs::remove(rad);
  EXPECT_EQ(r.rc, 0) << r.log;
  auto v = words(r.out);
  ASSERT_EQ(v.size(), 7u * 4) << r.out;
  expect_finite(v, "far origins");
  const double near = v[0];
  EXPECT_GT(near, 0);
  EXPECT_NEAR(v[3], 4, 1e-6);
  const double dist[] = {5, 1e6, 1e12, 1e15};
  for (int i = 1; i < 4; ++i) {
    EXPECT_NEAR(v[4 * i], near, 1e-5 * near) << dist[i];
    EXPECT_NEAR(v[4 * i + 3], dist[i] - 1, 1e-6 * dist[i]) << dist[i];
  }
  // 1e19 and 1e30: as exact as double places the entry point, hit or miss; 1e300: beyond.
  EXPECT_EQ(v[4 * 6], 0.0);
}
