// rtrace's output bytes against Radiance 5.4a's (tests/data/results/materials_*_rays_*): text
// records are parsed into RayOutput values and written back; binary outputs are compared with
// what the formatter makes of the same values.
#include "radcl/options/ray_io.h"

#include "files.h"
#include "test_env.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>

using namespace radcl::options;

namespace {

// A stored Radiance output (tests/data/results), which must be there.
std::string stored(const std::string& name) {
  const std::string path = radcl::test::data("results/" + name);
  EXPECT_TRUE(std::filesystem::exists(path)) << name;
  return radcl::test::read_file(path);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    lines.push_back(l);
  return lines;
}

// Reads one ascii record (TAB-separated fields, as written for `letters`) into a RayOutput.
RayOutput parse_record(const std::string& line, std::string_view letters) {
  std::vector<std::string> f;
  std::size_t p = 0;
  while (p < line.size()) {
    std::size_t t = line.find('\t', p);
    EXPECT_NE(t, std::string::npos) << "every field ends with a TAB";
    f.push_back(line.substr(p, t - p));
    p = t + 1;
  }
  std::size_t k = 0;
  RayOutput r;
  auto real = [&]() { return std::strtod(f.at(k++).c_str(), nullptr); };
  auto vec = [&](Vec3& v) {
    for (double& c : v)
      c = real();
  };
  for (char c : letters) {
    switch (c) {
    case 'o':
      vec(r.origin);
      break;
    case 'd':
      vec(r.direction);
      break;
    case 'v':
      vec(r.value);
      break;
    case 'V':
      vec(r.contribution);
      break;
    case 'w':
      r.weight = real();
      break;
    case 'W':
      vec(r.coefficient);
      break;
    case 'l':
      r.effective_length = real();
      break;
    case 'L':
      r.first_length = real();
      break;
    case 'c':
      r.u = real(), r.v = real();
      break;
    case 'p':
      vec(r.point);
      break;
    case 'n':
      vec(r.normal);
      break;
    case 'N':
      vec(r.unperturbed_normal);
      break;
    case 's':
      r.surface = f.at(k++);
      break;
    case 'm':
      r.modifier = f.at(k++);
      break;
    case 'M':
      r.material = f.at(k++);
      break;
    case 'r':
      vec(r.mirrored);
      break;
    case 'x':
      vec(r.unmirrored);
      break;
    case 'R':
      r.mirrored_length = real();
      break;
    case 'X':
      r.unmirrored_length = real();
      break;
    }
  }
  EXPECT_EQ(k, f.size()) << line;
  return r;
}

std::vector<RayOutput> parse_file(const std::string& name, std::string_view letters) {
  std::vector<RayOutput> rays;
  for (const std::string& l : lines_of(stored(name)))
    rays.push_back(parse_record(l, letters));
  return rays;
}

std::string write_all(const std::vector<RayOutput>& rays, std::string_view letters, char fmt) {
  std::string out;
  for (const RayOutput& r : rays)
    append_record(out, letters, r, fmt);
  return out;
}

struct TextCase {
  const char* file;
  const char* letters;
};

} // namespace

TEST(GoldenRayOutput, AsciiRecordsRoundTripByteForByte) {
  const TextCase cases[] = {
      {"materials_plain_rays_oodvVwWlLcpnNsmMrxRX.txt", "oodvVwWlLcpnNsmMrxRX"},
      {"materials_rays_oodvVwWlLcpnNsmMrxRX.txt", "oodvVwWlLcpnNsmMrxRX"},
      {"materials_plain_rays_odv.txt", "odv"},
      {"materials_rays_odv.txt", "odv"},
      {"materials_plain_rays_v.txt", "v"},
      {"materials_plain_rays_i_v.txt", "v"},
      {"materials_plain_rays_aa0.txt", "v"},
      {"materials_rays_v.txt", "v"},
      {"materials_rays_i_v.txt", "v"},
  };
  for (const TextCase& c : cases) {
    std::vector<RayOutput> rays = parse_file(c.file, c.letters);
    EXPECT_EQ(rays.size(), 160u) << c.file;
    EXPECT_EQ(write_all(rays, c.letters, 'a'), stored(c.file)) << c.file;
  }
}

