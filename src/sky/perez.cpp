#include "radcl/sky/perez.h"

#include "radcl/sky/cie_sky.h"
#include "radcl/sky/solar_position.h"

#include <algorithm>
#include <cmath>

namespace radcl::sky {
namespace {

// Perez et al. 1993, table 1: for each clearness bin and each coefficient a..e, the four
// numbers x1 x2 x3 x4 of x = x1 + x2 Z + delta (x3 + x4 Z). In the first bin c and d have
// their own forms (see perez_coefficients). Kept in single precision like gendaylit's table,
// so that the printed coefficients agree digit for digit.
const float kLuminanceTable[8][5][4] = {
    {{1.3525f, -0.2576f, -0.2690f, -1.4366f},
     {-0.7670f, 0.0007f, 1.2734f, -0.1233f},
     {2.8000f, 0.6004f, 1.2375f, 1.0000f},
     {1.8734f, 0.6297f, 0.9738f, 0.2809f},
     {0.0356f, -0.1246f, -0.5718f, 0.9938f}},
    {{-1.2219f, -0.7730f, 1.4148f, 1.1016f},
     {-0.2054f, 0.0367f, -3.9128f, 0.9156f},
     {6.9750f, 0.1774f, 6.4477f, -0.1239f},
     {-1.5798f, -0.5081f, -1.7812f, 0.1080f},
     {0.2624f, 0.0672f, -0.2190f, -0.4285f}},
    {{-1.1000f, -0.2515f, 0.8952f, 0.0156f},
     {0.2782f, -0.1812f, -4.5000f, 1.1766f},
     {24.7219f, -13.0812f, -37.7000f, 34.8438f},
     {-5.0000f, 1.5218f, 3.9229f, -2.6204f},
     {-0.0156f, 0.1597f, 0.4199f, -0.5562f}},
    {{-0.5484f, -0.6654f, -0.2672f, 0.7117f},
     {0.7234f, -0.6219f, -5.6812f, 2.6297f},
     {33.3389f, -18.3000f, -62.2500f, 52.0781f},
     {-3.5000f, 0.0016f, 1.1477f, 0.1062f},
     {0.4659f, -0.3296f, -0.0876f, -0.0329f}},
    {{-0.6000f, -0.3566f, -2.5000f, 2.3250f},
     {0.2937f, 0.0496f, -5.6812f, 1.8415f},
     {21.0000f, -4.7656f, -21.5906f, 7.2492f},
     {-3.5000f, -0.1554f, 1.4062f, 0.3988f},
     {0.0032f, 0.0766f, -0.0656f, -0.1294f}},
    {{-1.0156f, -0.3670f, 1.0078f, 1.4051f},
     {0.2875f, -0.5328f, -3.8500f, 3.3750f},
     {14.0000f, -0.9999f, -7.1406f, 7.5469f},
     {-3.4000f, -0.1078f, -1.0750f, 1.5702f},
     {-0.0672f, 0.4016f, 0.3017f, -0.4844f}},
    {{-1.0000f, 0.0211f, 0.5025f, -0.5119f},
     {-0.3000f, 0.1922f, 0.7023f, -1.6317f},
     {19.0000f, -5.0000f, 1.2438f, -1.9094f},
     {-4.0000f, 0.0250f, 0.3844f, 0.2656f},
     {1.0468f, -0.3788f, -2.4517f, 1.4656f}},
    {{-1.0500f, 0.0289f, 0.4260f, 0.3590f},
     {-0.3250f, 0.1156f, 0.7781f, 0.0025f},
     {31.0625f, -14.5000f, -46.1148f, 55.3750f},
     {-7.2312f, 0.4050f, 13.3500f, 0.6234f},
     {1.5000f, -0.6426f, 1.8564f, 0.5636f}},
};

// Upper clearness bounds of bins 0..6 (bin 7 is everything above).
const double kBinBounds[7] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};

// Perez et al. 1990, table 4: efficacy = a + b W + c cos Z + d ln(delta) (global and diffuse
// horizontal); direct normal: a + b W + c exp(5.73 Z - 5) + d delta.
struct EfficacyRow {
  double a, b, c, d;
};
const EfficacyRow kGlobalEfficacy[8] = {{96.63, -0.47, 11.50, -9.16}, {107.54, 0.79, 1.79, -1.19},
                                        {98.73, 0.70, 4.40, -6.95},   {92.72, 0.56, 8.36, -8.31},
                                        {86.73, 0.98, 7.10, -10.94},  {88.34, 1.39, 6.06, -7.60},
                                        {78.63, 1.47, 4.93, -11.37},  {99.65, 1.86, -4.46, -3.15}};
const EfficacyRow kDiffuseEfficacy[8] = {
    {97.24, -0.46, 12.00, -8.91},   {107.22, 1.15, 0.59, -3.95},    {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90}, {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03}, {152.23, 0.35, -45.27, -7.98}};
const EfficacyRow kDirectEfficacy[8] = {
    {57.20, -4.55, -2.98, 117.12}, {98.99, -3.46, -1.21, 12.38},  {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56}, {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44}, {101.18, 1.58, -1.10, -8.29}};

// The efficacy models' bin for epsilon in [1, top); -1 outside.
int efficacy_bin(double epsilon, double top) {
  static const double lower[9] = {1, 1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200, 0};
  int bin = -1;
  for (int i = 0; i < 8; ++i) {
    const double upper = i == 7 ? top : lower[i + 1];
    if (epsilon >= lower[i] && epsilon < upper) bin = i;
  }
  return bin;
}

} // namespace

