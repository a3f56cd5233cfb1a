// Virtual light sources for planar mirrors, after Radiance's virtuals.c and m_mirror.c: every
// source a mirror can reflect gets an image behind the mirror, relayed through up to -dr
// mirrors, so that light arriving by way of a mirror is part of the direct calculation.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "radcl/device_types.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/render/lights/light_sources.h"
#include "radcl/scene/scene.h"

namespace radcl::render {

// Traces shadow requests against the sources compiled so far; returns for each the fraction of
// its contribution that arrives (0 when blocked).
using ShadowTester =
    std::function<std::vector<float>(const CompiledSources&, const std::vector<rc_shadow>&)>;

// Appends the mirrors (polygons and rings of material `mirror` in the main scene; other
// surfaces get Radiance's warning "secondary sources not supported") and the virtual sources
// to `sources`. Radiance's rules: a mirror images a source only if part of the source is in
// front of it and the source is not relayed by that mirror itself; each image is imaged again
// by the other mirrors while fewer than `relays` mirrors are on its way. With `pretest` > 0
// (-dp, samples per steradian) shadow rays from points on the mirror to the imaged source
// decide: none arrives -> no virtual source; all arrive unchanged -> shadow rays need only reach
// the mirror; otherwise they follow the whole way (RC_SRCF_FOLLOW).
void add_virtual_sources(const scene::SceneDescription& scene, const geometry::SceneGeometry& geom,
                         const std::function<std::uint32_t(std::int32_t)>& surface_index,
                         int relays, int pretest, const ShadowTester& test,
                         CompiledSources& sources);

} // namespace radcl::render
