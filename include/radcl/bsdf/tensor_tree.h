// Tensor trees ("LBNL/Shirley-Chiu" basis): variable-resolution BSDFs over the unit hypercube,
// 3-dimensional for isotropic (TensorTree3) and 4-dimensional for anisotropic (TensorTree4) data.
//
// Flat layout, ready to copy to a device buffer as it is. `nodes` holds int32 records; the root
// is at offset 0. The record at offset k is
//   a branch:    nodes[k] = -1 and nodes[k + 1 + c] (c < 2^ndim) is the offset of child c, which
//                covers the upper half of dimension d where bit d of c is set, else the lower;
//   a leaf grid: nodes[k] = g >= 0 (log2 of its resolution along each dimension) and
//                nodes[k + 1] = the offset in `values` of its 2^(g * ndim) values, in row-major
//                order with dimension 0 slowest and dimension ndim - 1 fastest.
// The children of a branch appear in the file in the order c = 0, 1, ..., and a grid's values in
// the order above, as Radiance reads them. The tree keeps the file's structure (Radiance merges
// uniform branches into larger grids, which gives the same values).
//
// Coordinates (Radiance's SDqueryTre): TensorTree4 uses disk_to_square(-in.x, -in.y) for
// dimensions 0-1 and disk_to_square(out.x, out.y) for 2-3. TensorTree3 uses
// (0.5 - 1e-6) - 0.5 * |in.xy| for dimension 0 (so only its lower half is ever read) and, for
// 1-2, disk_to_square of the outgoing vector turned about z by -atan2(-in.y, -in.x), which puts
// the incident plane on +x.
#pragma once

#include "radcl/util/vec3.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace radcl::bsdf {

struct TensorTree {
  int ndim = 0; // 3 or 4; 0 for an empty tree
  std::vector<int32_t> nodes;
  std::vector<float> values;

  bool empty() const { return nodes.empty(); }
  // Value of the leaf holding a position in [0, 1)^ndim (clamped into that range).
  float lookup(const double* pos) const;
  // Value for a pair of directions in the tree's own orientation (only x and y are used: the
  // caller picks the tree by the sides the vectors are on), mapped as described above.
  float value(const vec::Vec3& in, const vec::Vec3& out) const;
  // The hypercube position value() looks up.
  std::array<double, 4> position(const vec::Vec3& in, const vec::Vec3& out) const;
};

// A syntax error in a tensor tree, at a character offset in the text.
class TreeSyntaxError : public std::runtime_error {
public:
  TreeSyntaxError(const std::string& msg, size_t offset)
      : std::runtime_error(msg), offset_(offset) {}
  size_t offset() const { return offset_; }

private:
  size_t offset_;
};

// Reads a nested-brace ScatteringData: "{" then either 2^ndim subtrees or a grid of 1, 2^ndim,
// 2^(2 ndim), ... numbers, then "}"; numbers and subtrees may be followed by a comma. Negative
// values become 0, as Radiance reads them. Throws TreeSyntaxError.
TensorTree parse_tensor_tree(std::string_view text, int ndim);

// The Shirley-Chiu concentric map between the unit square [0,1]^2 and the unit disk, which keeps
// areas in proportion; on the disk of (x, y) of unit vectors, area is projected solid angle.
std::array<double, 2> disk_to_square(double x, double y);
std::array<double, 2> square_to_disk(double s, double t);

} // namespace radcl::bsdf
