// Solar position for the sky generators, in the conventions of Radiance's gensky/gendaylit:
// angles in radians, longitudes and meridians positive WEST of Greenwich, azimuth measured
// from south towards west, solar time in hours. Two models: the IES approximation (no year)
// and the Astronomical Almanac's approximate algorithm (Michalsky 1988) when a year is given.
#pragma once

#include <array>

namespace radcl::sky {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180.0;

struct Site {
  double latitude = 0.66;         // radians north (Radiance's default, near San Francisco)
  double longitude = 2.13;        // radians west
  double meridian = 120.0 * kDeg; // standard time meridian, radians west
};

// Day of the year (1..365), ignoring leap years.
int day_of_year(int month, int day);

// IES model: hours to add to standard time to get solar time (equation of time plus the
// meridian-longitude offset).
double solar_time_offset(int day_of_year, const Site& site);
// IES model: solar declination (radians).
double declination(int day_of_year);

// Altitude and azimuth (radians) from declination and solar time (hours).
double solar_altitude(double declination, double solar_time, const Site& site);
double solar_azimuth(double declination, double solar_time, const Site& site);

// Almanac model: fractional days since noon UT, 1 January 2000, of a standard (meridian)
// time. Valid for 1950-2050.
double almanac_day(int year, int month, int day, double hour, const Site& site);
// Almanac model: declination (radians); when `solar_time` is given, also the local solar
// time (hours) at that instant.
double almanac_declination(double almanac_day, const Site& site, double* solar_time);

// Unit vector towards the sun: +x east, +y north, +z up.
std::array<double, 3> sun_direction(double altitude, double azimuth);

} // namespace radcl::sky
