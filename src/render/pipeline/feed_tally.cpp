// The -as tally tree fed a shaded slice, beside the shading of the next one.
#include "renderer_impl.h"

namespace radcl::render {

void Renderer::Impl::feed_tally(const rc_ray* rays, const rc_hit* hit, rc_ray* children,
                                std::size_t n) {
  ShadeScratch& x = shade_scratch;
  // In line where there is no core to spare, where its steps are timed, and where the cache's
  // passes move children about.
  const bool beside = tally_beside_env < 0 ? !ctx.zero_copy() : tally_beside_env == 1;
  if (!beside || prof.waves() || collecting) {
    tally.shaded_slice(rays, hit, x.total.data(), children, x.spawn_off.data(), x.nsp.data(),
                       x.cells.data(), n);
    return;
  }
  wait_tally();
  // The slice's vectors go to the task; shade_scratch gets the last task's room back.
  std::swap(tally_in.total, x.total);
  std::swap(tally_in.spawn_off, x.spawn_off);
  std::swap(tally_in.nsp, x.nsp);
  std::swap(tally_in.cells, x.cells);
  tally_hits = std::span<const rc_hit>(hit, n);
  tally_pending = true;
  ahead_arena.execute([&] {
    tally_task.run([this, rays, hit, children, n] {
      Timed timed(prof, Phase::Tally);
      tally.shaded_slice(rays, hit, tally_in.total.data(), children, tally_in.spawn_off.data(),
                         tally_in.nsp.data(), tally_in.cells.data(), n);
    });
  });
}

void Renderer::Impl::wait_tally() {
  if (!tally_pending) return;
  tally_pending = false;
  tally_hits = {};
  ahead_arena.execute([&] { tally_task.wait(); });
}

bool Renderer::Impl::tally_reads(const HitQueue& h) const {
  if (!tally_pending || tally_hits.empty() || h.capacity() == 0) return false;
  const rc_hit* a = h.data();
  const rc_hit* b = a + h.capacity();
  return tally_hits.data() < b && a < tally_hits.data() + tally_hits.size();
}

} // namespace radcl::render
