#include "radcl/sky/cie_sky.h"

#include "radcl/sky/solar_position.h"

#include <algorithm>
#include <cmath>

namespace radcl::sky {

double cie_normsc(bool intermediate, double altitude) {
  // Quartic fits in x = (altitude - 45 deg) / 45 deg, lowest order first.
  static const double fit[2][5] = {
      {2.766521, 0.547665, -0.369832, 0.009237, 0.059229},
      {3.5556, -2.7152, -1.3081, 1.0660, 0.60227},
  };
  const double* c = fit[intermediate ? 1 : 0];
  const double x = (altitude - kPi / 4.0) / (kPi / 4.0);
  double v = c[4];
  for (int i = 3; i >= 0; --i)
    v = v * x + c[i];
  return v;
}

double cie_f2(CieSky type, double altitude) {
  if (type == CieSky::intermediate)
    return (2.739 + .9891 * std::sin(.3119 + 2.6 * altitude)) *
           std::exp(-(kPi / 2.0 - altitude) * (.4441 + 1.48 * altitude));
  const double sz = std::sin(altitude);
  return 0.274 * (0.91 + 10.0 * std::exp(-3.0 * (kPi / 2.0 - altitude)) + 0.45 * sz * sz);
}

double cie_normfactor(CieSky type, double altitude) {
  switch (type) {
  case CieSky::uniform:
    return 1.0;
  case CieSky::overcast:
    return 0.777778; // exactly 7/9: the integral of (1 + 2 cos t)/3 cos t over the hemisphere / pi
  case CieSky::clear:
  case CieSky::intermediate:
    break;
  }
  return cie_normsc(type == CieSky::intermediate, altitude) / cie_f2(type, altitude) / kPi;
}

double cie_zenith_radiance(CieSky type, double altitude, double turbidity) {
  double kcd; // zenith luminance, kcd/m^2
  if (is_overcast(type))
    kcd = 8.6 * std::sin(altitude) + .123;
  else
    kcd = (1.376 * turbidity - 1.81) * std::tan(altitude) + 0.38;
  if (type == CieSky::intermediate) kcd = (kcd + 8.6 * std::sin(altitude) + .123) / 2.0;
  if (kcd < 0.0) return 0.0;
  return kcd * (1000.0 / 203.0); // skylight efficacy gensky assumes (D65)
}

namespace {
double clamped_acos(double x) {
  return std::acos(std::clamp(x, -1.0, 1.0));
}
} // namespace

double cie_sky_radiance(const CieSkyParams& p, const std::array<double, 3>& d) {
  const double dz = d[2];
  switch (p.type) {
  case CieSky::overcast:
    return p.zenith * (1 + 2 * dz) / 3;
  case CieSky::uniform:
    return p.zenith;
  case CieSky::clear:
  case CieSky::intermediate:
    break;
  }
  const double cosg = d[0] * p.sun[0] + d[1] * p.sun[1] + d[2] * p.sun[2];
  const double gamma = clamped_acos(cosg); // sun to sky point
  if (p.type == CieSky::clear) {
    const double gradation = dz > .01 ? 1.0 - std::exp(-.32 / dz) : 1.0;
    return p.zenith * (.91 + 10 * std::exp(-3 * gamma) + .45 * cosg * cosg) * gradation / p.f2;
  }
  const double sun_zenith = clamped_acos(p.sun[2]);
  const double eta = clamped_acos(dz); // zenith to sky point
  return p.zenith *
         ((1.35 * std::sin(5.631 - 3.59 * eta) + 3.12) * std::sin(4.396 - 2.6 * sun_zenith) + 6.37 -
          eta) /
         2.326 * std::exp(gamma * -.563 * ((2.629 - eta) * (1.562 - sun_zenith) + .812)) / p.f2;
}

double horizon_blend(double dz, double sky, double ground) {
  const double up = std::pow(dz + 1.01, 10.0);
  const double down = std::pow(dz + 1.01, -10.0);
  return (up * sky + down * ground) / (up + down);
}

double cie_skybright(const CieSkyParams& p, const std::array<double, 3>& d) {
  return horizon_blend(d[2], cie_sky_radiance(p, d), p.ground);
}

} // namespace radcl::sky
