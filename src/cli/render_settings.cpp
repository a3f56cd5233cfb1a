#include "render_settings.h"

#include <cstdlib>
#include <ctime>
#include <unistd.h>

namespace radcl::cli {

render::RenderSettings render_settings(const options::RenderOptions& r) {
  render::RenderSettings s;
  s.ds = r.direct_sampling;
  s.dj = r.direct_jitter;
  s.dt = r.direct_threshold;
  s.dc = r.direct_certainty;
  s.dv = r.direct_visible;
  s.bv = r.back_visible;
  s.dr = r.direct_relays;
  s.dp = r.direct_pretest;
  s.ss = r.specular_sampling;
  s.st = r.specular_threshold;
  s.av = r.ambient_value;
  s.ab = r.ambient_bounces;
  s.ad = r.ambient_divisions;
  s.as = r.ambient_supersamples;
  if (r.ambient_list.kind != options::ModifierList::Kind::None) {
    s.ambient_list = r.ambient_list.kind == options::ModifierList::Kind::Include
                         ? render::RenderSettings::AmbientList::Include
                         : render::RenderSettings::AmbientList::Exclude;
    s.ambient_names = r.ambient_list.names;
  }
  s.lr = r.max_depth;
  s.lw = r.min_weight;
  s.irradiance_i = r.irradiance;
  s.seed =
      r.uncorrelated ? static_cast<std::uint32_t>(std::time(nullptr) ^ (::getpid() << 16)) : 0u;
  // RADCL_SEED fixes -u+'s seed, so independent renders can be repeated (tests, averaging).
  if (const char* seed = std::getenv("RADCL_SEED"); seed && r.uncorrelated)
    s.seed = static_cast<std::uint32_t>(std::strtoul(seed, nullptr, 10));
  return s;
}

} // namespace radcl::cli
