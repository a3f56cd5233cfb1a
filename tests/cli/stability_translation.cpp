// Issue 8, case 1: the reference office moved far from the origin (1e3, 1e5, 1e6 m along every
// axis) and in other units (scaled by 1e-3 and 1e3), sensors transformed likewise, gives the
// sensor values of the original. The test writes the transformed scene itself (xform's
// arithmetic on the office's polygons, cylinder and ring; materials and the sky unchanged)
// and runs the built rtrace on it with a fixed seed (-u-), so the same random numbers drive
// both runs: what remains is the renderer's own error.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iomanip>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "files.h"
#include "reference_data.h"
#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::run_command;

namespace {

struct Xform {
  double s = 1, t = 0; // p -> s p + (t, t, t)
  std::string name() const {
    std::ostringstream o;
    o << "s" << s << "_t" << t;
    return o.str();
  }
};

std::vector<std::string> words(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> w;
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line.substr(0, line.find('#')));
    for (std::string x; ls >> x;)
      w.push_back(x);
  }
  return w;
}

std::string num(double v) {
  std::ostringstream o;
  o << std::setprecision(17) << v;
  return o.str();
}

// The primitives of `file` with xform -s s -t t t t applied (the office has polygons, one
// cylinder and one ring).
std::string transformed(const fs::path& file, const Xform& x) {
  std::vector<std::string> w = words(file);
  std::ostringstream out;
  auto pt = [&](double v) { return num(x.s * v + x.t); };
  for (std::size_t i = 0; i + 2 < w.size();) {
    std::string mod = w[i], type = w[i + 1], name = w[i + 2];
    i += 3;
    out << mod << " " << type << " " << name << "\n";
    for (int part = 0; part < 2; ++part) { // string and integer arguments, unchanged
      std::size_t n = std::stoul(w[i]);
      for (std::size_t k = 0; k <= n; ++k)
        out << w[i + k] << " ";
      out << "\n";
      i += n + 1;
    }
    std::size_t n = std::stoul(w[i++]);
    std::vector<double> a(n);
    for (std::size_t k = 0; k < n; ++k)
      a[k] = std::stod(w[i + k]);
    i += n;
    out << n;
    if (type == "polygon") {
      for (double v : a)
        out << " " << pt(v);
    } else if (type == "cylinder") {
      for (int k = 0; k < 6; ++k)
        out << " " << pt(a[k]);
      out << " " << num(x.s * a[6]);
    } else if (type == "ring") {
      for (int k = 0; k < 3; ++k)
        out << " " << pt(a[k]);
      for (int k = 3; k < 6; ++k)
        out << " " << num(a[k]);
      out << " " << num(x.s * a[6]) << " " << num(x.s * a[7]);
    } else {
      ADD_FAILURE() << "no transform for " << type;
    }
    out << "\n";
  }
  return out.str();
}

class StabilityTranslation : public radcl::test::TempDir {
protected:
  // Writes the office transformed by x and its sensors; returns the scene file's name.
  std::string write_office(const Xform& x) {
    const fs::path src = radcl::test::data("scenes");
    std::string rad = x.name() + ".rad";
    std::ofstream f(dir / rad);
    f << radcl::test::read_file(src / "office_mat.rad") << transformed(src / "office_geom.rad", x)
      << transformed(src / "office_desk.rad", x)
      << radcl::test::read_file(src / "office_sky_clear.rad");
    std::ofstream p(dir / (x.name() + ".pts"));
    for (const auto& s : radcl::test::read_rays(src / "office_grid.pts"))
      p << num(x.s * s[0] + x.t) << " " << num(x.s * s[1] + x.t) << " " << num(x.s * s[2] + x.t)
        << " " << s[3] << " " << s[4] << " " << s[5] << "\n";
    return rad;
  }

  // rtrace's sensor values (3 per sensor) for the office transformed by x.
  std::vector<double> sensors(const Xform& x, const std::string& opts) {
    std::string rad = write_office(x), out = (dir / "out.txt").string(), log;
    std::string cmd = "cd " + dir.string() + " && " + radcl::test::bin_dir() +
                      "/rtrace -h -I -u- " + opts + " " + rad + " < " + x.name() + ".pts > " + out;
    EXPECT_EQ(run_command(cmd, &log), 0) << cmd << "\n" << log;
    std::vector<double> v;
    for (const auto& row : radcl::test::read_table(out))
      v.insert(v.end(), row.begin(), row.end());
    EXPECT_EQ(v.size(), 77u * 3) << cmd;
    for (double y : v)
      EXPECT_TRUE(std::isfinite(y)) << cmd;
    return v;
  }

