#include "radcl/ambient/spread_choice.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace radcl::ambient {

namespace {

using Key = std::array<std::int64_t, 4>; // level, cell x, y, z

Key key_of(const rc_ray& m, double sep) {
  return {static_cast<std::int64_t>(m.ambient_depth),
          static_cast<std::int64_t>(std::floor(m.org.x / sep)),
          static_cast<std::int64_t>(std::floor(m.org.y / sep)),
          static_cast<std::int64_t>(std::floor(m.org.z / sep))};
}

constexpr std::uint32_t kNoCell = 0xFFFFFFFFu;

} // namespace

std::vector<std::uint32_t> choose_spread(std::span<const rc_ray> miss, double sep) {
  const std::size_t n = miss.size();
  std::vector<std::uint32_t> chosen;
  if (n == 0) return chosen;
  // Every miss's cell, numbered in order of first appearance through an open-addressing table
  // of cell numbers (most misses share a cell with many others).
  std::vector<Key> key(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) { key[i] = key_of(miss[i], sep); });
  std::size_t size = 64;
  while (size < 2 * n)
    size *= 2;
  std::vector<std::uint32_t> table(size, kNoCell);
  std::vector<Key> cells;
  auto slot_of = [&](const Key& k) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::int64_t v : k)
      h = (h ^ static_cast<std::uint64_t>(v)) * 0xBF58476D1CE4E5B9ull;
    std::size_t at = static_cast<std::size_t>(h ^ (h >> 29)) & (size - 1);
    while (table[at] != kNoCell && cells[table[at]] != k)
      at = (at + 1) & (size - 1);
    return at;
  };
  std::vector<std::uint32_t> cell_of(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t at = slot_of(key[i]);
    if (table[at] == kNoCell) {
      table[at] = static_cast<std::uint32_t>(cells.size());
      cells.push_back(key[i]);
    }
    cell_of[i] = table[at];
  }
  auto find = [&](const Key& k) { return table[slot_of(k)]; };
  // Each cell's occupied neighbours, its own first (where misses are dense, a chosen one that
  // rules a miss out lies there).
  std::vector<std::array<std::uint32_t, 27>> around(cells.size());
  tbb::parallel_for(std::size_t{0}, cells.size(), [&](std::size_t c) {
    std::array<std::uint32_t, 27>& a = around[c];
    a.fill(kNoCell);
    a[0] = static_cast<std::uint32_t>(c);
    std::size_t k = 1;
    for (int d = 0; d < 27; ++d) {
      if (d == 13) continue; // the cell itself
      Key nb = cells[c];
      nb[1] += d / 9 - 1;
      nb[2] += d / 3 % 3 - 1;
      nb[3] += d % 3 - 1;
      if (const std::uint32_t id = find(nb); id != kNoCell) a[k++] = id;
    }
  });
  // The sequential rule; each cell's chosen misses listed (a cell rarely holds more than a few).
  std::vector<std::vector<std::uint32_t>> in_cell(cells.size());
  const double sep2 = sep * sep;
  for (std::size_t i = 0; i < n; ++i) {
    const rc_ray& m = miss[i];
    bool near = false;
    for (std::uint32_t c : around[cell_of[i]]) {
      if (c == kNoCell) break;
      for (std::uint32_t j : in_cell[c]) {
        const rc_ray& o = miss[j];
        const double ex = m.org.x - o.org.x, ey = m.org.y - o.org.y, ez = m.org.z - o.org.z;
        const double facing = m.dir.x * o.dir.x + m.dir.y * o.dir.y + m.dir.z * o.dir.z;
        if (facing > 0.5 && ex * ex + ey * ey + ez * ez < sep2) {
          near = true;
          break;
        }
      }
      if (near) break;
    }
    if (near) continue;
    in_cell[cell_of[i]].push_back(static_cast<std::uint32_t>(i));
    chosen.push_back(static_cast<std::uint32_t>(i));
  }
  return chosen;
}

} // namespace radcl::ambient
