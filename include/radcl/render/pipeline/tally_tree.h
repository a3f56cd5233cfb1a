// Where a batch's contributions add up when they cannot go straight to their primary ray.
// Normally every ray adds into its primary's sum. With -as, the first samples of a hemisphere
// add into one cell per division; once every ray below a hemisphere has finished, the cells'
// values decide where the super-samples go (Radiance's ambsupersamp), and once those have
// finished too, the hemisphere adds the sum of its divisions' averages into its parent.
// In rtrace's trace modes (-ot/-oT) every ray gets a node of its own, so each ray's value is
// known when its subtree has finished, and the tree can be printed in Radiance's order.
// With -oe a primary's first hemispheres (those at ambient depth 0) keep their divisions apart
// whether or not they are super-sampled, and the spread of the divisions' values gives the
// primary's standard error.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "radcl/device_types.h"
#include "radcl/render/pipeline/phase_profile.h"
#include "radcl/util/no_init.h"

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

  // A traced shadow ray (-oT): its request, its contribution on arrival, whether it arrived.
  struct TracedShadow {
    rc_shadow request;
    rc_float4 arrived;
    bool blocked;
  };

  // A ray of a traced tree, with its node's final sum (its contribution to the primary).
  struct Traced {
    rc_ray ray{};
    rc_hit hit{};
    bool shaded = false;
    bool is_shadow = false;
    TracedShadow shadow{};
    std::uint32_t node = RC_NONE;
    std::vector<std::uint32_t> kids; // in the order they were made
  };

  // Primaries 0..n-1, each waiting for its own ray; `trace` gives every ray a node; `spread`
  // keeps each primary's standard error.
  void reset(std::size_t primaries, std::uint32_t seed, bool trace = false, bool spread = false);

  // A shaded ray's total and children: marks hemisphere samples' tallies (children are
  // rewritten in place), counts the children as pending, retires the ray. In trace mode the
  // ray's shadow rays join its traced children.
  void shaded(const rc_ray& ray, const rc_hit& hit, const rc_float4& total, rc_ray* children,
              std::size_t nchildren, const TracedShadow* shadows = nullptr,
              std::size_t nshadows = 0);

  // The same for rays [0, n) of a slice, in order, outside trace mode: ray i's children are
  // children[off[i], off[i] + count[i]). The hemispheres' nodes are made on every core (their
  // places follow from counts, so they are those the serial order gives); sums and settling
  // stay in ray order. `cells` (null: unknown) says which rays marked hemisphere samples (the
  // kernel's rc_ray.cell): the others' children are plain and are not read.
  void shaded_slice(const rc_ray* rays, const rc_hit* hits, const rc_float4* totals,
                    rc_ray* children, const std::uint32_t* off, const std::uint32_t* count,
                    const std::uint8_t* cells, std::size_t n);

  // Super-sample children of request `r` (their cell field names the division).
  void supersampled(const SuperRequest& r, rc_ray* children, std::size_t nchildren);

  // RADCL_PROFILE=waves: shaded_slice's parts timed into `p` (null: not timed).
  void set_profile(PhaseProfile* p) { prof_ = p; }

  // Requests made since the last call.
  std::vector<SuperRequest> take_requests() { return std::move(requests_); }

  const Vec3d& sum(std::size_t primary) const { return nodes_[primary].sum; }
  // Trace mode: the primary's traced rays in post-order (children first), with their depth.
  std::vector<std::pair<const Traced*, int>> traced(std::size_t primary) const;
  const Vec3d& node_sum(std::uint32_t node) const { return nodes_[node].sum; }
  const Vec3d& mirrored(std::size_t primary) const { return nodes_[primary].msum; }
  // The primary's standard error (reset's `spread`): the square root of its first
  // hemispheres' variances, each estimated from pairs of neighbouring divisions (see
  // add_spread in the .cpp).
  Vec3d std_error(std::size_t primary) const;
  std::uint64_t hemispheres() const { return hemis_.size(); }

private:
  enum class Kind : std::uint8_t { Primary, Ray, Cell, Hemi };
  // Nodes and hemispheres are made by the million per batch, in room grown without clearing it
  // first (NoInit): every field is written where one is made (fresh_node, make_hemi).
  struct Node {
    Kind kind;
    std::uint32_t traced; // trace mode: the ray's record
    std::uint32_t parent; // a cell's hemisphere, a hemisphere's or ray's tally
    std::int64_t pending; // rays in flight + hemispheres below not yet resolved
    Vec3d sum, msum;      // contributions; the part below the mirror reflection
    std::uint32_t count;  // a cell's samples
    std::uint32_t hemi;   // a hemisphere node's record
  };
  static Node fresh_node(Kind kind, std::uint32_t parent, std::int64_t pending) {
    return Node{kind, RC_NONE, parent, pending, Vec3d{}, Vec3d{}, 1, RC_NONE};
  }
  struct Hemi {
    rc_ray ray;
    rc_hit hit;
    Vec3d acoef; // Radiance's hp->acoef: the ambient coefficient over ns * ns
    std::uint32_t node, first_cell, ns, budget, which;
    std::uint32_t ncells; // ns * ns, or fewer where -lw dropped samples (then no budget)
    bool second;          // the super-sample decision has been made
  };
  void add(std::uint32_t node, const rc_float4& c, bool mirrored);
  // The hemisphere whose first samples begin at children[k] (m of them) of `ray`: its node at
  // `node`, its cells after it, its record at hemis_[hemi]; the samples point at their cells.
  void make_hemi(const rc_ray& ray, const rc_hit& hit, rc_ray* children, std::size_t k,
                 std::size_t m, std::uint32_t node, std::uint32_t hemi);
  // The number of a hemisphere's first samples from children[k] on (0: not a sample).
  static std::size_t run_length(const rc_ray* children, std::size_t k, std::size_t nchildren);
  // shaded_slice's first step: each ray's new nodes and hemispheres (into new_nodes_,
  // new_hemis_) and plain children (plain_); true where the slice is not in primary order.
  bool count_children(const rc_ray* rays, const rc_ray* children, const std::uint32_t* off,
                      const std::uint32_t* count, const std::uint8_t* cells, std::size_t n);
  // Per slice, kept: each ray's new nodes, hemispheres and plain children.
  std::vector<std::uint32_t> new_nodes_, new_hemis_, plain_;
  // Trace mode: a node of its own for a child ray under `parent`, recorded under `rec`.
  std::uint32_t ray_node(std::uint32_t parent, std::uint32_t rec);
  // Settles `node` up its tree; super-sample requests it makes go to `requests`.
  void settle(std::uint32_t node, std::vector<SuperRequest>& requests);
  // Radiance's super-sample counts of each division into `counts` (ns * ns); whether any
  // (`counts` is left as it was when none).
  bool allocate(const Hemi& h, std::vector<std::uint32_t>& counts) const;
  // A resolved hemisphere at ambient depth 0 adds its variance to its primary's.
  void add_spread(const Hemi& h, std::uint32_t parent);
  // The primary a node belongs to.
  std::uint32_t primary_of(std::uint32_t node) const;

  std::vector<Node, NoInit<Node>> nodes_;
  std::vector<Hemi, NoInit<Hemi>> hemis_;
  std::vector<SuperRequest> requests_;
  std::vector<Traced> traced_;
  bool trace_ = false;
  std::uint32_t seed_ = 0;
  std::vector<Vec3d> variance_; // per primary, with spread
  PhaseProfile* prof_ = nullptr;
};

} // namespace radcl::render