int perez_clearness_bin(float epsilon) {
  int bin = 0;
  while (bin < 7 && !(epsilon < kBinBounds[bin]))
    ++bin;
  return bin;
}

PerezCoefficients perez_coefficients(double z, double epsilon, double delta) {
  if (epsilon > 1.065 && epsilon < 2.8 && delta < 0.2) delta = 0.2;
  const int bin = perez_clearness_bin(static_cast<float>(epsilon));
  const auto& t = kLuminanceTable[bin];
  double c[5];
  for (int i = 0; i < 5; ++i)
    c[i] = t[i][0] + t[i][1] * z + delta * (t[i][2] + t[i][3] * z);
  if (bin == 0) { // overcast bin: c and d are not linear in delta
    c[2] = std::exp(std::pow(delta * (t[2][0] + t[2][1] * z), t[2][2])) - t[2][3];
    c[3] = -std::exp(delta * (t[3][0] + t[3][1] * z)) + t[3][2] + delta * t[3][3];
  }
  return {c[0], c[1], c[2], c[3], c[4]};
}

double perez_relative_luminance(const PerezCoefficients& k, double zeta, double gamma) {
  return (1 + k.a * std::exp(k.b / std::cos(zeta))) *
         (1 + k.c * std::exp(k.d * gamma) + k.e * std::cos(gamma) * std::cos(gamma));
}

double perez_diffuse_efficacy(double epsilon, double delta, double w, double zdeg) {
  const int bin = efficacy_bin(epsilon, 12.01);
  if (bin < 0) return -1;
  const EfficacyRow& r = kDiffuseEfficacy[bin];
  return r.a + r.b * w + r.c * std::cos(zdeg * kPi / 180) + r.d * std::log(delta);
}

double perez_global_efficacy(double epsilon, double delta, double w, double zdeg) {
  const int bin = std::max(efficacy_bin(epsilon, 12.01), 0);
  const EfficacyRow& r = kGlobalEfficacy[bin];
  return r.a + r.b * w + r.c * std::cos(zdeg * kPi / 180) + r.d * std::log(delta);
}

double perez_direct_efficacy(double epsilon, double delta, double w, double zdeg) {
  const int bin = std::max(efficacy_bin(epsilon, 12.1), 0);
  const EfficacyRow& r = kDirectEfficacy[bin];
  const double v = r.a + r.b * w + r.c * std::exp(5.73 * zdeg * kPi / 180 - 5) + r.d * delta;
  return v < 0 ? 0 : v;
}

double perez_discrete_integral(const PerezCoefficients& k, double z) {
  // Rings of patch centres: zenith angle (deg), number of patches (equally spaced from
  // azimuth 0); the last ring is the zenith patch.
  static const int rings[8][2] = {{84, 30}, {72, 30}, {60, 24}, {48, 24},
                                  {36, 18}, {24, 12}, {12, 6},  {0, 1}};
  double sum = 0;
  for (const auto& ring : rings) {
    const double theta = ring[0] * (kPi / 180.);
    const int n = ring[1];
    for (int j = 0; j < n; ++j) {
      const double phi = (360 / n) * j * (kPi / 180.);
      const double cosg =
          std::cos(z) * std::cos(theta) + std::sin(z) * std::sin(theta) * std::cos(phi);
      const double gamma = cosg > 1 ? 0 : std::acos(cosg);
      const float lv = static_cast<float>(perez_relative_luminance(k, theta, gamma));
      sum += lv * std::cos(theta);
    }
  }
  return sum * (2. * kPi / 145.);
}

double perez_sky_radiance(const PerezSkyParams& p, const std::array<double, 3>& d) {
  const double cosg = d[0] * p.sun[0] + d[1] * p.sun[1] + d[2] * p.sun[2];
  const double gamma = std::acos(std::clamp(cosg, -1.0, 1.0));
  const double dz = d[2] > 0.01 ? d[2] : 0.01;
  auto clamped_exp = [](double x) { return x < -100 ? 0.0 : std::exp(x); };
  return p.diffnorm * (1 + p.k.a * clamped_exp(p.k.b / dz)) *
         (1 + p.k.c * clamped_exp(p.k.d * gamma) + p.k.e * cosg * cosg);
}

double perez_skybright(const PerezSkyParams& p, const std::array<double, 3>& d) {
  return horizon_blend(d[2], perez_sky_radiance(p, d), p.ground);
}

} // namespace radcl::sky
