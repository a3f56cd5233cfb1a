#include "radcl/bsdf/klems_basis.h"

#include "radcl/util/error.h"

#include <cmath>
#include <cstdio>
#include <strings.h>

namespace radcl::bsdf {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

} // namespace

KlemsBasis::KlemsBasis(std::string name, std::vector<double> theta_bounds, std::vector<int> nphis)
    : name_(std::move(name)), theta_(std::move(theta_bounds)), nphis_(std::move(nphis)) {
  const std::string where = "angle basis \"" + name_ + "\"";
  if (nphis_.empty() || theta_.size() != nphis_.size() + 1)
    throw FatalError(where + " has no rings");
  if (theta_[0] != 0) throw FatalError(where + ": first ring does not start at theta 0");
  for (size_t r = 0; r < nphis_.size(); ++r) {
    if (!(theta_[r + 1] > theta_[r]) || theta_[r + 1] > 90)
      throw FatalError(where + ": bad theta bounds " + number(theta_[r]) + " to " +
                       number(theta_[r + 1]));
    // One patch is a polar cap; a ring away from the pole needs several.
    if (nphis_[r] <= 0 || (nphis_[r] == 1 && theta_[r] > 0))
      throw FatalError(where + ": illegal phi count " + std::to_string(nphis_[r]) + " at theta " +
                       number(theta_[r]));
    first_.push_back(size_);
    size_ += nphis_[r];
  }
}

const KlemsBasis* KlemsBasis::standard(const std::string& name) {
  // The LBNL definitions (WINDOW 6), as Radiance builds them in.
  static const KlemsBasis bases[] = {
      {"LBNL/Klems Full",
       {0, 5, 15, 25, 35, 45, 55, 65, 75, 90},
       {1, 8, 16, 20, 24, 24, 24, 16, 12}},
      {"LBNL/Klems Half", {0, 6.5, 19.5, 32.5, 46.5, 61.5, 76.5, 90}, {1, 8, 12, 16, 20, 12, 4}},
      {"LBNL/Klems Quarter", {0, 9, 27, 46, 66, 90}, {1, 8, 12, 12, 8}},
  };
  for (const KlemsBasis& b : bases)
    if (strcasecmp(b.name().c_str(), name.c_str()) == 0) return &b;
  return nullptr;
}

int KlemsBasis::ring_of(int patch) const {
  if (patch < 0 || patch >= size_) return -1;
  int r = rings() - 1;
  while (first_[r] > patch)
    --r;
  return r;
}

int KlemsBasis::patch(const vec::Vec3& dir) const {
  if (dir[2] < 0) return -1;
  const double theta = std::atan2(std::hypot(dir[0], dir[1]), dir[2]) / kDeg;
  int r = 0;
  while (r < rings() && theta_[r + 1] <= theta)
    ++r;
  if (r == rings()) return -1;
  double phi = std::atan2(dir[1], dir[0]) / kDeg;
  if (phi < 0) phi += 360;
  // Patch j spans [j - 1/2, j + 1/2] * 360 / n: round, and the top half-patch wraps to 0.
  int j = static_cast<int>(phi * nphis_[r] / 360 + 0.5);
  if (j >= nphis_[r]) j = 0;
  return first_[r] + j;
}

vec::Vec3 KlemsBasis::centre(int patch) const {
  const int r = ring_of(patch);
  if (r < 0) return {0, 0, 0};
  const bool cap = nphis_[r] == 1 && theta_[r] == 0;
  const double theta = cap ? 0.0 : 0.5 * (theta_[r] + theta_[r + 1]) * kDeg;
  const double phi = 2 * kPi * (patch - first_[r]) / nphis_[r];
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

double KlemsBasis::lambda(int patch) const {
  const int r = ring_of(patch);
  if (r < 0) return 0;
  const double c0 = std::cos(theta_[r] * kDeg), c1 = std::cos(theta_[r + 1] * kDeg);
  return kPi * (c0 * c0 - c1 * c1) / nphis_[r];
}

int incident_patch(const KlemsBasis& basis, const vec::Vec3& in, bool front) {
  const double z = front ? in[2] : -in[2];
  return z < 0 ? -1 : basis.patch({-in[0], -in[1], z});
}

int outgoing_patch(const KlemsBasis& basis, const vec::Vec3& out, bool front) {
  const double z = front ? out[2] : -out[2];
  return z < 0 ? -1 : basis.patch({out[0], out[1], z});
}

} // namespace radcl::bsdf
