// Stage: shadow rays, stepped through Embree and rc_shadow_step until each reaches its source
// or is blocked.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "pipeline_util.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

void Renderer::Impl::trace_shadows(std::vector<rc_shadow>& shadows,
                                   std::vector<std::uint8_t>& blocked) {
  constexpr std::size_t kChunk = 1u << 18;
  blocked.assign(shadows.size(), 1);
  for (std::size_t a = 0; a < shadows.size(); a += kChunk)
    trace_shadow_chunk(shadows.data() + a, std::min(kChunk, shadows.size() - a),
                       blocked.data() + a);
}

void Renderer::Impl::trace_shadow_chunk(rc_shadow* shadows, std::size_t n, std::uint8_t* blocked) {
  std::vector<std::uint32_t>& slot = shadow_slot;
  std::vector<rc_shadow>& cur = shadow_cur;
  slot.clear();
  cur.clear();
  // Estimates and empty slots of the -dt selection (source RC_NONE) are not rays. Where there
  // are none (a hit with two source samples or fewer writes no estimate), the chunk is copied
  // whole, on every core.
  const bool all_rays =
      std::none_of(shadows, shadows + n, [](const rc_shadow& q) { return q.source == RC_NONE; });
  if (all_rays) {
    cur.resize(n);
    parallel_copy(cur.data(), shadows, n * sizeof(rc_shadow));
    slot.resize(n);
    std::iota(slot.begin(), slot.end(), std::uint32_t{0});
  } else {
    for (std::size_t i = 0; i < n; ++i)
      if (shadows[i].source != RC_NONE) {
        slot.push_back(static_cast<std::uint32_t>(i));
        cur.push_back(shadows[i]);
      }
  }
  std::vector<std::uint32_t>& state = shadow_state;
  state.assign(cur.size(), 0);
  // Radiance traces shadow rays on until their weight vanishes; a glass stack that needs
  // more steps than this contributes nothing measurable.
  constexpr int kMaxSteps = 64;
  for (int step = 0; step < kMaxSteps && !cur.empty(); ++step) {
    std::size_t m = cur.size();
    Timed timed(prof, Phase::ShadowTrace);
    // One pass per ray: the query and its device record.
    std::vector<rc_hit>& hits = shadow_hits;
    hits.resize(m);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 256), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const rc_shadow& s = cur[i];
        const rc_source& src = cs.sources.sources[s.source];
        geometry::Ray ray;
        ray.org = {s.org.x + centre[0], s.org.y + centre[1], s.org.z + centre[2]};
        ray.dir = {s.dir.x, s.dir.y, s.dir.z};
        ray.tmin = s.org.w;
        ray.free_origin = s.org.w > 0; // from an -I meter's point (rc_leave_org)
        ray.tmax =
            src.kind == RC_SRC_DISTANT || !std::isfinite(s.dir.w) ? 1e300 : s.dir.w * 1.001 + 1e-3;
        hits[i] =
            to_device(ray, geom.intersect(ray.org, ray.dir, ray.tmin, ray.tmax, ray.free_origin));
      }
    });
    stats.shadow += m;
    timed.start(Phase::ShadowStep);

    device::Buffer& bcur = scratch(kStepRays, m * sizeof(rc_shadow));
    write_rows(bcur, cur.data(), m * sizeof(rc_shadow));
    device::Buffer& bhits = scratch(kStepHits, m * sizeof(rc_hit));
    write_rows(bhits, hits.data(), m * sizeof(rc_hit));
    device::Buffer& bstate = scratch(kStepState, state);
    std::uint32_t um = static_cast<std::uint32_t>(m);
    shadow_step.arg(0, bcur).arg(1, bhits).arg(2, bstate).arg(3, um);
    set_scene_args(shadow_step, 4);
    ctx.run(shadow_step, m);
    // Into place (no fresh, zeroed vectors); in one wait where they are transfers.
    if (!bcur.zero_copy()) bcur.read_later(cur.data(), m * sizeof(rc_shadow));
    bstate.read_later(state.data(), m * sizeof(std::uint32_t));
    ctx.finish();
    if (bcur.zero_copy()) read_rows(bcur, cur.data(), m * sizeof(rc_shadow));

    std::size_t k = 0;
    for (std::size_t i = 0; i < m; ++i) {
      std::uint32_t status = state[i] & 3u;
      if (status == 1u) { // reached its source
        shadows[slot[i]].contrib = cur[i].contrib;
        blocked[slot[i]] = 0;
      } else if (status == 2u) { // goes on
        cur[k] = cur[i];
        state[k] = state[i];
        slot[k] = slot[i];
        ++k;
      }
    }
    cur.resize(k);
    state.resize(k);
    slot.resize(k);
  }
}

} // namespace radcl::render
