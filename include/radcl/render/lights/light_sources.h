// Light sources for the direct calculation, compiled from the scene into device records
// (rc_source) the kernels sample (kernels/lights/sources.cl).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "radcl/device_types.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/scene/scene.h"

namespace radcl::render {

struct CompiledSources {
  std::vector<rc_source> sources;
  std::vector<rc_float4> verts;   // polygon source vertices (re-centred), referenced by rc_source
  std::vector<rc_mirror> mirrors; // mirrors of virtual sources (virtual_sources.h)
  std::vector<std::string> names; // object names of the real sources (they come first)
  std::vector<std::uint32_t> object_surface; // compiled surface of each real source's object
};

// One rc_source per direct light source of the main scene (scene::is_light_source) and per
// distant `source` with a light-type material, in object order. Positions are re-centred on
// geom.centre(). `surface_index` maps a main-scene surface object number to its compiled
// surface index. Radiance's errors and warnings for sources are raised here ("cannot hit source
// center" for a polygon whose centroid lies outside it, "illegal material" for a light on a
// cone, "source aspect too small" for a thick cylinder, spotlight on a distant source).
//
// Field use beyond device_types.h's comments:
// - polygon: pos = area centroid, pos.w = largest vertex distance from it; su/sv are the half
//   extents of a rectangle covering the polygon (a parallelogram's own half edges, as
//   Radiance), centred at pos + su.w * su + sv.w * sv; verts/nverts hold its vertices.
// - ring: pos.w = outer radius, su.w = inner radius, su/sv = orthonormal in-plane axes scaled
//   by the outer radius (su x sv along the normal).
// - cylinder: pos.w = radius; distant: pos.w = sqrt(solid angle / pi) (Radiance's srad).
// - a spotlight whose cone lies behind its flat source is dropped with Radiance's warning
//   "invalid spotlight direction" (Radiance never samples it either).
CompiledSources compile_sources(const scene::SceneDescription& scene,
                                const geometry::SceneGeometry& geom,
                                const std::function<std::uint32_t(std::int32_t)>& surface_index);

} // namespace radcl::render
