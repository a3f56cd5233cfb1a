// The irradiance cache's records as the lookups and the leak test read them: a forest of BVHs
// over consecutive ranges of the records, each at most half the size of the one before (or
// small), laid one after another; records joining rebuild only the last tree, so a build that
// uploads thousands of times costs O(n log n), and the device keeps the rest. Beside it the same
// forest over the corral-marked records alone, which the leak tests walk on the host.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "radcl/ambient/cache.h"
#include "radcl/ambient/record.h"

namespace radcl::render {

class CacheForest {
public:
  // Where the last update changed the lookup buffers: from these nodes and records on (what
  // comes before is as the device has it); none when nothing changed.
  struct Change {
    bool any = false;
    std::size_t nodes = 0, records = 0;
  };
  // Brings the forest to records [0, n) of `local` (re-centred records, in the order they
  // joined); fewer than before rebuilds it whole. With `marked`, the marked records' forest
  // too.
  Change update(std::span<const ambient::AmbientRecord> local, std::size_t n, double aa,
                bool marked);
  bool empty() const { return trees_.empty(); }
  const ambient::AmbientCacheBuffers& lookup() const { return cache_; }
  const ambient::AmbientCacheBuffers& marked() const { return marked_; }
  // Leaf in marked() -> leaf in lookup().
  const std::vector<std::uint32_t>& to_full() const { return to_full_; }

private:
  struct Tree {
    std::size_t from = 0, to = 0;         // range of the records
    std::size_t nodes = 0, records = 0;   // where it begins in cache_
    std::size_t mnodes = 0, mrecords = 0; // where its marked records' tree begins in marked_
    std::size_t msrc = 0;                 // where its marked inputs begin in marked_src_
  };
  static constexpr std::size_t kSmallTree = 256; // a tree this small absorbs the next
  void add_tree(std::size_t n);
  void build_marked(std::span<const ambient::AmbientRecord> local, const Tree& last, double aa);

  ambient::AmbientCacheBuffers cache_, marked_;
  std::vector<Tree> trees_;
  std::vector<std::uint32_t> marked_src_; // record index of each marked tree input
  std::vector<std::uint32_t> leaf_of_;    // record index -> leaf in cache_
  std::vector<std::uint32_t> to_full_;    // leaf in marked_ -> leaf in cache_
};

} // namespace radcl::render
