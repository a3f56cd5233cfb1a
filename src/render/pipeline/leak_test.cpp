// Stage: Radiance's leak test for the cache records a chunk's lookups may use.
#include <cstring>

#include "pipeline_util.h"
#include "radcl/scene/object_type.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

void Renderer::Impl::test_leaks(std::span<const rc_ray> queue, HitQueue& hits) {
  if (!leak_tester.active()) return;
  Timed timed(prof, Phase::Leaks);
  const std::size_t n = queue.size();
  const double eps = ray_eps;
  auto segment_blocked = [&](const std::array<double, 3>& o, const std::array<double, 3>& d,
                             double tmax, const std::array<double, 3>& n) {
    // From beside the surface, as the kernels' rays leave it (rc_leave).
    const double lv = leave_dist(o[0], o[1], o[2]);
    Vec3d org = {o[0] + centre[0] + lv * n[0], o[1] + centre[1] + lv * n[1],
                 o[2] + centre[2] + lv * n[2]};
    const Vec3d dir = {d[0], d[1], d[2]};
    double t0 = RC_TMIN_OFF;
    for (int k = 0; k < 64; ++k) { // void surfaces are passed, as Radiance passes them
      std::optional<geometry::Hit> h = geom.intersect(org, dir, t0, tmax);
      if (!h) return false;
      const std::uint32_t s = cs.surface_of(*h);
      if (s < cs.surfaces.size() && cs.surfaces[s].material != RC_NONE) return true;
      t0 = h->t + eps;
    }
    return true;
  };
  constexpr std::size_t kGrain = 256;
  const std::size_t nchunks = (n + kGrain - 1) / kGrain;
  std::vector<std::vector<std::uint32_t>> lists(nchunks);
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> at(nchunks);
  std::vector<std::size_t> traced(nchunks, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nchunks), [&](const auto& range) {
    std::vector<std::uint32_t> found;
    for (std::size_t c = range.begin(); c != range.end(); ++c)
      for (std::size_t i = c * kGrain; i < std::min(n, (c + 1) * kGrain); ++i) {
        const rc_ray& r = queue[i];
        const rc_hit& h = hits[i];
        if (static_cast<int>(r.ambient_depth) >= settings.ab) continue;
        if (h.surface != RC_SURF_IRRADIANCE) {
          if (h.surface >= cs.surfaces.size() || h.pos.w < 0) continue;
          const rc_surface& sf = cs.surfaces[h.surface];
          if (sf.material == RC_NONE || sf.source != RC_NONE || (sf.flags & RC_SURFF_NO_AMBIENT))
            continue;
        }
        LeakLookup q;
        q.point = {h.pos.x, h.pos.y, h.pos.z};
        if (h.surface == RC_SURF_IRRADIANCE) {
          q.exact_normal = true;
        } else {
          const rc_material& m = cs.materials[cs.surfaces[h.surface].material];
          q.exact_normal =
              m.npatterns == 0 && !scene::is_mixture(static_cast<scene::ObjectType>(m.type));
        }
        // The normal facing the ray (a -I meter faces its given direction).
        const double f = h.surface == RC_SURF_IRRADIANCE || h.front ? 1.0 : -1.0;
        q.normal = {f * h.nrm.x, f * h.nrm.y, f * h.nrm.z};
        q.level = r.ambient_depth;
        q.weight = r.coef.w;
        found.clear();
        traced[c] += leak_tester.find(q, segment_blocked, found);
        if (found.empty()) continue;
        at[c].push_back(
            {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(lists[c].size())});
        lists[c].push_back(static_cast<std::uint32_t>(found.size()));
        lists[c].insert(lists[c].end(), found.begin(), found.end());
      }
  });
  for (std::size_t c = 0; c < nchunks; ++c) {
    stats.leak_tests += traced[c];
    const std::uint32_t base_off = static_cast<std::uint32_t>(leak_lists.size());
    for (const auto& [i, off] : at[c]) {
      const std::uint32_t code = base_off + off + 1; // 0: no list
      std::memcpy(&hits[i].nrm.w, &code, sizeof code);
      ++stats.leaks;
    }
    leak_lists.insert(leak_lists.end(), lists[c].begin(), lists[c].end());
  }
  if (leak_lists.size() != leak_uploaded) {
    amb_blocked.update(ctx, leak_lists, leak_uploaded);
    leak_uploaded = leak_lists.size();
  }
}

} // namespace radcl::render
