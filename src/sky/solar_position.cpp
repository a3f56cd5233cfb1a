#include "radcl/sky/solar_position.h"

#include <cmath>

namespace radcl::sky {

int day_of_year(int month, int day) {
  static const int before[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  return before[month - 1] + day;
}

// The IES fits below (and their constants) are the ones gensky uses; keeping the same
// arithmetic keeps the printed angles identical.
double solar_time_offset(int jd, const Site& site) {
  const double eot = 0.170 * std::sin((4.0 * kPi / 373.0) * (jd - 80)) -
                     0.129 * std::sin((2.0 * kPi / 355.0) * (jd - 8));
  return eot + (12.0 / kPi) * (site.meridian - site.longitude);
}

double declination(int jd) {
  return 0.4093 * std::sin((2.0 * kPi / 365.0) * (jd - 81));
}

double solar_altitude(double decl, double st, const Site& site) {
  const double hour_angle = st * (kPi / 12.0);
  return std::asin(std::sin(site.latitude) * std::sin(decl) -
                   std::cos(site.latitude) * std::cos(decl) * std::cos(hour_angle));
}

double solar_azimuth(double decl, double st, const Site& site) {
  const double hour_angle = st * (kPi / 12.0);
  return -std::atan2(std::cos(decl) * std::sin(hour_angle),
                     -std::cos(site.latitude) * std::sin(decl) -
                         std::sin(site.latitude) * std::cos(decl) * std::cos(hour_angle));
}

namespace {
// Wraps an angle or time into [0, period).
double wrap(double v, double period) {
  while (v < 0)
    v += period;
  while (v >= period)
    v -= period;
  return v;
}
} // namespace

double almanac_day(int year, int month, int day, double hour, const Site& site) {
  int jd = day_of_year(month, day);
  jd += (month > 2) & !(year & 3); // leap day (every 4th year is right for 1950-2050)
  jd += (year - 1949) * 365 + (year - 1949) / 4;
  hour += site.meridian * (12.0 / kPi); // standard time to UT
  // Julian date 2432916.5 is 0h UT on 31 December 1948; 2451545.0 is noon 1 January 2000.
  return jd + hour * (1.0 / 24.0) + (2432916.5 - 2451545.0);
}

double almanac_declination(double n, const Site& site, double* solar_time) {
  const double mean_longitude = wrap(280.460 * kDeg + 0.9856474 * kDeg * n, 2.0 * kPi);
  const double mean_anomaly = wrap(357.528 * kDeg + 0.9856003 * kDeg * n, 2.0 * kPi);
  const double ecl_longitude = mean_longitude + 1.915 * kDeg * std::sin(mean_anomaly) +
                               0.020 * kDeg * std::sin(2.0 * mean_anomaly);
  const double obliquity = 23.439 * kDeg - 4e-7 * kDeg * n;
  const double sin_l = std::sin(ecl_longitude);
  if (solar_time) {
    const double right_ascension = std::atan2(sin_l * std::cos(obliquity), std::cos(ecl_longitude));
    const double ut_hours = 24.0 * (n - std::floor(n)) + 12.0;
    const double gmst = 6.697375 + 0.0657098242 * n + ut_hours;
    const double lmst = gmst - site.longitude * (12.0 / kPi);
    *solar_time = wrap(lmst - right_ascension * (12.0 / kPi) + 12.0, 24.0);
  }
  return std::asin(std::sin(obliquity) * sin_l);
}

std::array<double, 3> sun_direction(double altitude, double azimuth) {
  return {-std::sin(azimuth) * std::cos(altitude), -std::cos(azimuth) * std::cos(altitude),
          std::sin(altitude)};
}

} // namespace radcl::sky
