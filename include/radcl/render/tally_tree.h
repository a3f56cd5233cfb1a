// Where a batch's contributions add up when they cannot go straight to their primary ray.
// Normally every ray adds into its primary's sum. With -as, the first samples of a hemisphere
// add into one cell per division; once every ray below a hemisphere has finished, the cells'
// values decide where the super-samples go (Radiance's ambsupersamp), and once those have
// finished too, the hemisphere adds the sum of its divisions' averages into its parent.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "radcl/device_types.h"

namespace radcl::render {

class TallyTree {
public:
  using Vec3d = std::array<double, 3>;

  // A hemisphere that wants super-samples: counts per division of hemisphere `which` of the
  // shaded ray `ray` at `hit`.
  struct SuperRequest {
    std::uint32_t hemi;
    rc_ray ray;
    rc_hit hit;
    std::uint32_t which;
    std::vector<std::uint32_t> counts; // ns * ns
  };

  // Primaries 0..n-1, each waiting for its own ray.
  void reset(std::size_t primaries, std::uint32_t seed);

  // A shaded ray's total and children: marks hemisphere samples' tallies (children are
  // rewritten in place), counts the children as pending, retires the ray.
  void shaded(const rc_ray& ray, const rc_hit& hit, const rc_float4& total, rc_ray* children,
              std::size_t nchildren);

  // Super-sample children of request `r` (their cell field names the division).
  void supersampled(const SuperRequest& r, rc_ray* children, std::size_t nchildren);

  // Requests made since the last call.
  std::vector<SuperRequest> take_requests() { return std::move(requests_); }

  const Vec3d& sum(std::size_t primary) const { return nodes_[primary].sum; }
  const Vec3d& mirrored(std::size_t primary) const { return nodes_[primary].msum; }
  std::uint64_t hemispheres() const { return hemis_.size(); }

private:
  struct Node {
    std::uint32_t parent = RC_NONE; // a cell's hemisphere, a hemisphere's tally
    std::int64_t pending = 0;       // rays in flight + hemispheres below not yet resolved
    Vec3d sum{}, msum{};            // contributions; the part below the mirror reflection
    std::uint32_t count = 1;        // a cell's samples
    std::uint32_t hemi = RC_NONE;   // a hemisphere node's record
  };
  struct Hemi {
    rc_ray ray;
    rc_hit hit;
    Vec3d acoef; // Radiance's hp->acoef: the ambient coefficient over ns * ns
    std::uint32_t node, first_cell, ns, budget, which;
    bool second = false; // the super-sample decision has been made
  };

  void add(std::uint32_t node, const rc_float4& c, bool mirrored);
  void settle(std::uint32_t node);
  std::vector<std::uint32_t> allocate(const Hemi& h) const;

  std::vector<Node> nodes_;
  std::vector<Hemi> hemis_;
  std::vector<SuperRequest> requests_;
  std::uint32_t seed_ = 0;
};

} // namespace radcl::render