  struct Diff {
    double max = 0, rms = 0, mean = 0;
  };
  // Relative differences of b from a over the sensors a sees lit (components above 1e-3 of
  // the largest; the others must stay as dark).
  static Diff compare(const std::vector<double>& a, const std::vector<double>& b) {
    Diff d;
    if (a.size() != b.size() || a.empty()) {
      ADD_FAILURE() << "sizes " << a.size() << " " << b.size();
      return d;
    }
    double top = 0;
    for (double v : a)
      top = std::max(top, v);
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (a[i] <= 1e-3 * top) {
        EXPECT_LE(b[i], 2e-3 * top) << "component " << i;
        continue;
      }
      double r = (b[i] - a[i]) / a[i];
      d.max = std::max(d.max, std::fabs(r));
      d.rms += r * r;
      d.mean += r;
      ++n;
    }
    d.rms = std::sqrt(d.rms / n);
    d.mean /= n;
    return d;
  }

  // Every transform against the untransformed office with the same options and seed.
  void expect_same(const std::vector<Xform>& xs, const std::string& opts, double max_rel) {
    std::vector<double> base = sensors({}, opts);
    for (const Xform& x : xs) {
      Diff d = compare(base, sensors(x, opts));
      EXPECT_LE(d.max, max_rel) << x.name() << " " << opts << ": rms " << d.rms << " mean "
                                << d.mean;
      RecordProperty(x.name() + " max", std::to_string(d.max));
    }
  }
};

const std::vector<Xform> kTranslations = {{1, 1e3}, {1, 1e5}, {1, 1e6}};
const std::vector<Xform> kScales = {{1e-3, 0}, {1e3, 0}};
const std::string kDirect = "-ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1";
const std::string kNoCache = "-ab 2 -aa 0 -ad 256 -as 64";
const std::string kCache = "-ab 2 -aa 0.15 -ad 512 -as 128 -ar 64";

} // namespace

// Direct light (the sun through the window) is deterministic: equal to float rounding.
// Measured: identical output for every transform.
TEST_F(StabilityTranslation, DirectTranslatedAndScaled) {
  std::vector<Xform> all = kTranslations;
  all.insert(all.end(), kScales.begin(), kScales.end());
  expect_same(all, kDirect, 1e-5);
}

// Two bounces without the cache: the same rays, so the same values (measured: identical).
TEST_F(StabilityTranslation, AmbientNoCacheTranslated) {
  expect_same(kTranslations, kNoCache, 0.005);
}

// Building the cache: records far from the origin were stored in float world coordinates and
// moved by their rounding (3.5% RMS at 1e5 m before the fix); measured now: identical.
TEST_F(StabilityTranslation, AmbientCacheTranslated) {
  expect_same(kTranslations, kCache, 0.005);
}

// Other units without the cache, measured at the surfaces (-i, rays down onto the floor and
// the desk, no -I meter): the geometry epsilon had an absolute 1e-6 m floor (up to 9% off in
// mm before the fix); measured now: 1.1e-6 at most.
TEST_F(StabilityTranslation, AmbientNoCacheScaledAtSurfaces) {
  auto run = [&](const Xform& x) {
    write_office(x);
    std::ofstream down(dir / (x.name() + ".dn"));
    for (const auto& s : radcl::test::read_rays(radcl::test::data("scenes/office_grid.pts")))
      down << num(x.s * s[0] + x.t) << " " << num(x.s * s[1] + x.t) << " " << num(x.s * s[2] + x.t)
           << " 0 0 -1\n";
    down.close();
    std::string out = (dir / "down.txt").string(), log;
    std::string cmd = "cd " + dir.string() + " && " + radcl::test::bin_dir() +
                      "/rtrace -h -i -u- " + kNoCache + " " + x.name() + ".rad < " + x.name() +
                      ".dn > " + out;
    EXPECT_EQ(run_command(cmd, &log), 0) << cmd << "\n" << log;
    std::vector<double> v;
    for (const auto& row : radcl::test::read_table(out))
      v.insert(v.end(), row.begin(), row.end());
    EXPECT_EQ(v.size(), 77u * 3);
    return v;
  };
  std::vector<double> base = run({});
  for (const Xform& x : kScales) {
    Diff d = compare(base, run(x));
    EXPECT_LE(d.max, 0.005) << x.name() << ": rms " << d.rms << " mean " << d.mean;
  }
}

