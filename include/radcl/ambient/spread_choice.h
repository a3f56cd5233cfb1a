// The cache build's choice of which misses become records (Renderer's make_records): in order,
// a miss is chosen unless a chosen one of its level, facing within 60 degrees, lies within
// `sep` of it. The rule is sequential (each answer depends on the ones before), so the grid of
// cells of side `sep` it searches is laid out first: each miss gets its cell's number (through
// a hash table of cells) and each cell its occupied neighbours (in parallel), and the
// sequential pass reads arrays only.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "radcl/device_types.h"

namespace radcl::ambient {

// Indices into `miss` of the chosen ones, in increasing order. A miss's point is its org.xyz,
// its facing direction dir.xyz, its level ambient_depth.
std::vector<std::uint32_t> choose_spread(std::span<const rc_ray> miss, double sep);

} // namespace radcl::ambient
