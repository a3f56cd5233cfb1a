#include "radcl/ambient/record_maker.h"

#include <algorithm>
#include <cmath>

#include "radcl/ambient/dircode.h"
#include "radcl/device/buffer.h"
#include "radcl/device/context.h"

namespace radcl::ambient {
namespace {

rc_float4 f4(double x, double y, double z, double w) {
  return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z),
          static_cast<float>(w)};
}

} // namespace

float ambient_record_weight(int level, double ray_weight) {
  double w = 1.0;
  for (int i = 0; i < level; ++i)
    w *= kAvgRefl;
  if (ray_weight < 0.1 * w) w = 1.25 * ray_weight; // makeambient's heuristic override
  return static_cast<float>(w);
}

rc_amb_hemi make_hemisphere(const std::array<double, 3>& p, const std::array<double, 3>& n,
                            const std::array<double, 3>& ux, unsigned ns, unsigned first, int level,
                            double weight, const HemisphereSettings& s) {
  const std::array<double, 3> uy{n[1] * ux[2] - n[2] * ux[1], n[2] * ux[0] - n[0] * ux[2],
                                 n[0] * ux[1] - n[1] * ux[0]};
  rc_amb_hemi h{};
  h.pos = f4(p[0], p[1], p[2], weight);
  h.nrm = f4(n[0], n[1], n[2], s.minarad);
  h.ux = f4(ux[0], ux[1], ux[2], s.maxarad);
  h.uy = f4(uy[0], uy[1], uy[2], s.aa);
  h.first = first;
  h.ns = ns;
  h.level = static_cast<std::uint32_t>(level);
  return h;
}

RecordMaker::RecordMaker(device::Context& ctx)
    : ctx_(ctx), program_(ctx, device::ProgramSource{{"ambient/ambient_record.cl"}, "", ""}),
      kernel_(program_.kernel("rc_make_record")) {}

void RecordMaker::run(const device::Buffer& hemis, const device::Buffer& samples,
                      std::uint32_t count, device::Buffer& records, device::Buffer& made) {
  if (count == 0) return;
  kernel_.arg(0, hemis).arg(1, samples).arg(2, count).arg(3, records).arg(4, made);
  ctx_.run(kernel_, std::size_t{count} * RC_AMR_GROUP, RC_AMR_GROUP);
}

device::Buffer& RecordMaker::room(device::Buffer& b, std::size_t bytes) {
  if (b.size() < bytes) b = device::Buffer(ctx_, bytes + bytes / 2);
  return b;
}

MadeRecords RecordMaker::make(std::span<const rc_amb_hemi> hemis,
                              std::span<const rc_amb_sample> samples) {
  MadeRecords out;
  if (hemis.empty()) return out;
  const auto n = static_cast<std::uint32_t>(hemis.size());
  // The buffers are kept between calls (a cache build makes records in many small calls).
  device::Buffer& bh = room(hemis_, hemis.size_bytes());
  bh.write(hemis.data(), hemis.size_bytes());
  device::Buffer& bs = room(samples_, std::max<std::size_t>(samples.size_bytes(), 1));
  if (!samples.empty()) bs.write(samples.data(), samples.size_bytes());
  device::Buffer& br = room(records_, n * sizeof(rc_amb_record));
  device::Buffer& bm = room(made_, n * sizeof(rc_amb_made));
  run(bh, bs, n, br, bm);
  out.records.resize(n);
  out.made.resize(n);
  br.read_later(out.records.data(), n * sizeof(rc_amb_record));
  bm.read_later(out.made.data(), n * sizeof(rc_amb_made));
  ctx_.finish();
  return out;
}

ambient::AmbientRecord to_ambient_record(const rc_amb_record& r, std::uint32_t corral,
                                         const std::array<double, 3>& centre) {
  ambient::AmbientRecord a;
  a.pos = {static_cast<float>(r.pos.x + centre[0]), static_cast<float>(r.pos.y + centre[1]),
           static_cast<float>(r.pos.z + centre[2])};
  a.ndir = ambient::encode_dir({r.nrm.x, r.nrm.y, r.nrm.z});
  a.udir = ambient::encode_dir({r.udir.x, r.udir.y, r.udir.z});
  a.lvl = static_cast<std::int16_t>(std::lround(r.val.w));
  a.weight = r.pos.w;
  a.rad = {r.nrm.w, r.udir.w};
  a.val = {r.val.x, r.val.y, r.val.z};
  a.gpos = {r.grad.x, r.grad.y};
  a.gdir = {r.grad.z, r.grad.w};
  a.corral = corral;
  return a;
}

} // namespace radcl::ambient
