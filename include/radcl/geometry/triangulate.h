// Polygon helpers shared by the Embree builder and its tests: Radiance's polygon plane, and
// triangulation of polygons whose holes are joined to the outline by seams.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace radcl::geometry {

using Point2 = std::array<double, 2>;
using Tri = std::array<std::uint32_t, 3>;

struct PolygonPlane {
  std::array<double, 3> normal{}; // normalised sum of fan cross products (Radiance's)
  double area = 0;                // half the length of that sum; 0 for a degenerate polygon
  double offset = 0;              // mean of normal . vertex (Radiance's plane offset)
};

PolygonPlane polygon_plane(std::span<const std::array<double, 3>> verts);

// Triangulates a polygon given counter-clockwise (positive signed area). Seams are allowed:
// coincident vertices and zero-width bridges between an outline and its holes. Convex
// polygons are fanned; others are ear-clipped. Degenerate (zero-area) triangles are dropped.
std::vector<Tri> triangulate_2d(std::span<const Point2> pts);

// Projects `verts` onto the plane with the given normal (as seen from its front) and
// triangulates them; indices refer to `verts`.
std::vector<Tri> triangulate_polygon(std::span<const std::array<double, 3>> verts,
                                     const std::array<double, 3>& normal);

} // namespace radcl::geometry
