// gensky and gendaylit options beyond the reference cases: time formats and zones, years,
// defaults, errors, and gendaylit's input modes. Checked against each other and against
// Radiance's documented behaviour (the golden test covers the printed numbers).
#include "radcl/sky/program.h"

#include <gtest/gtest.h>

#include <sstream>

namespace rs = radcl::sky;

namespace {
rs::ProgramResult gensky(const std::string& args) {
  std::vector<std::string> argv{"gensky"};
  std::istringstream in(args);
  for (std::string w; in >> w;)
    argv.push_back(w);
  return rs::run_gensky(argv);
}
rs::ProgramResult gendaylit(const std::string& args) {
  std::vector<std::string> argv{"gendaylit"};
  std::istringstream in(args);
  for (std::string w; in >> w;)
    argv.push_back(w);
  return rs::run_gendaylit(argv);
}
// Output without its first line (the echoed command line).
std::string body(const std::string& out) {
  return out.substr(out.find('\n') + 1);
}
} // namespace

TEST(SkyOptions, CommandLineQuoting) {
  EXPECT_EQ(rs::format_command_line({"gensky", "3", "a b", "it's", "'x'"}),
            "gensky 3 \"a b\" \"it's\" 'x'\n");
}

TEST(SkyOptions, TimeZoneSetsMeridianAndOverridesM) {
  const auto zone = gensky("3 21 12EST -a 40 -o 75 -m 60");
  const auto merid = gensky("3 21 12 -a 40 -o 75 -m 75");
  EXPECT_EQ(zone.status, 0);
  EXPECT_EQ(body(zone.out), body(merid.out));
  EXPECT_EQ(body(gensky("3 21 12cest -a -10 -o -30").out),
            body(gensky("3 21 12 -a -10 -o -30 -m -30").out));
}

TEST(SkyOptions, HourFormats) {
  EXPECT_EQ(body(gensky("3 21 12:30 -a 40").out), body(gensky("3 21 12.5 -a 40").out));
  const auto solar = gensky("3 21 +12 -a 40 -o 75 -m 0");
  EXPECT_NE(solar.out.find("# Local solar time: 12.00\n"), std::string::npos);
  EXPECT_EQ(solar.err, ""); // no meridian warning for solar time
  const auto bad = gensky("3 21 +12EST");
  EXPECT_EQ(bad.status, 1);
  EXPECT_EQ(bad.err, "gensky: bad time format: +12EST\n");
  const auto unknown = gensky("3 21 12XST");
  EXPECT_EQ(unknown.status, 1);
  EXPECT_EQ(
      unknown.err.rfind("gensky: unknown time zone: XST\nKnown time zones:\n\tYST YDT PST", 0), 0u);
}

TEST(SkyOptions, Warnings) {
  const auto far = gensky("6 21 12 -o 10");
  EXPECT_EQ(far.err, "gensky: warning - -7.3 hours btwn. standard meridian and longitude\n");
  const auto year = gensky("6 21 12 -y 1900");
  EXPECT_EQ(year.err, "gensky: warning - year should be in range 1950-2050\n");
  const auto high = gensky("-ang 89 0 +s");
  EXPECT_EQ(high.err,
            "gensky: warning - sun too close to zenith, reducing altitude to 87 degrees\n");
  EXPECT_NE(high.out.find("# warning - sun too close to zenith"), std::string::npos);
  EXPECT_EQ(gensky("-ang 89 0 -c").err, ""); // overcast skies keep the altitude
}

