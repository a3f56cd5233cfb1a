// The irradiance cache's light-leak test (Radiance's plugaleak,
// ../shared/docs/radiance/ambient-file.md §3), made on the host: a record whose corral bits mark
// the direction of a lookup point is used there only if a short test ray from the point towards the
// record meets nothing. The lookup kernel cannot trace, so before a wave is shaded the host finds,
// for every hit, the marked records the kernel's tests could accept and traces their test rays; the
// kernel then skips the records listed as blocked (kernels/ambient/ambient_cache.cl).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "radcl/ambient/cache.h"

namespace radcl::ambient {

// A lookup the kernel may make at a hit: the point as the kernel sees it (re-centred, float),
// the surface normal facing the ray (Radiance's r->ron), the ray's ambient level and weight;
// `exact_normal` where the kernel looks up with that normal or its reverse (no texture
// perturbs it), so the tester need not widen its direction test.
struct LeakLookup {
  std::array<float, 3> point;
  std::array<double, 3> normal;
  std::uint32_t level = 0;
  float weight = 1;
  bool exact_normal = false;
};

// Whether a segment from `org` (re-centred, on a surface whose normal on the segment's side is
// `normal`) along unit `dir` meets a visible surface before `tmax`.
using SegmentBlocked =
    std::function<bool(const std::array<double, 3>& org, const std::array<double, 3>& dir,
                       double tmax, const std::array<double, 3>& normal)>;

class LeakTester {
public:
  LeakTester() = default;
  // `cache` must outlive the tester; `aa` is -aa, `minarad` Radiance's minimum radius.
  // `to_index` (if given, it too must outlive the tester) maps cache's records to the indices
  // reported: the tester may walk a cache of the marked records only, naming them by their
  // place in the full one.
  LeakTester(const AmbientCacheBuffers* cache, float aa, float minarad,
             const std::vector<std::uint32_t>* to_index = nullptr);

  // Whether any record has corral bits (else no lookup needs a test).
  bool active() const { return marked_ > 0; }

  // Appends to `blocked` the indices (leaf order, or to_index's) of the marked records the
  // kernel could accept at `q` whose test ray is blocked; returns how many test rays were
  // traced.
  std::size_t find(const LeakLookup& q, const SegmentBlocked& segment_blocked,
                   std::vector<std::uint32_t>& blocked) const;

  // Radiance's plugaleak for one record seen from `q` (record index in leaf order): whether
  // the record must not be used there. Exposed for the tests.
  bool leaks(const LeakLookup& q, std::uint32_t record, const SegmentBlocked& segment_blocked,
             bool* traced = nullptr) const;

private:
  const AmbientCacheBuffers* cache_ = nullptr;
  const std::vector<std::uint32_t>* to_index_ = nullptr;
  float aa_ = 0, minarad_ = 0;
  std::size_t marked_ = 0;
};

// Radiance's atan2a (a polynomial arctangent with values in [-pi/2, 3pi/2)), in float as the
// record kernel computes it: corral sectors follow its values.
float corral_atan2a(float y, float x);

} // namespace radcl::ambient
