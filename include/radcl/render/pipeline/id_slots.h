// Slot of a ray id within one batch: the renderer's rays carry ids (their random numbers' key)
// that are mostly a compact range (input indices, a call's hemisphere samples), so a flat table
// over [min, max] answers in one load and holds 4 bytes per id; scattered ids fall back to a
// hash map. A hash map over the millions of samples of one cache-build round cost time and
// memory.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "radcl/util/error.h"

namespace radcl::render {

class IdSlots {
public:
  // ids[k] is the id of slot k; ids must be unique.
  void assign(std::span<const std::uint32_t> ids) {
    flat_.clear();
    map_.clear();
    if (ids.empty()) return;
    const auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
    const std::uint64_t range = std::uint64_t{*hi} - *lo + 1;
    if (range <= 4 * std::uint64_t{ids.size()} + 1024) {
      base_ = *lo;
      flat_.assign(range, kNone);
      for (std::size_t k = 0; k < ids.size(); ++k)
        flat_[ids[k] - base_] = static_cast<std::uint32_t>(k);
    } else {
      map_.reserve(ids.size());
      for (std::size_t k = 0; k < ids.size(); ++k)
        map_[ids[k]] = static_cast<std::uint32_t>(k);
    }
  }
  void clear() {
    flat_.clear();
    map_.clear();
  }
  bool empty() const { return flat_.empty() && map_.empty(); }
  std::uint32_t at(std::uint32_t id) const {
    if (!flat_.empty()) {
      if (id >= base_ && id - base_ < flat_.size() && flat_[id - base_] != kNone)
        return flat_[id - base_];
    } else if (auto it = map_.find(id); it != map_.end()) {
      return it->second;
    }
    throw FatalError("renderer: ray id " + std::to_string(id) + " is not in the batch");
  }

private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::uint32_t base_ = 0;
  std::vector<std::uint32_t> flat_;
  std::unordered_map<std::uint32_t, std::uint32_t> map_;
};

} // namespace radcl::render
