// The irradiance cache's records in the form the lookup kernel reads (kernels/ambient/
// ambient_cache.cl): decoded, re-centred records in BVH leaf order and the flattened BVH over
// their regions, built with Embree's BVH builder.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "radcl/ambient/record.h"
#include "radcl/device_types.h"

namespace radcl::ambient {

struct AmbientCacheBuffers {
  std::vector<rc_amb_record> records; // in leaf order
  std::vector<rc_amb_node> nodes;     // a forest, depth first; empty when there are no records
  std::vector<std::uint32_t> corral;  // each record's corral bits, in leaf order (host only)
  std::vector<std::uint32_t> source;  // each record's index in the input span (host only)
};

// `centre`: the scene's re-centring origin; `aa`: -aa (a record covers points within aa times
// its radii). Records of zero radius (which Radiance never stores) are left out.
AmbientCacheBuffers build_ambient_cache(std::span<const ambient::AmbientRecord> records,
                                        const std::array<double, 3>& centre, double aa);

// One forest of `a`'s and `b`'s records: `a`'s trees, then `b`'s (leaf order: a's records, then
// b's; b's `source` indices are raised by `b_offset`, the count of records a was built from).
// The cache grows by a small forest over its newest records joined to the large one over the
// rest, so a record added to 100,000 does not rebuild them all.
AmbientCacheBuffers join_ambient_caches(const AmbientCacheBuffers& a, const AmbientCacheBuffers& b,
                                        std::uint32_t b_offset);
// The same in place: `ab` keeps its first `a_nodes` nodes and `a_records` records (a forest
// over those records, as a join left it) and gets b's forest after them, at the cost of b's
// size, not a's (a cache build joins thousands of times onto a forest of 100,000 records).
void rejoin_ambient_caches(AmbientCacheBuffers& ab, std::size_t a_nodes, std::size_t a_records,
                           const AmbientCacheBuffers& b, std::uint32_t b_offset);

// Whether node `nd`'s normal cone can hold a unit normal within angle theta (cosine ct, sine
// st; theta <= pi/2) of unit `n`, or of -n as well when `two_sided` (as the kernel's test in
// kernels/ambient/ambient_cache.cl).
inline bool node_cone_may_hold(const rc_amb_node& nd, const std::array<double, 3>& n, double ct,
                               double st, bool two_sided) {
  double c = nd.bin < 2 ? n[0] : (nd.bin < 4 ? n[1] : n[2]);
  if (nd.bin & 1u) c = -c;
  if (two_sided && c < 0) c = -c;
  // The angle to the axis at most theta + h: its cosine at least cos(theta + h).
  return c >= ct * nd.lo.w - st * nd.hi.w - 1e-6;
}

// Radiance's setambres(): the smallest record radius, the octree cube's size over -ar (1e-5
// when -ar is 0), and the largest, 64 times that but at most a fifth of the cube.
double ambient_min_radius(double cube_size, int ar);
double ambient_max_radius(double cube_size, int ar);

// -aw: the constant ambient value (-av) that rays past the last bounce take, averaged in the
// log domain with the values of the cache's records (Radiance's dumbamb): unchanged when aw <= 0
// or no record has a positive brightness; with a black -av the records' geometric mean times
// 0.5 (grey).
std::array<double, 3> averaged_ambient_value(const std::array<double, 3>& av, int aw,
                                             std::span<const ambient::AmbientRecord> records);

} // namespace radcl::ambient
