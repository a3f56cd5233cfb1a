// The shading kernels' launches: rc_shade (its scene arguments, its count mode, the slot sizes
// a chunk gets, rays shaded again into exact room) and rc_pack. shade_slice.cpp runs them.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>

#include "pipeline_util.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

void Renderer::Impl::set_scene_args(device::Kernel& k, unsigned first) {
  k.arg(first, surfaces)
      .arg(first + 1, materials)
      .arg(first + 2, args)
      .arg(first + 3, sources)
      .arg(first + 4, verts)
      .arg(first + 5, mirror_surfaces)
      .arg(first + 6, params)
      .arg(first + 7, patterns)
      .arg(first + 8, amb_records.buffer())
      .arg(first + 9, amb_nodes.buffer())
      .arg(first + 10, amb_blocked.buffer());
}

void Renderer::Impl::run_shade(const ShadeLaunch& l, std::size_t n) {
  shade.arg(0, *l.rays).arg(1, *l.hits).arg(2, static_cast<std::uint32_t>(n));
  set_scene_args(shade, 3);
  shade.arg(kSceneArgs + 3, *l.shadow_off)
      .arg(kSceneArgs + 4, *l.spawn_off)
      .arg(kSceneArgs + 5, *l.shadows)
      .arg(kSceneArgs + 6, *l.spawned)
      .arg(kSceneArgs + 7, *l.immediate)
      .arg(kSceneArgs + 8, l.super)
      .arg(kSceneArgs + 9, l.super_off ? *l.super_off : *l.shadow_off)
      .arg(kSceneArgs + 10, l.super_data ? *l.super_data : *l.shadow_off)
      .arg(kSceneArgs + 11, l.cap_shadow)
      .arg(kSceneArgs + 12, l.cap_spawn)
      .arg(kSceneArgs + 13, l.nshadow ? *l.nshadow : *l.shadow_off)
      .arg(kSceneArgs + 14, l.nspawn ? *l.nspawn : *l.spawn_off)
      .arg(kSceneArgs + 15, l.cells ? *l.cells : *l.spawn_off)
      .arg(kSceneArgs + 16, std::uint32_t{l.tallies ? 1u : 0u})
      .arg(kSceneArgs + 17, l.tallies ? *l.tallies : *l.spawn_off);
  ctx.run(shade, n);
}

void Renderer::Impl::run_count(device::Buffer& rays, device::Buffer& hits, device::Buffer& nshadow,
                               device::Buffer& nspawn, std::size_t n, device::Buffer* super_off,
                               device::Buffer* super_data) {
  ShadeLaunch l{&rays, &hits, &nshadow, &nspawn, &nshadow, &nshadow, &nshadow};
  l.super = super_off ? 1 : 0;
  l.super_off = super_off;
  l.super_data = super_data;
  l.cap_shadow = l.cap_spawn = 0;
  l.nshadow = &nshadow;
  l.nspawn = &nspawn;
  run_shade(l, n);
}

void Renderer::Impl::size_slots(std::span<const rc_ray> queue, const HitQueue& hits) {
  if (queue.size() <= kUncountedWave) return;
  Timed timed(prof, Phase::Slots);
  std::size_t n = queue.size(), stride = std::max<std::size_t>(1, n / 512);
  std::vector<rc_ray> r;
  std::vector<rc_hit> h;
  for (std::size_t i = stride / 2; i < n; i += stride) {
    r.push_back(queue[i]);
    h.push_back(hits[i]);
  }
  std::size_t m = r.size();
  device::Buffer& brays = scratch(kStepRays, r);
  device::Buffer& bhits = scratch(kStepHits, h);
  device::Buffer& bnshadow = scratch(kNShadow, m * 4);
  device::Buffer& bnspawn = scratch(kNSpawn, m * 4);
  run_count(brays, bhits, bnshadow, bnspawn, m);
  auto quantile = [m](std::vector<std::uint32_t> v) {
    std::size_t k = m * 98 / 100;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
    return std::max<std::uint32_t>(1, v[k]);
  };
  std::vector<std::uint32_t> csh(m), csp(m);
  bnshadow.read_later(csh.data(), m * 4);
  bnspawn.read_later(csp.data(), m * 4);
  ctx.finish();
  cap_shadow = quantile(std::move(csh));
  cap_spawn = quantile(std::move(csp));
}

void Renderer::Impl::reshade(const rc_ray* rays, const rc_hit* hit,
                             const std::vector<std::uint32_t>& over,
                             const std::vector<std::uint32_t>& nsp,
                             const std::vector<std::uint32_t>& shadow_off,
                             const std::vector<std::uint32_t>& spawn_off, device::Buffer& shadows,
                             rc_ray* children, device::Buffer* into, std::size_t base) {
  std::size_t m = over.size();
  std::vector<rc_ray> r(m);
  std::vector<rc_hit> h(m);
  std::vector<std::uint32_t> soff(m), poff(m);
  for (std::size_t k = 0; k < m; ++k) {
    r[k] = rays[over[k]];
    h[k] = hit[over[k]];
    soff[k] = shadow_off[over[k]]; // straight into their packed places
    // Children: where the device keeps the next generation, straight into their places there
    // (the others are there already), which is then read whole; else into room of their own.
    poff[k] = into ? static_cast<std::uint32_t>(base + spawn_off[over[k]]) : nsp[over[k]];
  }
  const std::uint32_t tsp = into ? 0 : prefix_sum(poff);
  device::Buffer& brays = scratch(kStepRays, r);
  device::Buffer& bhits = scratch(kStepHits, h);
  device::Buffer& bsoff = scratch(kSuperOff, soff);
  device::Buffer& bpoff = scratch(kSuperData, poff);
  device::Buffer& bsp = into ? *into : scratch(kSpawned, std::size_t{tsp} * sizeof(rc_ray));
  device::Buffer& bimm = scratch(kTotal, m * sizeof(rc_float4));
  run_shade(ShadeLaunch{&brays, &bhits, &bsoff, &bpoff, &shadows, &bsp, &bimm}, m);
  if (into) {
    const std::size_t total = spawn_off.back() + nsp.back();
    into->read_later(children, total * sizeof(rc_ray), base * sizeof(rc_ray));
    ctx.finish();
    return;
  }
  std::vector<rc_ray> sp(tsp);
  bsp.read_later(sp.data(), sp.size() * sizeof(rc_ray));
  ctx.finish();
  for (std::size_t k = 0; k < m; ++k)
    std::copy_n(sp.data() + poff[k], nsp[over[k]], children + spawn_off[over[k]]);
}

void Renderer::Impl::run_pack(device::Buffer& slot_sh, device::Buffer& slot_sp,
                              device::Buffer& nshadow, device::Buffer& nspawn,
                              device::Buffer& shadow_off, device::Buffer& spawn_off, std::size_t n,
                              bool with_spawn, device::Buffer& shadows, device::Buffer& spawned) {
  pack.arg(0, slot_sh)
      .arg(1, slot_sp)
      .arg(2, nshadow)
      .arg(3, nspawn)
      .arg(4, shadow_off)
      .arg(5, spawn_off)
      .arg(6, static_cast<std::uint32_t>(n))
      .arg(7, cap_shadow)
      .arg(8, cap_spawn)
      .arg(9, throwaway ? 0u : 1u)
      .arg(10, with_spawn ? 1u : 0u)
      .arg(11, shadows)
      .arg(12, spawned);
  ctx.run(pack, n);
}

} // namespace radcl::render
