// Radiance's polygon plane and the projection of a polygon into it for triangulation.
#include <cmath>

#include "radcl/geometry/triangulate.h"
#include "vec.h"

namespace radcl::geometry {

PolygonPlane polygon_plane(std::span<const std::array<double, 3>> v) {
  PolygonPlane pl;
  if (v.size() < 3) return pl;
  // Fan of cross products from vertex 0: the normal's length is twice the area, exactly as
  // Radiance computes it (so the same polygons are zero-area).
  Vec3 sum{0, 0, 0};
  Vec3 e1 = sub(v[1], v[0]);
  for (std::size_t i = 2; i < v.size(); ++i) {
    const Vec3 e2 = sub(v[i], v[0]);
    sum = add(sum, cross(e1, e2));
    e1 = e2;
  }
  const double l = length(sum);
  if (l == 0) return pl;
  pl.normal = scale(sum, 1 / l);
  pl.area = 0.5 * l;
  double off = 0;
  for (const auto& p : v)
    off += dot(pl.normal, p);
  pl.offset = off / static_cast<double>(v.size());
  return pl;
}

std::vector<Tri> triangulate_polygon(std::span<const std::array<double, 3>> verts,
                                     const std::array<double, 3>& n) {
  if (verts.size() < 3) return {};
  // Orthonormal (u, w) with u x w = n, so a polygon counter-clockwise about n stays
  // counter-clockwise in 2D. Coordinates relative to vertex 0 keep their precision.
  const Vec3 axis = std::abs(n[0]) < std::abs(n[1])
                        ? (std::abs(n[0]) < std::abs(n[2]) ? Vec3{1, 0, 0} : Vec3{0, 0, 1})
                        : (std::abs(n[1]) < std::abs(n[2]) ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  const Vec3 u = normalized(cross(n, axis));
  const Vec3 w = cross(n, u);
  std::vector<Point2> p2(verts.size());
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const Vec3 d = sub(verts[i], verts[0]);
    p2[i] = {dot(d, u), dot(d, w)};
  }
  return triangulate_2d(p2);
}

} // namespace radcl::geometry
