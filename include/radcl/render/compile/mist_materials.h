// mist: the material's compiled arguments and its source list (Radiance's m_mist). A mist names
// the light sources whose light it scatters into rays crossing it; every distinct name across the
// scene's mists gets one bit of rc_ray.slights, and the renderer resolves the names to source
// indices once the virtual sources exist (names `relay>source` denote those).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "radcl/render/lights/light_sources.h"
#include "radcl/scene/scene.h"

namespace radcl::render {

// The most distinct source names all mist materials of a scene may list (rc_ray.slights' bits;
// Radiance allows 32 sources in one ray's list).
constexpr std::size_t kMaxMistSources = 32;

// The distinct source names the scene's mists list, one per bit, and the first mist to list each.
struct MistSources {
  std::vector<std::string> names, mists;
};

// The RC_MIST_NARGS arguments of mist `o` (device_types.h). Its names join `list` (one bit
// each); a name it lists twice draws Radiance's "duplicate source" warning. More than
// kMaxMistSources names in the scene is fatal.
std::vector<float> mist_arguments(const scene::Object& o, MistSources& list);

// Per name, the index of the source it denotes (the last one that matches, as Radiance), or
// RC_NONE with Radiance's "unknown source" warning; then the bit set of the names that matched
// (a mist's list holds only those, as Radiance's). `surface_names` names compiled surfaces
// (a virtual source's relay is its mirror's surface).
std::vector<std::uint32_t> mist_source_table(const MistSources& list,
                                             const CompiledSources& sources,
                                             const std::vector<std::string>& surface_names);

} // namespace radcl::render
