// Trace mode: each primary's ray tree as rtrace's -tr and -trs report it.
#include "pipeline_util.h"
#include "radcl/render/lights/virtual_sources.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

std::vector<TracedRay> Renderer::Impl::traced(std::size_t primary) const {
  std::vector<TracedRay> out;
  for (const auto& [t, depth] : tally.traced(primary)) {
    if (depth == 0 && settings.irradiance_I) continue;
    TracedRay r;
    r.depth = depth;
    if (t->is_shadow) {
      const rc_shadow& s = t->shadow.request;
      r.shadow = true;
      r.org = {s.org.x + centre[0], s.org.y + centre[1], s.org.z + centre[2]};
      r.dir = {s.dir.x, s.dir.y, s.dir.z};
      // The source's radiance as the shadow ray brought it back, and the factor that made
      // its contribution.
      const rc_source& src = cs.sources.sources[s.source];
      const float e[3] = {src.emit.x, src.emit.y, src.emit.z};
      const float c0[3] = {s.contrib.x, s.contrib.y, s.contrib.z};
      const float c1[3] = {t->shadow.arrived.x, t->shadow.arrived.y, t->shadow.arrived.z};
      for (int i = 0; i < 3; ++i) {
        double pass = !t->shadow.blocked && c0[i] > 0 ? c1[i] / c0[i] : 0.0;
        r.value[i] = e[i] * pass;
        r.coef[i] = e[i] > 0 ? c0[i] / e[i] : 0.0;
        r.contribution[i] = t->shadow.blocked ? 0.0 : c1[i];
      }
      r.weight = 1;
      if (!t->shadow.blocked) { // it met its source
        if (src.kind == RC_SRC_DISTANT) {
          r.surface = distant_surface(cs, geom, r.dir);
        } else {
          r.surface = src.surface;
          r.hit = true;
          r.t = s.dir.w;
          for (int i = 0; i < 3; ++i)
            r.point[i] = r.org[i] + r.t * r.dir[i];
        }
      }
      if (!r.hit) r.point = r.org;
      out.push_back(r);
      continue;
    }
    const rc_ray& q = t->ray;
    const rc_hit& h = t->hit;
    r.org = {q.org.x + centre[0], q.org.y + centre[1], q.org.z + centre[2]};
    r.dir = {q.dir.x, q.dir.y, q.dir.z};
    r.weight = q.coef.w;
    const Vec3d& sum = tally.node_sum(t->node);
    const float c[3] = {q.coef.x, q.coef.y, q.coef.z};
    for (int i = 0; i < 3; ++i) {
      r.coef[i] = c[i];
      r.contribution[i] = sum[i];
      r.value[i] = c[i] > 0 ? sum[i] / c[i] : 0.0;
    }
    r.surface = h.surface < cs.surfaces.size() ? h.surface : RC_NONE;
    r.point = r.org;
    if (h.surface != RC_NONE && h.pos.w >= 0) {
      r.hit = true;
      r.t = h.pos.w;
      r.point = {h.pos.x + centre[0], h.pos.y + centre[1], h.pos.z + centre[2]};
      r.normal = {h.nrm.x, h.nrm.y, h.nrm.z};
    }
    out.push_back(r);
  }
  return out;
}

} // namespace radcl::render
