#include "radcl/render/pipeline/irradiance_meter.h"

#include <algorithm>
#include <cmath>

namespace radcl::render {

double meter_offset(const geometry::SceneGeometry& g, const Vec3d& p) {
  const Vec3d c = g.centre();
  const std::array<Vec3d, 2> b = g.bounds();
  const double diag = std::hypot(b[1][0] - b[0][0], b[1][1] - b[0][1], b[1][2] - b[0][2]);
  const double off = std::isfinite(diag) && diag > 0 ? std::min(1e-4, 1e-6 * diag) : 1e-4;
  const double far =
      std::max({std::fabs(p[0] - c[0]), std::fabs(p[1] - c[1]), std::fabs(p[2] - c[2])});
  return std::isfinite(far) ? std::max(off, 5e-7 * far) : off;
}

Vec3d meter_point(const geometry::SceneGeometry& g, const Vec3d& p, const Vec3d& dir) {
  const double off = meter_offset(g, p);
  return {p[0] + off * dir[0], p[1] + off * dir[1], p[2] + off * dir[2]};
}

} // namespace radcl::render
