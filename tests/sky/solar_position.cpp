// Solar position against published values.
#include "radcl/sky/solar_position.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rs = radcl::sky;

namespace {
constexpr double kDeg = rs::kDeg;
}

TEST(SolarPosition, DayOfYear) {
  EXPECT_EQ(rs::day_of_year(1, 1), 1);
  EXPECT_EQ(rs::day_of_year(3, 21), 80);
  EXPECT_EQ(rs::day_of_year(12, 31), 365);
}

// Declination at the solstices (Astronomical Almanac: +-23.44 deg). Near the equinoxes the
// IES fit (zero on day 81, 22 March, and a 365-day sine) runs one to two days late, about 1 deg
// of declination, which gensky reproduces: the bound there is the fit's own error.
TEST(SolarPosition, IesDeclinationSolsticesAndEquinoxes) {
  EXPECT_NEAR(rs::declination(rs::day_of_year(6, 21)) / kDeg, 23.44, 0.05);
  EXPECT_NEAR(rs::declination(rs::day_of_year(12, 21)) / kDeg, -23.44, 0.1);
  // Equinoxes of 2003 (US Naval Observatory): 21 March 00:59 UT, 23 September 10:47 UT.
  EXPECT_NEAR(rs::declination(rs::day_of_year(3, 21)) / kDeg, 0.0, 1.2);
  EXPECT_NEAR(rs::declination(rs::day_of_year(9, 23)) / kDeg, 0.0, 1.2);
}

// The Almanac algorithm at the instants of the 2003 equinoxes, to its stated 0.01 deg.
TEST(SolarPosition, AlmanacDeclinationAtEquinoxes) {
  rs::Site greenwich{0.0, 0.0, 0.0};
  auto decl = [&](int month, int day, double hour) {
    return rs::almanac_declination(rs::almanac_day(2003, month, day, hour, greenwich), greenwich,
                                   nullptr) /
           kDeg;
  };
  EXPECT_NEAR(decl(3, 21, 0 + 59 / 60.0), 0.0, 0.01);
  EXPECT_NEAR(decl(9, 23, 10 + 47 / 60.0), 0.0, 0.01);
}

// The equation of time (solar minus mean time) is +16.4 min around 3 November and -14.2 min
// around 11 February (Astronomical Almanac); the IES fit is good to about half a minute.
TEST(SolarPosition, IesEquationOfTime) {
  rs::Site greenwich{0.0, 0.0, 0.0};
  EXPECT_NEAR(rs::solar_time_offset(rs::day_of_year(11, 3), greenwich) * 60, 16.4, 0.5);
  EXPECT_NEAR(rs::solar_time_offset(rs::day_of_year(2, 11), greenwich) * 60, -14.2, 0.5);
  // The meridian-longitude part: 15 degrees of longitude west of the meridian is one hour.
  rs::Site west{0.0, 15 * kDeg, 0.0};
  EXPECT_NEAR(rs::solar_time_offset(80, west) - rs::solar_time_offset(80, greenwich), -1.0, 1e-12);
}

// At solar noon the sun is due south (azimuth 0) at altitude 90 - latitude + declination.
TEST(SolarPosition, NoonAltitudeAndAzimuth) {
  rs::Site site{40 * kDeg, 0, 0};
  const double decl = 20 * kDeg;
  EXPECT_NEAR(rs::solar_altitude(decl, 12.0, site) / kDeg, 70.0, 1e-9);
  EXPECT_NEAR(rs::solar_azimuth(decl, 12.0, site) / kDeg, 0.0, 1e-9);
  // Morning sun is east of south: negative azimuth (degrees west of south).
  EXPECT_LT(rs::solar_azimuth(decl, 9.0, site), 0.0);
  EXPECT_GT(rs::solar_azimuth(decl, 15.0, site), 0.0);
  const auto d = rs::sun_direction(30 * kDeg, -90 * kDeg); // due east
  EXPECT_NEAR(d[0], std::cos(30 * kDeg), 1e-15);
  EXPECT_NEAR(d[1], 0.0, 1e-15);
  EXPECT_NEAR(d[2], 0.5, 1e-15);
}

// Reda & Andreas (2004), the NREL SPA paper's example: Golden, Colorado (39.742476 N,
// 105.1786 W), 17 October 2003, 12:30:30 MST (UTC-7): topocentric zenith 50.11162 deg
// (refraction included, about 0.02 deg at this height), azimuth 194.34024 deg east of north.
// The Almanac algorithm (Michalsky 1988) is good to about 0.01 deg.
TEST(SolarPosition, AlmanacMatchesSpaExample) {
  rs::Site golden{39.742476 * kDeg, 105.1786 * kDeg, 105 * kDeg};
  const double hour = 12 + 30 / 60.0 + 30 / 3600.0;
  const double n = rs::almanac_day(2003, 10, 17, hour, golden);
  double st = 0;
  const double decl = rs::almanac_declination(n, golden, &st);
  const double alt = rs::solar_altitude(decl, st, golden) / kDeg;
  const double azi = rs::solar_azimuth(decl, st, golden) / kDeg;
  EXPECT_NEAR(90 - alt, 50.11162 + 0.0167, 0.03); // SPA's zenith without refraction
  EXPECT_NEAR(azi + 180, 194.34024, 0.03);
  // SPA's declination for that instant: -9.31434 deg.
  EXPECT_NEAR(decl / kDeg, -9.31434, 0.01);
}