TEST(SkyOptions, YearUsesAlmanacAlgorithm) {
  const auto r = gensky("6 21 12 -y 2003 -a 40 -o 105 -m 105");
  EXPECT_EQ(r.status, 0);
  // 21 June 2003, noon MST at 105 W: declination 23.44, equation of time -1.6 min.
  EXPECT_NE(r.out.find("# Local solar time: 11.97\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("# Solar altitude and azimuth: 73.4 "), std::string::npos) << r.out;
}

TEST(SkyOptions, DefaultsAndUsage) {
  EXPECT_EQ(gensky("-defaults").out, "+s\t\t\t\t# Sunny sky with sun\n"
                                     "-g 0.200000\t\t\t# Ground plane reflectance\n"
                                     "-t 2.450000\t\t\t# Atmospheric turbidity\n"
                                     "-a 37.815214\t\t\t# Site latitude (degrees)\n"
                                     "-o 122.040010\t\t\t# Site longitude (degrees)\n"
                                     "-m 120.000000\t\t\t# Standard meridian (degrees)\n");
  const auto bad = gensky("13 1 12");
  EXPECT_EQ(bad.status, 1);
  EXPECT_EQ(bad.err, "gensky: Use error - bad month\n"
                     "Usage: gensky month day hour [options]\n"
                     "   Or: gensky -ang altitude azimuth [options]\n"
                     "   Or: gensky -defaults\n");
  EXPECT_EQ(gensky("3 21 12 -q").err.rfind("gensky: Use error - unknown option: -q\n", 0), 0u);
  EXPECT_EQ(gensky("3 21 12 -t").status, 1); // missing value: a use error, not a crash
  EXPECT_EQ(gendaylit("3 21 12 -W 100").status, 1);
  EXPECT_EQ(gendaylit("3 21 25 -W 100 100").err.rfind("gendaylit: Use error - bad hour\n\n", 0),
            0u);
}

TEST(SkyOptions, GenskyIrradianceInputs) {
  // -B: zenith radiance from horizontal diffuse irradiance; -R: sun from horizontal direct.
  const auto r = gensky("-ang 30 0 +s -B 100 -R 300");
  EXPECT_NE(r.out.find("# Ground ambient level: 31.8\n"), std::string::npos) << r.out; // 100/pi
  // Ls = 300 / (6e-5 * sin 30 deg) = 1e7
  EXPECT_NE(r.out.find("3 1.00e+07 1.00e+07 1.00e+07\n"), std::string::npos) << r.out;
  EXPECT_EQ(gensky("-ang 30 0 +s -r 0").out.find("void light solar"), std::string::npos);
}

TEST(SkyOptions, GendaylitInputModes) {
  // -P: the Perez parameters directly.
  const auto p = gendaylit("6 21 12 -a 40 -o 75 -m 75 -P 3 0.25");
  EXPECT_EQ(p.status, 0);
  EXPECT_NE(p.out.find("# epsilon, delta, atmospheric precipitable water content : 3.0000 "
                       "0.2500 2.0000 \n"),
            std::string::npos);
  // -E: the Erbs split of the global irradiance, announced in two comment lines.
  const auto e = gendaylit("6 21 12 -a 40 -o 75 -m 75 -E 700");
  EXPECT_NE(e.out.find("# erbs_s0, erbs_kt, irr_dir_h, irr_diff: 1267.694 0.552 317.753 "
                       "382.247\n# WARNING: the -E option is only recommended for a rough "
                       "estimation!\n# Local solar time"),
            std::string::npos)
      << e.out;
  // -O other than 0, 1, 2 is refused after the header.
  const auto o = gendaylit("6 21 12 -a 40 -o 75 -m 75 -W 500 100 -O 3");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "Wrong output specification.\n");
  // -s: no sun description, and (unlike gensky) no sun term in the ground radiance.
  const auto with = gendaylit("6 21 12 -W 500 100"), without = gendaylit("6 21 12 -W 500 100 -s");
  EXPECT_EQ(without.out.find("void light solar"), std::string::npos);
  EXPECT_NE(with.out.find("\n10 2.470e+01 2.200e+01 -0.965552 "), std::string::npos) << with.out;
  EXPECT_NE(without.out.find("\n10 2.470e+01 3.985e+00 -0.965552 "), std::string::npos);
}

TEST(SkyOptions, GendaylitErrorSkies) {
  const auto night = gendaylit("6 21 22 -W 100 100");
  EXPECT_EQ(night.status, 0);
  EXPECT_EQ(night.err,
            "Warning: sun altitude below zero at time step 6 21 22.00, printing error sky\n");
  EXPECT_NE(night.out.find("10 0.00 0.00  0.000 0.000 0.000 0.000 0.000  "), std::string::npos);
  EXPECT_EQ(gendaylit("6 21 22 -W 100 100 -w").err, ""); // -w: no warnings
  // -i: near sunset the sun is placed in the part of the interval it is up.
  const auto late = gendaylit("6 21 19.9 -W 100 100 -i 60");
  EXPECT_EQ(late.err, "Solar position corrected at time step 6 21 19.900\n");
  EXPECT_EQ(gendaylit("6 21 20.5 -W 100 100 -i 60").err,
            "Warning: sun position too low, printing error sky at 6 21 20.500\n");
}

TEST(SkyOptions, GendaylitColourOutput) {
  const auto clear = gendaylit("6 21 12 -W 800 80 -C");
  EXPECT_NE(clear.out.find("4 skybright_r skybright_g skybright_b perezlum_c.cal\n0\n22 "),
            std::string::npos)
      << clear.out;
  const auto inter = gendaylit("6 21 12 -W 300 150 -C"); // intermediate: no colour model
  EXPECT_NE(inter.err.find("\twarning: no color output ! \n"), std::string::npos);
  EXPECT_NE(inter.out.find("2 skybright perezlum.cal\n"), std::string::npos);
}
