// The irradiance cache's records in the form the lookup kernel reads (kernels/render/
// ambient_cache.cl): decoded, re-centred records in BVH leaf order and the flattened BVH over
// their regions, built with Embree's BVH builder.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "radcl/ambient/record.h"
#include "radcl/device_types.h"

namespace radcl::render {

struct AmbientCacheBuffers {
  std::vector<rc_amb_record> records; // in leaf order
  std::vector<rc_amb_node> nodes;     // depth first; empty when there are no records
  std::vector<std::uint32_t> corral;  // each record's corral bits, in leaf order (host only)
  std::vector<std::uint32_t> source;  // each record's index in the input span (host only)
};

// `centre`: the scene's re-centring origin; `aa`: -aa (a record covers points within aa times
// its radii). Records of zero radius (which Radiance never stores) are left out.
AmbientCacheBuffers build_ambient_cache(std::span<const ambient::AmbientRecord> records,
                                        const std::array<double, 3>& centre, double aa);

// One tree over `a`'s and `b`'s records: a root over both, then `a`'s nodes, then `b`'s (leaf
// order: a's records, then b's; b's `source` indices are raised by `b_offset`, the count of
// records a was built from). The cache grows by a small tree over its newest records joined to
// the large one over the rest, so a record added to 100,000 does not rebuild them all.
AmbientCacheBuffers join_ambient_caches(const AmbientCacheBuffers& a, const AmbientCacheBuffers& b,
                                        std::uint32_t b_offset);

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

} // namespace radcl::render
