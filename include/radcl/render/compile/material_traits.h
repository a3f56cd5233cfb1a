// What the host decides from a material's kind, in one table: whether the kernels implement it,
// how many real arguments they read, whether a shadow ray that meets it is blocked whatever it
// carries, and whether rtrace's lengths see through it. The kernels decide the rest per ray.
#pragma once

#include <cstddef>
#include <cstdint>

#include "radcl/device_types.h"

namespace radcl::render {

struct CompiledScene;

struct MaterialTraits {
  bool shaded = false; // the kernels implement it; a scene with any other is refused by name
  // The real arguments the kernels read, where the count is fixed (Radiance refuses others);
  // min_reals < 0: any count.
  int min_reals = -1, max_reals = -1;
  // A shadow ray that meets it is blocked, whatever the ray carries (rc_shadow_at's last case:
  // the opaque reflectors): the host decides such rays without a step on the device.
  bool blocks_shadows = false;
  // rtrace's unmirrored length goes on through it (m_glass, m_dielectric: the image lies
  // behind it): always, on flat surfaces only, or as its arguments say (trans: where pure
  // specular transmission outweighs the diffuse parts).
  enum class SeenThrough { No, Always, WhenFlat, ByArguments };
  SeenThrough seen_through = SeenThrough::No;
};

const MaterialTraits& material_traits(rc_object_type t);

// Whether the kernels read `n` real arguments of a material of kind t.
bool real_count_ok(rc_object_type t, std::size_t n);

// Whether rtrace's lengths see through compiled material `material` at a hit on a flat
// (polygon, ring) or curved surface.
bool seen_through(const CompiledScene& cs, std::uint32_t material, bool flat);

} // namespace radcl::render
