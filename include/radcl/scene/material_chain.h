// Walking a surface's modifier chain as Radiance does: the first material shades it; aliases
// stand for the object they name.
#pragma once

#include <cstdint>

#include "radcl/scene/scene.h"

namespace radcl::scene {

// The object whose type and arguments an alias stands for (following chains of aliases), or
// `obj` itself when it is no alias. kVoid if a named reference does not resolve.
std::int32_t alias_target(const SceneDescription& scene, std::int32_t obj);

// The first material in the modifier chain of `surface` (alias targets resolved), or kVoid when
// the chain ends in void without one. Throws FatalError for a chain that loops.
std::int32_t first_material(const SceneDescription& scene, std::int32_t surface);
// The same, starting from a modifier (mesh faces name theirs directly).
std::int32_t first_material_from(const SceneDescription& scene, std::int32_t modifier);

// Whether `surface` is a light source for the direct calculation: its material is light, illum
// or spotlight, or glow with a positive radius of influence, and the surface is not a distant
// `source` with glow (glow on a source is never a direct source).
bool is_light_source(const SceneDescription& scene, std::int32_t surface);

} // namespace radcl::scene
