#include "cache_forest.h"

namespace radcl::render {

CacheForest::Change CacheForest::update(std::span<const ambient::AmbientRecord> local,
                                        std::size_t n, double aa, bool marked) {
  if (n < (trees_.empty() ? 0 : trees_.back().to)) {
    trees_.clear();
    cache_ = marked_ = ambient::AmbientCacheBuffers{};
    marked_src_.clear();
  }
  if (n <= (trees_.empty() ? 0 : trees_.back().to))
    return trees_.empty() ? Change{true, 0, 0} : Change{};
  add_tree(n);
  // Only the last tree changed: it is rebuilt in place after the ones before it.
  const Tree& last = trees_.back();
  rejoin_ambient_caches(
      cache_, last.nodes, last.records,
      ambient::build_ambient_cache(local.subspan(last.from, last.to - last.from), {0, 0, 0}, aa),
      static_cast<std::uint32_t>(last.from));
  leaf_of_.resize(n);
  for (std::size_t k = last.records; k < cache_.source.size(); ++k)
    leaf_of_[cache_.source[k]] = static_cast<std::uint32_t>(k);
  if (marked) build_marked(local, last, aa);
  return {true, last.nodes, last.records};
}

// The new records make a tree after the others; it absorbs the last one while that is not
// twice its size (or is small), so sizes fall by half or more along the forest: O(log n) trees,
// and each record rebuilt O(log n) times however many uploads a build makes (the open-plan
// floor's makes 1,759 onto up to 225,000 records).
void CacheForest::add_tree(std::size_t n) {
  Tree t;
  t.from = trees_.empty() ? 0 : trees_.back().to;
  t.to = n;
  t.nodes = cache_.nodes.size();
  t.records = cache_.records.size();
  t.mnodes = marked_.nodes.size();
  t.mrecords = marked_.records.size();
  t.msrc = marked_src_.size();
  trees_.push_back(t);
  while (trees_.size() >= 2) {
    Tree& a = trees_[trees_.size() - 2];
    const Tree& b = trees_.back();
    if (2 * (b.to - b.from) < a.to - a.from && a.to - a.from >= kSmallTree) break;
    a.to = b.to;
    trees_.pop_back();
  }
}

// The marked records' trees over the same ranges, their leaves named by their place in cache_
// for the tester.
void CacheForest::build_marked(std::span<const ambient::AmbientRecord> local, const Tree& last,
                               double aa) {
  std::vector<ambient::AmbientRecord> mrecs;
  marked_src_.resize(last.msrc);
  for (std::size_t i = last.from; i < last.to; ++i)
    if (local[i].corral) {
      marked_src_.push_back(static_cast<std::uint32_t>(i));
      mrecs.push_back(local[i]);
    }
  rejoin_ambient_caches(marked_, last.mnodes, last.mrecords,
                        ambient::build_ambient_cache(mrecs, {0, 0, 0}, aa),
                        static_cast<std::uint32_t>(last.msrc));
  to_full_.resize(marked_.source.size());
  for (std::size_t j = last.mrecords; j < to_full_.size(); ++j)
    to_full_[j] = leaf_of_[marked_src_[marked_.source[j]]];
}

} // namespace radcl::render
