// xform-style transform arguments (-t -rx -ry -rz -s -mx -my -mz -i), as used by instance,
// mesh and the function types. Row-vector convention: p' = p * M.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace radcl::scene {

struct Transform {
  std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
  double scale = 1; // product of |-s| factors: converts distances between the two spaces

  std::array<double, 3> point(const std::array<double, 3>& p) const;
  std::array<double, 3> vector(const std::array<double, 3>& v) const; // no translation
  Transform inverse() const;
  bool is_identity() const;
};

// Radiance's xf(): parses the longest valid transform starting at args[first] into `out` and
// returns the index of the first word not used (args.size() when all were used). A transform
// whose numbers or products are not finite (or whose scale underflows to 0) uses nothing.
std::size_t transform_prefix(const std::vector<std::string>& args, std::size_t first,
                             Transform& out);

// Parses args[first..] completely; throws FatalError("bad transform") on anything left over
// or malformed. An empty range gives the identity.
Transform parse_transform(const std::vector<std::string>& args, std::size_t first = 0);

} // namespace radcl::scene
