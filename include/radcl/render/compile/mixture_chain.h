// Radiance's walk of a modifier chain with mixtures in it (rayshade, raytexture, raymixture):
// which patterns a hit applies, in what order, and where the chain ends. A mixture none of
// whose sides reaches a material is a pattern of its own (the sides' colours and normal
// perturbations blended by its coefficient) and the walk goes on past it; a mixture with a
// material on a side ends the walk as the de facto material.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "radcl/device_types.h"
#include "radcl/scene/scene.h"

namespace radcl::render {

// Markers in a pattern program: a pattern-only mixture `m` is written as
// kMixBegin, m, <its foreground side's program>, kMixBack, <its background's>, kMixEnd.
constexpr std::int32_t kMixBegin = -2;
constexpr std::int32_t kMixBack = -3;
constexpr std::int32_t kMixEnd = -4;

struct ChainWalk {
  std::vector<std::int32_t> program;    // patterns (object numbers) and marked mixtures, in order
  std::int32_t material = scene::kVoid; // the material the walk reaches, or
  std::int32_t mixture = scene::kVoid;  // the mixture with a material on a side that ends it
  // Whose modifiers the material's raytexture() walks: the material's own, or those of the
  // named alias that stands for it (Radiance's m_alias gives the copy the alias's modifier).
  std::int32_t texture_owner = scene::kVoid;
};

// The walk of rayshade() from modifier `mod` of `sd`. `surface` names the surface for messages
// (`polygon "floor"`). Fatal: a pattern type or mixture the renderer does not handle, an
// undefined mixture side, a mixture with a material side and a modifier of its own
// ("inappropriate modifier"), nesting deeper than RC_MIX_MAX_DEPTH (radcl's limit).
ChainWalk walk_chain(const scene::SceneDescription& sd, std::int32_t mod,
                     const std::string& surface);

// The walk of raytexture() over the modifiers of `owner` (a material, or the named alias
// standing for one): patterns and pattern-only mixtures; a material or a mixture with one met
// there is fatal "conflicting material".
std::vector<std::int32_t> walk_texture(const scene::SceneDescription& sd, std::int32_t owner,
                                       const std::string& surface);

// The modifiers a mixture names as foreground and background (kVoid for "void"). Fatal: too few
// string arguments for its type, an undefined name.
std::array<std::int32_t, 2> mixture_sides(const scene::SceneDescription& sd, std::int32_t mix);

// The name Radiance's findmaterial() reports for a surface with modifier `mod`: its first
// material, or a mixture with a void modifier before it (the de facto material); "void".
std::string reported_material(const scene::SceneDescription& sd, std::int32_t mod);

} // namespace radcl::render
