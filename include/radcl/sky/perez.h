// The Perez all-weather sky model (Perez, Seals & Michalsky 1993, Solar Energy 50(3)) and the
// Perez luminous-efficacy models (Perez et al. 1990, Solar Energy 44(5)), as gendaylit and
// perezlum.cal use them. Angles in radians unless said otherwise.
#pragma once

#include <array>

namespace radcl::sky {

// Sky clearness (epsilon) bins of both papers: bin k covers [bound[k], bound[k+1]).
int perez_clearness_bin(float epsilon);

// The five coefficients a..e of the relative luminance distribution for a sun at zenith
// angle `sun_zenith`, clearness `epsilon` and brightness `delta` (delta is raised to 0.2 for
// 1.065 < epsilon < 2.8, as gendaylit does).
struct PerezCoefficients {
  double a = 0, b = 0, c = 0, d = 0, e = 0;
};
PerezCoefficients perez_coefficients(double sun_zenith, double epsilon, double delta);

// Relative luminance at zenith angle `zeta` and angular distance `gamma` from the sun.
double perez_relative_luminance(const PerezCoefficients& k, double zeta, double gamma);

// Luminous efficacies (lm/W) of diffuse horizontal and direct normal irradiance, for
// precipitable water `w` (cm) and sun zenith angle in DEGREES; a negative diffuse result
// means epsilon fell outside every bin.
double perez_diffuse_efficacy(double epsilon, double delta, double w, double sun_zenith_deg);
double perez_direct_efficacy(double epsilon, double delta, double w, double sun_zenith_deg);
double perez_global_efficacy(double epsilon, double delta, double w, double sun_zenith_deg);

// gendaylit's discrete integral of the relative luminance times cos(zenith) over the sky
// hemisphere: 145 directions (the Tregenza-like patch centres gendaylit uses) of equal
// weight 2 pi / 145. The luminances are stored as float, as gendaylit does.
double perez_discrete_integral(const PerezCoefficients& k, double sun_zenith);

// The arguments perezlum.cal receives (A1..A10).
struct PerezSkyParams {
  double diffnorm = 0;                // A1
  double ground = 0;                  // A2
  PerezCoefficients k;                // A3..A7
  std::array<double, 3> sun{0, 0, 1}; // A8..A10
};
// The sky's radiance in direction `dir` without the ground blend (perezlum.cal's intersky).
double perez_sky_radiance(const PerezSkyParams& p, const std::array<double, 3>& dir);
// perezlum.cal's `skybright`: blended into the ground radiance below the horizon.
double perez_skybright(const PerezSkyParams& p, const std::array<double, 3>& dir);

} // namespace radcl::sky
