#include "radcl/bsdf/tensor_tree.h"

#include "scan.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace radcl::bsdf {

namespace {

constexpr double kPi = 3.14159265358979323846;
// The square-disk maps keep disk points just inside the unit circle (and square coordinates
// of unit vectors inside [0, 1]), as Radiance's do.
constexpr double kShrink = 1 - 1e-13;
// Deeper than this no file goes (2^-32 of the hypercube), and it bounds the parser's recursion.
constexpr int kMaxDepth = 32;

using detail::skip_space;

class TreeParser {
public:
  TreeParser(std::string_view text, int ndim, TensorTree& tree)
      : s_(text), nd_(ndim), tree_(tree) {}

  void parse() {
    i_ = skip_space(s_, 0);
    node(0);
    i_ = skip_space(s_, i_);
    if (i_ != s_.size()) fail("extra characters after the tensor tree", i_);
  }

private:
  [[noreturn]] void fail(const std::string& msg, size_t at) { throw TreeSyntaxError(msg, at); }

  bool eat(char c) {
    i_ = skip_space(s_, i_);
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }

  // Reads one node at i_ and returns its offset in nodes.
  int32_t node(int depth) {
    const size_t open = skip_space(s_, i_);
    if (!eat('{')) fail("missing '{' in tensor tree", open);
    if (depth > kMaxDepth) fail("tensor tree nested too deeply", open);
    const auto at = static_cast<int32_t>(tree_.nodes.size());
    i_ = skip_space(s_, i_);
    if (i_ < s_.size() && s_[i_] == '{') {
      const int nchild = 1 << nd_;
      tree_.nodes.resize(tree_.nodes.size() + 1 + nchild);
      tree_.nodes[at] = -1;
      for (int c = 0; c < nchild; ++c) {
        i_ = skip_space(s_, i_);
        if (i_ < s_.size() && s_[i_] == '}')
          fail("tensor tree branch with " + std::to_string(c) + " subtrees, not " +
                   std::to_string(nchild),
               i_);
        const int32_t child = node(depth + 1);
        tree_.nodes[at + 1 + c] = child;
      }
    } else {
      grid(open);
    }
    if (!eat('}')) fail("missing '}' in tensor tree", skip_space(s_, i_));
    eat(',');
    return at;
  }

  void grid(size_t open) {
    const size_t first = tree_.values.size();
    for (;;) {
      i_ = skip_space(s_, i_);
      if (i_ >= s_.size() || s_[i_] == '}') break;
      double v;
      const size_t end = detail::scan_real(s_, i_, &v);
      if (end == std::string_view::npos ||
          (end < s_.size() && !detail::is_space(s_[end]) && s_[end] != ',' && s_[end] != '}'))
        fail("bad number \"" + std::string(detail::word_at(s_, i_)) + "\" in tensor tree", i_);
      tree_.values.push_back(v < 0 ? 0.0f : static_cast<float>(v));
      if (tree_.values.size() > static_cast<size_t>(INT32_MAX)) fail("tensor tree too large", i_);
      i_ = end;
      eat(',');
    }
    const size_t n = tree_.values.size() - first;
    int g = 0;
    while (g * nd_ < 31 && (size_t{1} << (g * nd_)) < n)
      ++g;
    if (g * nd_ >= 31 || (size_t{1} << (g * nd_)) != n)
      fail("tensor tree leaf of " + std::to_string(n) + " values (must be 1 or a power of " +
               std::to_string(1 << nd_) + ")",
           open);
    tree_.nodes.push_back(g);
    tree_.nodes.push_back(static_cast<int32_t>(first));
  }

  std::string_view s_;
  size_t i_ = 0;
  int nd_;
  TensorTree& tree_;
};

} // namespace

TensorTree parse_tensor_tree(std::string_view text, int ndim) {
  TensorTree tree;
  tree.ndim = ndim;
  TreeParser(text, ndim, tree).parse();
  return tree;
}

float TensorTree::lookup(const double* pos) const {
  if (nodes.empty()) return 0;
  double p[4];
  for (int d = 0; d < ndim; ++d)
    p[d] = std::clamp(pos[d], 0.0, std::nextafter(1.0, 0.0));
  int32_t k = 0;
  while (nodes[k] < 0) {
    int c = 0;
    for (int d = 0; d < ndim; ++d) {
      p[d] *= 2;
      if (p[d] >= 1) {
        c |= 1 << d;
        p[d] -= 1;
      }
    }
    k = nodes[k + 1 + c];
  }
  const int n = 1 << nodes[k];
  size_t index = 0;
  for (int d = 0; d < ndim; ++d)
    index = index * n + std::min(static_cast<int>(p[d] * n), n - 1);
  return values[nodes[k + 1] + index];
}

std::array<double, 4> TensorTree::position(const vec::Vec3& in, const vec::Vec3& out) const {
  std::array<double, 4> pos{};
  if (ndim == 3) {
    pos[0] = (0.5 - 1e-6) - 0.5 * std::sqrt(in[0] * in[0] + in[1] * in[1]);
    // Turn the outgoing vector so that the incident light travels along +x. atan2 of signed
    // zeros is kept as it is (normal incidence turns by pi), as in Radiance.
    const double a = -std::atan2(-in[1], -in[0]);
    const double c = std::cos(a), s = std::sin(a);
    const auto sq = disk_to_square(out[0] * c - out[1] * s, out[0] * s + out[1] * c);
    pos[1] = sq[0];
    pos[2] = sq[1];
  } else if (ndim == 4) {
    const auto si = disk_to_square(-in[0], -in[1]);
    const auto so = disk_to_square(out[0], out[1]);
    pos = {si[0], si[1], so[0], so[1]};
  }
  return pos;
}

float TensorTree::value(const vec::Vec3& in, const vec::Vec3& out) const {
  const auto pos = position(in, out);
  return lookup(pos.data());
}

std::array<double, 2> square_to_disk(double s, double t) {
  const double a = 2 * s - 1, b = 2 * t - 1;
  if (a == 0 && b == 0) return {0, 0};
  // Concentric rings of the square become circles: the larger of |a|, |b| is the radius and the
  // other sweeps a quarter of the circle.
  double r, phi;
  if (std::fabs(a) > std::fabs(b)) {
    r = a;
    phi = kPi / 4 * (b / a);
  } else {
    r = b;
    phi = kPi / 2 - kPi / 4 * (a / b);
  }
  r *= kShrink;
  return {r * std::cos(phi), r * std::sin(phi)};
}

std::array<double, 2> disk_to_square(double x, double y) {
  const double r = std::sqrt(x * x + y * y);
  double phi = std::atan2(y, x);
  if (phi < -kPi / 4) phi += 2 * kPi; // [-pi/4, 7pi/4): one quarter per side of the square
  double a, b;
  if (phi < kPi / 4) {
    a = r;
    b = a * phi / (kPi / 4);
  } else if (phi < 3 * kPi / 4) {
    b = r;
    a = -b * (phi - kPi / 2) / (kPi / 4);
  } else if (phi < 5 * kPi / 4) {
    a = -r;
    b = a * (phi - kPi) / (kPi / 4);
  } else {
    b = -r;
    a = -b * (phi - 3 * kPi / 2) / (kPi / 4);
  }
  return {0.5 + 0.5 * a / kShrink, 0.5 + 0.5 * b / kShrink};
}

} // namespace radcl::bsdf
