// Stage (rcontrib): a shaded slice's contributions into its primaries' bins. Each ray's own
// (rc_shade wrote it where rtrace keeps the immediate value) and each of its shadow requests'
// (rc_accumulate_contrib, which drops the blocked ones and finds their bins), added on the
// host in ray order, request order within a ray, so the double sums do not depend on slice
// or wave sizes.
#include <bit>

#include "pipeline_util.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace pipeline;

void Renderer::Impl::add_slice_contrib(const ShadeSlice& s) {
  ShadeScratch& x = shade_scratch;
  const std::size_t n = s.n;
  const std::uint32_t nshadow = s.total_shadows;
  // x.total: the rays' own contributions, read with the slice's counts (launch_slice); rays
  // shaded again write the same values.
  std::vector<rc_float4>& sh = contrib_requests;
  sh.resize(nshadow);
  if (nshadow > 0) {
    device::Buffer& out = scratch(kContrib, std::size_t{nshadow} * sizeof(rc_float4));
    accumulate_contrib.arg(0, *s.shadows)
        .arg(1, scratch(kBlocked, std::size_t{nshadow}))
        .arg(2, nshadow);
    set_scene_args(accumulate_contrib, 3);
    accumulate_contrib.arg(3 + kSceneArgs, out);
    ctx.run(accumulate_contrib, nshadow);
    read_rows(out, sh.data(), sh.size() * sizeof(rc_float4));
  }
  const std::size_t bins = settings.contrib->total_bins();
  const auto add = [&](std::uint32_t primary, const rc_float4& c) {
    const auto bin = std::bit_cast<std::uint32_t>(c.w);
    if (bin == RC_NONE) return;
    if (bin >= bins) {
      ++stats.bad_bins; // Radiance: "bad bin number (n ignored)"
      return;
    }
    double* d = batch.contrib.data() + slot(primary) * 3 * bins + 3 * std::size_t{bin};
    d[0] += c.x;
    d[1] += c.y;
    d[2] += c.z;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t primary = s.rays[i].primary;
    add(primary, x.total[i]);
    const std::size_t end = i + 1 < n ? x.shadow_off[i + 1] : nshadow;
    for (std::size_t k = x.shadow_off[i]; k < end; ++k)
      add(primary, sh[k]);
  }
}

} // namespace radcl::render
