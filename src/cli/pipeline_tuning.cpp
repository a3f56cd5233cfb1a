// The pipeline's tuning from the environment, read once per program (render/pipeline/tuning.h
// says what each field does; docs/performance.md lists the variables).
#include "pipeline_tuning.h"

#include <cstdlib>
#include <string_view>

namespace radcl::cli {
namespace {

// A variable's value; null where it is not set.
const char* env(const char* name) { return std::getenv(name); }

bool is_zero(const char* v) { return v && std::string_view(v) == "0"; }

// A count from a non-empty variable, at least 1; `fallback` where it is unset or empty.
std::size_t count(const char* v, std::size_t fallback) {
  if (!v || !*v) return fallback;
  const std::size_t n = std::strtoull(v, nullptr, 10);
  return n < 1 ? 1 : n;
}

} // namespace

render::PipelineTuning tuning_from_environment() {
  render::PipelineTuning t;
  using Profile = render::PipelineTuning::Profile;
  if (const char* p = env("RADCL_PROFILE"))
    t.profile = std::string_view(p) == "waves" ? Profile::Waves
                : std::string_view(p) == "raw" ? Profile::Raw
                                               : Profile::Phases;
  t.chunk_rays = count(env("RADCL_CHUNK_RAYS"), 0);
  t.generation_rays = count(env("RADCL_GENERATION_RAYS"), 0);
  if (const char* b = env("RADCL_WAVE_BYTES")) t.slice_bytes = std::strtoull(b, nullptr, 10);
  t.overlap = !env("RADCL_NO_OVERLAP");
  t.ahead_normal_priority = env("RADCL_AHEAD_NORMAL") != nullptr;
  t.fewer_waits = !is_zero(env("RADCL_FEWER_WAITS"));
  t.children_later = !is_zero(env("RADCL_CHILDREN_LATER"));
  if (const char* e = env("RADCL_TALLY_BESIDE"); e && *e) t.tally_beside = is_zero(e) ? 0 : 1;
  t.keep_generations_on_device = !is_zero(env("RADCL_MIRROR"));
  t.shadow_blockers_on_host = !is_zero(env("RADCL_SHADOW_ON_HOST"));
  t.leak_test = !is_zero(env("RADCL_LEAK_TEST"));
  t.debug_cache = env("RADCL_DEBUG_CACHE") != nullptr;
  return t;
}

} // namespace radcl::cli