TEST(GoldenRayOutput, NamesAndMarkerInBinaryFormats) {
  RayOutput r;
  r.value = {1, 2, 3};
  r.surface = "floor";
  std::string out;
  append_record(out, "s~vM", r, 'f');
  float v[3] = {1, 2, 3};
  EXPECT_EQ(out, "floor\t~\t" + std::string(reinterpret_cast<char*>(v), 12) + "*\t");
  out.clear();
  append_record(out, "w", r, 'd', 2); // trace-mode indentation comes first
  double w = 1;
  EXPECT_EQ(out, "\t\t" + std::string(reinterpret_cast<char*>(&w), 8));
  out.clear();
  append_record(out, "Lv", r, 'a', 1);
  EXPECT_EQ(out, "\t1.000000e+10\t1.000000e+00\t2.000000e+00\t3.000000e+00\t\n");
}

// Each -o letter's text against the long reference: the values that say what a ray hit.
TEST(GoldenRayOutput, NoHitRecordMatchesEmptyRay) {
  std::vector<RayOutput> rays =
      parse_file("materials_plain_rays_oodvVwWlLcpnNsmMrxRX.txt", "oodvVwWlLcpnNsmMrxRX");
  // The first ray sees only the glow sky (a distant source): its geometric fields are those
  // of an empty ray, apart from the name fields and normals sourcehit() sets.
  RayOutput e = RayOutput::empty(rays[0].origin, rays[0].direction);
  EXPECT_EQ(rays[0].first_length, e.first_length);
  EXPECT_EQ(rays[0].point, e.point);
  EXPECT_EQ(rays[0].u, 0.0);
  std::string a, b;
  append_record(a, "oLcpRX", rays[0], 'a');
  append_record(b, "oLcpRX", e, 'a');
  EXPECT_EQ(a, b);
  std::string bogus;
  append_record(bogus, "vwsmMN", RayOutput::empty({1, 2, 3}, {0, 0, 1}), 'a');
  EXPECT_EQ(bogus, "0.000000e+00\t0.000000e+00\t0.000000e+00\t1.000000e+00\t*\t*\t*\t"
                   "0.000000e+00\t0.000000e+00\t0.000000e+00\t\n");
}

TEST(GoldenRayOutput, UnmirroredIsValueMinusMirrored) {
  // x = v - r in float, as Radiance computes it: check against every reference record.
  for (const char* file : {"materials_plain_rays_oodvVwWlLcpnNsmMrxRX.txt",
                           "materials_rays_oodvVwWlLcpnNsmMrxRX.txt"}) {
    for (RayOutput r : parse_file(file, "oodvVwWlLcpnNsmMrxRX")) {
      Vec3 ref = r.unmirrored;
      r.derive_unmirrored();
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(r.unmirrored[k], ref[k], 1e-6 * std::abs(ref[k]) + 1e-6 * std::abs(r.value[k]))
            << file;
    }
  }
}

// -fac: RGBE bytes follow from the printed values exactly (setcolr truncates, and 7
// significant digits are enough to decide every byte here).
TEST(GoldenRayOutput, RgbeMatchesRadiance) {
  std::vector<RayOutput> rays = parse_file("materials_plain_rays_v.txt", "v");
  const std::string ref = stored("materials_plain_rays_fac.bin");
  ASSERT_EQ(ref.size(), 160u * 4);
  std::string out = write_all(rays, "v", 'c');
  EXPECT_EQ(out, ref);
  EXPECT_EQ(to_rgbe(0, 0, 0), (std::array<unsigned char, 4>{0, 0, 0, 0}));
  EXPECT_EQ(to_rgbe(1, 0.5, -1), (std::array<unsigned char, 4>{128, 64, 0, 129}));
  EXPECT_EQ(stored("materials_rays_fac.bin").size(), 160u * 4);
}