// -I meters in mm: Radiance's fixed 1e-4 in front of the point is below the float resolution
// of points 5000 units from the centre (max 2.2%, RMS 0.24% before); the meter now sits at
// least four float steps out (Renderer::Impl::meter_offset). Measured: within 0.5%.
TEST_F(StabilityTranslation, AmbientNoCacheMillimetreSensors) {
  expect_same({{1e3, 0}}, kNoCache, 0.005);
}

// In km Radiance's fixed 1e-4 is 0.1 m above a 0.8 mm workplane (max 23%, RMS 5.4%); the
// meter now sits 1e-6 of the model's size out in models under 100 units across
// (render/pipeline/irradiance_meter.h).
TEST_F(StabilityTranslation, AmbientNoCacheKilometreSensors) {
  expect_same({{1e-3, 0}}, kNoCache, 0.005);
}

// The cache in mm: Radiance's record radii, (4/lambda)^(1/4) of the Hessian's eigenvalues,
// grow as the square root of the model's size, so in mm they fall under -ar's minimum radius,
// which is relative: the cache stays the metre office's within noise (measured: mean +0.02%,
// RMS 2.0%; two seeds of the metre office differ by 2.9% RMS, 0.4% in the mean).
TEST_F(StabilityTranslation, AmbientCacheMillimetreWithinNoise) {
  std::vector<double> base = sensors({}, kCache);
  Diff d = compare(base, sensors({1e3, 0}, kCache));
  EXPECT_LE(std::fabs(d.mean), 0.02);
  EXPECT_LE(d.rms, 0.06);
}

// Known gap: in km the same radii are 31.6 times larger against the model and reach -ar's
// maximum (0.2 of the cube): few, large records (measured: mean +18%, RMS 23%). Radii in the
// model's own unit pass (session 16: radii times sqrt(u) and the behind test's, the corral's
// and the sample cap's fixed lengths times u, with u = 1e-3: mean 0.00%, RMS 0.06%; u = 0.0017
// still passes, 0.017 does not), but the only length a scene offers is its size, and taking u
// from it (u = size / 100) slows every small model in metres by 2-4x for no accuracy (the
// luminaires room, 10 m across: 26.9 s instead of 7.5 s, mean error against the converged
// answer 1.22% instead of 1.23%). A local length (session 17: radii times sqrt(R / R0), R each
// record's harmonic mean hit distance) passes too, but costs either the office's accuracy
// (R0 = 1: 2.55% against 0.95%) or the luminaires room's time (R0 = 8: 29 s against 6 s).
// The km office at -ar 2048 (32 times the metre office's) is within these bounds (mean +1.1%,
// RMS 3.0%): the user's remedy. docs/differences.md.
TEST_F(StabilityTranslation, DISABLED_AmbientCacheKilometreWithinNoise) {
  std::vector<double> base = sensors({}, kCache);
  Diff d = compare(base, sensors({1e-3, 0}, kCache));
  EXPECT_LE(std::fabs(d.mean), 0.02);
  EXPECT_LE(d.rms, 0.06);
}

// The remedy docs/ambient.md gives users with a model in km: -ar about sqrt(1000) = 32 times
// the metre model's scales -ar's relative minimum and maximum radii down to meet the radii
// (measured: mean +1.1%, RMS 3.0% at -ar 2048 against the metre office at -ar 64).
TEST_F(StabilityTranslation, AmbientCacheKilometreWithArScaledWithinNoise) {
  std::vector<double> base = sensors({}, kCache);
  Diff d = compare(base, sensors({1e-3, 0}, kCache + " -ar 2048"));
  EXPECT_LE(std::fabs(d.mean), 0.02);
  EXPECT_LE(d.rms, 0.06);
}
