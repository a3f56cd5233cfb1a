// Ear clipping that survives Radiance's seam-connected holes: a hole is walked in the opposite
// direction and joined to the outline by a bridge traversed twice, so vertices repeat and
// edges coincide. Ears are validated against repeated vertices by looking at the directions
// of their edges, and zero-area vertices (collinear, spikes, repeats) are dropped as they
// appear, which also removes bridges once one side of them is clipped away.
#include "radcl/geometry/triangulate.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace radcl::geometry {
namespace {

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}
double cross_dir(const Point2& u, const Point2& v) {
  return u[0] * v[1] - u[1] * v[0];
}
Point2 sub(const Point2& a, const Point2& b) {
  return {a[0] - b[0], a[1] - b[1]};
}
double len(const Point2& a) {
  return std::hypot(a[0], a[1]);
}

class EarClipper {
public:
  explicit EarClipper(std::span<const Point2> pts) : p_(pts) {
    const std::size_t n = pts.size();
    next_.resize(n);
    prev_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      next_[i] = static_cast<std::uint32_t>((i + 1) % n);
      prev_[i] = static_cast<std::uint32_t>((i + n - 1) % n);
    }
    double lo[2] = {pts[0][0], pts[0][1]}, hi[2] = {lo[0], lo[1]};
    for (const auto& q : pts)
      for (int k = 0; k < 2; ++k)
        lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
    const double size = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    same_tol2_ = (1e-12 * size) * (1e-12 * size);
    area_tol_ = 1e-14 * size * size;
    count_ = n;
  }

  std::vector<Tri> run() {
    std::vector<Tri> out;
    std::uint32_t v = 0;
    std::size_t since_clip = 0; // vertices examined since the last change
    while (count_ > 3) {
      if (since_clip > count_) { // a full lap without an ear: clip the most convex vertex
        if (!force_clip(out)) break;
        since_clip = 0;
        continue;
      }
      const std::uint32_t a = prev_[v], c = next_[v];
      if (degenerate(a, v, c)) {
        remove(v);
        v = a;
        since_clip = 0;
      } else if (is_ear(a, v, c)) {
        out.push_back({a, v, c});
        remove(v);
        v = a;
        since_clip = 0;
      } else {
        v = c;
        ++since_clip;
      }
    }
    if (count_ == 3 && cross(p_[prev_[v]], p_[v], p_[next_[v]]) > area_tol_)
      out.push_back({prev_[v], v, next_[v]});
    return out;
  }

private:
  bool same(std::uint32_t i, std::uint32_t j) const {
    const double dx = p_[i][0] - p_[j][0], dy = p_[i][1] - p_[j][1];
    return dx * dx + dy * dy <= same_tol2_;
  }
  // Collinear, reversing or repeated: dropping the vertex changes no area.
  bool degenerate(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const Point2 e1 = sub(p_[b], p_[a]), e2 = sub(p_[c], p_[b]);
    return std::abs(cross_dir(e1, e2)) <= 1e-12 * len(e1) * len(e2) || same(a, b) || same(b, c);
  }
  // Direction w from a corner lies strictly inside the angle swept counter-clockwise from e1
  // to e2 (< 180 degrees).
  bool inside_angle(const Point2& e1, const Point2& e2, const Point2& w) const {
    const double lw = len(w);
    return cross_dir(e1, w) > 1e-12 * len(e1) * lw && cross_dir(w, e2) > 1e-12 * len(e2) * lw;
  }
  // Another vertex p sitting on corner `k` of the triangle blocks the ear if one of its edges
  // leaves the corner into the triangle.
  bool edges_enter(std::uint32_t p, const Point2& corner, const Point2& e1,
                   const Point2& e2) const {
    for (std::uint32_t q : {prev_[p], next_[p]}) {
      const Point2 w = sub(p_[q], corner);
      if (w[0] * w[0] + w[1] * w[1] <= same_tol2_) continue;
      if (inside_angle(e1, e2, w)) return true;
    }
    return false;
  }
  bool is_ear(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const Point2 &A = p_[a], &B = p_[b], &C = p_[c];
    if (cross(A, B, C) <= area_tol_) return false; // reflex or flat
    for (std::uint32_t p = next_[c]; p != a; p = next_[p]) {
      const Point2& P = p_[p];
      if (same(p, a)) {
        if (edges_enter(p, A, sub(B, A), sub(C, A))) return false;
        continue;
      }
      if (same(p, b)) {
        if (edges_enter(p, B, sub(C, B), sub(A, B))) return false;
        continue;
      }
      if (same(p, c)) {
        if (edges_enter(p, C, sub(A, C), sub(B, C))) return false;
        continue;
      }
      const double o1 = cross(A, B, P), o2 = cross(B, C, P), o3 = cross(C, A, P);
      if (o1 < -area_tol_ || o2 < -area_tol_ || o3 < -area_tol_) continue;  // outside
      if (o1 > area_tol_ && o2 > area_tol_ && o3 > area_tol_) return false; // inside
      if (o3 <= area_tol_ && o1 > area_tol_ && o2 > area_tol_) {
        // On the new diagonal: harmless unless one of its edges enters the triangle.
        const Point2 ca = sub(A, C);
        for (std::uint32_t q : {prev_[p], next_[p]})
          if (cross_dir(ca, sub(p_[q], P)) > 1e-12 * len(ca) * len(sub(p_[q], P))) return false;
        continue;
      }
      return false; // on an edge of the polygon itself: be conservative
    }
    return true;
  }
  bool force_clip(std::vector<Tri>& out) {
    std::uint32_t start = 0;
    while (prev_[start] == kDead)
      ++start;
    std::uint32_t best = kDead;
    double best_area = area_tol_;
    std::uint32_t v = start;
    do {
      const double ar = cross(p_[prev_[v]], p_[v], p_[next_[v]]);
      if (ar > best_area) best_area = ar, best = v;
      v = next_[v];
    } while (v != start);
    if (best == kDead) return false;
    out.push_back({prev_[best], best, next_[best]});
    remove(best);
    return true;
  }
  void remove(std::uint32_t v) {
    next_[prev_[v]] = next_[v];
    prev_[next_[v]] = prev_[v];
    prev_[v] = next_[v] = kDead;
    --count_;
  }

  static constexpr std::uint32_t kDead = ~0u;
  std::span<const Point2> p_;
  std::vector<std::uint32_t> next_, prev_;
  std::size_t count_ = 0;
  double same_tol2_ = 0, area_tol_ = 0;
};

// Strictly convex everywhere and turning once around: a fan is exact.
bool is_convex(std::span<const Point2> p) {
  const std::size_t n = p.size();
  double turning = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 e1 = sub(p[(i + 1) % n], p[i]), e2 = sub(p[(i + 2) % n], p[(i + 1) % n]);
    const double cr = cross_dir(e1, e2);
    if (!(cr > 1e-12 * len(e1) * len(e2))) return false;
    turning += std::atan2(cr, e1[0] * e2[0] + e1[1] * e2[1]);
  }
  return std::abs(turning - 2 * std::numbers::pi) < 1e-6;
}

} // namespace

std::vector<Tri> triangulate_2d(std::span<const Point2> pts) {
  std::vector<Tri> out;
  if (pts.size() < 3) return out;
  if (is_convex(pts)) {
    for (std::uint32_t i = 1; i + 1 < pts.size(); ++i)
      out.push_back({0, i, i + 1});
    return out;
  }
  return EarClipper(pts).run();
}

} // namespace radcl::geometry
