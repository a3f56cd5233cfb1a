// CIE sky luminance distributions as gensky and skybright.cal use them (clear, overcast,
// uniform, intermediate), with gensky's zenith radiance and normalisation. Radiances are in
// Radiance's W/sr/m^2 (luminance / 179 for white light; gensky uses 203 lm/W for skylight).
#pragma once

#include <array>

namespace radcl::sky {

enum class CieSky { clear = 1, overcast = 2, uniform = 3, intermediate = 4 };

inline bool is_overcast(CieSky t) {
  return t == CieSky::overcast || t == CieSky::uniform;
}

// gensky's polynomial fit of (horizontal irradiance * F2 / zenith radiance) against solar
// altitude for the clear and intermediate skies.
double cie_normsc(bool intermediate, double altitude);
// The gradation/indicatrix product at the zenith for a sun at `altitude` (clear and
// intermediate skies only).
double cie_f2(CieSky type, double altitude);
// Horizontal diffuse irradiance divided by (pi * zenith radiance).
double cie_normfactor(CieSky type, double altitude);
// Zenith radiance (W/sr/m^2) from gensky's empirical formulas (turbidity for clear skies).
double cie_zenith_radiance(CieSky type, double altitude, double turbidity);

// The arguments skybright.cal receives (A1..A7).
struct CieSkyParams {
  CieSky type = CieSky::clear;
  double zenith = 0;                  // A2: zenith radiance
  double ground = 0;                  // A3: ground radiance
  double f2 = 1;                      // A4: normalisation
  std::array<double, 3> sun{0, 0, 1}; // A5..A7
};

// The sky's own radiance in direction `dir` (unit vector, z up), without the blend into the
// ground below the horizon: the function whose hemispherical integral gensky normalises.
double cie_sky_radiance(const CieSkyParams& p, const std::array<double, 3>& dir);
// skybright.cal's `skybr`: the sky blended smoothly into the ground radiance below the horizon.
double cie_skybright(const CieSkyParams& p, const std::array<double, 3>& dir);

// skybright.cal's and perezlum.cal's smooth hand-over from the sky to the ground radiance
// around the horizon: weights (dz + 1.01)^10 for the sky and (dz + 1.01)^-10 for the ground.
double horizon_blend(double dz, double sky, double ground);

} // namespace radcl::sky