// -ff/-fd: Radiance made these from the binary camera rays (materials_rays.f32/.f64), which
// carry more digits than materials_rays.txt, so a few rays near edges land elsewhere; the
// rest agree to the text's precision. The bytes of the formatter are checked by round trip.
TEST(GoldenRayOutput, FloatAndDoubleMatchRadiance) {
  std::vector<RayOutput> rays = parse_file("materials_plain_rays_v.txt", "v");
  const std::string ref_f = stored("materials_plain_rays_ff.f32");
  const std::string ref_d = stored("materials_plain_rays_fd.f64");
  std::string out_f = write_all(rays, "v", 'f');
  std::string out_d = write_all(rays, "v", 'd');
  ASSERT_EQ(out_f.size(), ref_f.size());
  ASSERT_EQ(out_d.size(), ref_d.size());
  std::vector<float> mf(480), rf(480);
  std::vector<double> md(480), rd(480);
  std::memcpy(mf.data(), out_f.data(), out_f.size());
  std::memcpy(rf.data(), ref_f.data(), ref_f.size());
  std::memcpy(md.data(), out_d.data(), out_d.size());
  std::memcpy(rd.data(), ref_d.data(), ref_d.size());
  int close_f = 0, close_d = 0;
  for (int k = 0; k < 480; ++k) {
    const double t = rays[k / 3].value[k % 3];
    EXPECT_EQ(md[k], t); // doubles are written unchanged
    EXPECT_EQ(mf[k], static_cast<float>(t));
    EXPECT_NEAR(rf[k], t, 1e-4 * std::abs(t)) << k;
    EXPECT_NEAR(rd[k], t, 1e-4 * std::abs(t)) << k;
    close_f += std::abs(rf[k] - t) <= 0.51e-6 * std::abs(t) + 1e-30;
    close_d += std::abs(rd[k] - t) <= 0.51e-6 * std::abs(t) + 1e-30;
  }
  EXPECT_GE(close_f, 400);
  EXPECT_GE(close_d, 400);

  // Round trip: Radiance's binary values through RayOutput come back as the same bytes.
  auto from_binary = [](const auto& vals) {
    std::vector<RayOutput> rs(160);
    for (int k = 0; k < 480; ++k)
      rs[k / 3].value[k % 3] = vals[k];
    return rs;
  };
  EXPECT_EQ(write_all(from_binary(rf), "v", 'f'), ref_f);
  EXPECT_EQ(write_all(from_binary(rd), "v", 'd'), ref_d);
}

TEST(GoldenRayOutput, HeaderMatchesRadiance) {
  setenv("TZ", "UTC", 1); // the reference machine's clock was UTC (CAPDATE equals GMT)
  tzset();
  std::tm tm{};
  tm.tm_year = 2026 - 1900, tm.tm_mon = 10, tm.tm_mday = 22;
  tm.tm_hour = 2, tm.tm_min = 45, tm.tm_sec = 3;
  RtraceHeader h;
  h.octree_lines = {"#?RADIANCE", "oconv materials_plain.rad", "FORMAT=Radiance_octree"};
  h.command = {"rtrace", "-ab", "0", "-dj", "0", "-ds", "0.02", "-dt", "0", "-dc", "1", "-ov"};
  h.software = "RADIANCE 5.4a 2026-11-22 LBNL (5.2.Unknown)";
  h.time = timegm(&tm);
  h.ncomp = parse_output_spec("v").ncomp;
  h.out_format = 'a';
  std::string ref = stored("materials_plain_rays_header.txt");
  std::string expected = ref.substr(0, ref.find("\n\n") + 2);
  EXPECT_EQ(format_rtrace_header(h), expected);
  // Records follow the header.
  std::vector<std::string> ref_lines = lines_of(ref);
  RayOutput r = parse_record(ref_lines[9] + "", "v");
  std::string rec;
  append_record(rec, "v", r, 'a');
  EXPECT_EQ(rec, ref_lines[9] + "\n");

  h.out_format = 'f';
  h.ncomp = 0;
  h.command = {"/usr/bin/rtrace", "-e", "my log", "-oit's"};
  std::string s = format_rtrace_header(h);
  const char* be = "BigEndian=0\nFORMAT=float\n\n";
  EXPECT_NE(s.find(std::string("/usr/bin/rtrace -e \"my log\" \"-oit's\"\nSOFTWARE=")),
            std::string::npos)
      << s;
  EXPECT_EQ(s.substr(s.size() - std::strlen(be)), be);
  EXPECT_EQ(s.find("NCOMP"), std::string::npos);
  h.out_format = 'c';
  EXPECT_NE(format_rtrace_header(h).find("\nFORMAT=32-bit_rle_rgbe\n\n"), std::string::npos);
  EXPECT_EQ(format_resolution(16, 12), "-Y 12 +X 16\n");
}
