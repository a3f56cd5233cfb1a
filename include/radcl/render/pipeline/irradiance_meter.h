// Where an -I meter measures: Radiance traces a ray back at the given point from 1.1e-4 in
// front of it and measures where that ray stops, 1e-4 in front of the point.
#pragma once

#include <array>

#include "radcl/geometry/scene_geometry.h"

namespace radcl::render {

using Vec3d = std::array<double, 3>;

// How far along its unit direction a meter at world point p measures in scene g. Radiance's
// fixed 1e-4 assumes a model in metres; in a model under 100 units across (the office in km)
// it is a visible step (0.1 m there), so there the meter sits 1e-6 of the model's size out,
// and never within four float steps of p relative to the scene's centre (in mm, 5 m from the
// centre, 1e-4 is below them). docs/differences.md.
double meter_offset(const geometry::SceneGeometry& g, const Vec3d& p);

// The point itself: p + meter_offset(g, p) * dir.
Vec3d meter_point(const geometry::SceneGeometry& g, const Vec3d& p, const Vec3d& dir);

} // namespace radcl::render
