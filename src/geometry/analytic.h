// Spheres, cones, cylinders and rings (with their inward twins) as exact double-precision
// surfaces, set up from Radiance objects with Radiance's argument checks and conversions.
#pragma once

#include <cstdint>
#include <optional>

#include "radcl/scene/scene.h"
#include "vec.h"

namespace radcl::geometry {

enum class Shape : std::uint8_t { Sphere, Cone, Ring };

struct AnalyticSurface {
  std::int32_t object = -1;
  scene::ObjectType type{}; // after conversions (negative radius: sphere <-> bubble, ...)
  Shape shape = Shape::Sphere;
  bool inward = false;   // bubble, cup, tube: normal points to the axis/centre
  Vec3 c{};              // sphere/ring centre; cone/cylinder end with the smaller radius
  Vec3 axis{};           // unit: cone from small to large end; ring normal
  double length = 0;     // cone axis length
  double r0 = 0, r1 = 0; // radius at c and at the far end (cylinder: equal); ring inner/outer
};

// Validates and converts `o` (a sphere, bubble, cone, cup, cylinder, tube or ring). Throws
// FatalError for bad argument counts and negative ring radii; warns for other negative radii.
// Returns nullopt (after Radiance's warning) for degenerate surfaces: zero or illegal radii,
// no orientation.
std::optional<AnalyticSurface> make_analytic(const scene::Object& o, std::int32_t index);

// Re-expresses the surface relative to `origin`.
void shift(AnalyticSurface& s, const Vec3& origin);

// Bounds (lo, hi) of the surface.
std::array<Vec3, 2> analytic_bounds(const AnalyticSurface& s);

// First intersection of o + t d with tmin < t < tmax (d need not be unit; t is parametric).
// On a hit, sets t and the unit normal in Radiance's orientation. An origin within `on`
// (distance) of the surface lies on it: the root there is the origin itself, never a hit (a
// ray leaving a sphere outwards, or a ring, cannot meet it again; inwards it meets the far
// side). This is what keeps rays from float-rounded surface points off their own surface.
bool intersect_analytic(const AnalyticSurface& s, const Vec3& o, const Vec3& d, double tmin,
                        double tmax, double& t, Vec3& n, double on = 0);

} // namespace radcl::geometry
