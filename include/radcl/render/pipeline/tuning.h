// How the pipeline runs, as opposed to what it computes (RenderSettings): sizes, overlaps and
// waits that give the same bits whichever way they are set (tests/render/pipeline/
// determinism.cpp, tests/cli/stability_determinism.cpp), and the switches that measure a part
// by turning it off. The programs fill it once from RADCL_* variables (src/cli/
// pipeline_tuning.cpp; the variables are listed in docs/devices.md); tests set its fields.
#pragma once

#include <cstddef>

namespace radcl::render {

struct PipelineTuning {
  // RADCL_PROFILE: 1 prints the time by phase when the renderer ends; waves also waits for each
  // step of a shading slice on its own; raw also times Embree alone on every traced chunk.
  enum class Profile { Off, Phases, Waves, Raw };
  Profile profile = Profile::Off;
  // Rays of a generation traced and shaded together (RADCL_CHUNK_RAYS); 0: the device's size.
  std::size_t chunk_rays = 0;
  // The largest generation a batch of primaries may make without the cache
  // (RADCL_GENERATION_RAYS); 0: the device's size.
  std::size_t generation_rays = 0;
  // A shading slice's slots at most (RADCL_WAVE_BYTES).
  std::size_t slice_bytes = std::size_t{1} << 26;
  // The next chunk traced while this one is shaded (RADCL_NO_OVERLAP turns it off).
  bool overlap = true;
  // The tracing ahead at normal priority instead of low (RADCL_AHEAD_NORMAL).
  bool ahead_normal_priority = false;
  // A slice's reads gathered into few waits (RADCL_FEWER_WAITS=0: a wait each).
  bool fewer_waits = true;
  // On a GPU a slice's children read back while its shadow rays are traced
  // (RADCL_CHILDREN_LATER=0: before).
  bool children_later = true;
  // The -as tally fed beside the shading (RADCL_TALLY_BESIDE=1 or 0); -1: the device decides.
  int tally_beside = -1;
  // On a GPU each generation kept on the device for the next (RADCL_MIRROR=0: uploaded).
  bool keep_generations_on_device = true;
  // Shadow rays that meet a blocker decided on the host (RADCL_SHADOW_ON_HOST=0: every ray
  // stepped on the device, the tests' reference).
  bool shadow_blockers_on_host = true;
  // Radiance's leak test for cache lookups (RADCL_LEAK_TEST=0 leaves it out, to time it: this
  // one changes results).
  bool leak_test = true;
  // The cache's passes reported on standard error (RADCL_DEBUG_CACHE).
  bool debug_cache = false;
};

} // namespace radcl::render
