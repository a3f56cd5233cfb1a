#include "radcl/ambient/leaks.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace radcl::ambient {
namespace {

constexpr double kFtiny = 1e-6;        // Radiance's FTINY
constexpr double kCos70Sq = 0.1169778; // cos(70 degrees)^2: the test ray's target elevation
constexpr double kPi = 3.14159265358979323846;

using V3 = std::array<double, 3>;
double dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 xyz(const rc_float4& v) {
  return {v.x, v.y, v.z};
}

// Real roots of a t^2 + b t + c in ascending order, counted as Radiance's quadratic() counts
// them (near-zero a: the linear root; a near-zero discriminant: one double root).
int roots(double a, double b, double c, double t[2]) {
  if (std::fabs(a) <= kFtiny) {
    if (std::fabs(b) <= kFtiny) return 0;
    t[0] = -c / b;
    return 1;
  }
  const double h = 0.5 * b, disc = h * h - a * c;
  if (disc < -kFtiny * kFtiny) return 0;
  if (disc <= kFtiny * kFtiny) {
    t[0] = -h / a;
    return 1;
  }
  const double s = std::sqrt(disc), r0 = (-h - s) / a, r1 = (-h + s) / a;
  t[0] = std::min(r0, r1);
  t[1] = std::max(r0, r1);
  return 2;
}

float atan_poly(float y, float x) {
  const float q = y / x, aq = std::fabs(q);
  return static_cast<float>(kPi / 4) * q - q * (aq - 1.0f) * (0.2447f + 0.0663f * aq) +
         (x < 0.0f ? static_cast<float>(kPi) : 0.0f);
}

} // namespace

float corral_atan2a(float y, float x) {
  if (x == 0.0f) return y > 0.0f ? static_cast<float>(kPi / 2) : static_cast<float>(1.5 * kPi);
  if (std::fabs(y / x) > 1.01f) return static_cast<float>(kPi / 2) - atan_poly(x, y);
  return atan_poly(y, x);
}

LeakTester::LeakTester(const AmbientCacheBuffers* cache, float aa, float minarad,
                       const std::vector<std::uint32_t>* to_index)
    : cache_(cache), to_index_(to_index), aa_(aa), minarad_(minarad) {
  for (std::uint32_t c : cache->corral)
    marked_ += c != 0;
}

bool LeakTester::leaks(const LeakLookup& q, std::uint32_t k, const SegmentBlocked& segment_blocked,
                       bool* traced) const {
  if (traced) *traced = false;
  const rc_amb_record& a = cache_->records[k];
  const std::uint32_t corral = cache_->corral[k];
  if (!corral) return false;
  const V3 p = {q.point[0], q.point[1], q.point[2]}, pos = xyz(a.pos), an = xyz(a.nrm);
  const V3 u = xyz(a.udir), v = cross(an, u);
  const V3 ck = {p[0] - pos[0], p[1] - pos[1], p[2] - pos[2]};
  // A record at the lookup point itself (made there for a ray that is now shaded again) has no
  // direction to leak along; Radiance, which never looks a new record up where it made it,
  // would find a double root below and plug it, so the point would miss again in every round.
  const double tiny = 1e-6 * std::max({1.0, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
  if (dot(ck, ck) <= tiny * tiny) return false;
  // The sector of the point as seen from the record, in its u, v frame.
  double ang = corral_atan2a(static_cast<float>(dot(ck, v)), static_cast<float>(dot(ck, u)));
  if (ang < 0) ang += 2 * kPi;
  const int sector = std::min(31, static_cast<int>(ang * (16 / kPi)));
  if (!((corral >> sector) & 1u)) return false;
  // The test ray aims at the point above the record, along its normal, that the lookup point
  // sees 20 degrees above its own tangent plane: high enough to pass over local clutter.
  V3 ron = q.normal;
  if (dot(ron, an) < 0) ron = {-ron[0], -ron[1], -ron[2]}; // a lookup on the back side
  const V3 vd = {-ck[0], -ck[1], -ck[2]};
  const double nd = dot(an, ron), ndotd = dot(vd, ron), nadotd = dot(vd, an);
  double t[2];
  if (roots(nd * nd - kCos70Sq, 2 * (nd * ndotd - nadotd * kCos70Sq),
            ndotd * ndotd - dot(vd, vd) * kCos70Sq, t) != 2)
    return true;                    // Radiance plugs these rare cases
  if (t[1] <= kFtiny) return false; // the behind test handles it
  V3 dir = {vd[0] + an[0] * t[1], vd[1] + an[1] * t[1], vd[2] + an[2] * t[1]};
  const double len = std::sqrt(dot(dir, dir));
  if (!(len > 0)) return false;
  for (double& c : dir)
    c /= len;
  if (traced) *traced = true;
  return segment_blocked(p, dir, len, ron);
}

std::size_t LeakTester::find(const LeakLookup& q, const SegmentBlocked& segment_blocked,
                             std::vector<std::uint32_t>& blocked) const {
  if (!active()) return 0;
  const float aa = aa_;
  // The kernel's tests, a little wider so that every record it accepts is looked at: its
  // direction test uses the shading normal (perturbed by textures, reversed for the back of
  // translucent surfaces), which the host does not know unless no texture applies.
  float maxangle = static_cast<float>(10.0 * kPi / 180.0) + aa;
  if (q.weight < 0.6f)
    maxangle = (maxangle - static_cast<float>(kPi / 2)) * std::pow(q.weight, 0.13f) +
               static_cast<float>(kPi / 2);
  // The kernel accepts a chord 2 - 2 cos(angle) below maxangle^2: angles to 2 asin(maxangle / 2).
  const double reach = 2 * std::asin(std::min(1.0, 0.5 * static_cast<double>(maxangle)));
  const double wide = std::min(kPi / 2, reach + (q.exact_normal ? 1e-3 : 0.5));
  const double cwide = std::cos(wide), swide = std::sin(wide), mincos = cwide - 1e-6;
  const double behind = -(static_cast<double>(minarad_) * aa + 0.001) * 1.001 - 1e-6;
  const double lim2 = static_cast<double>(aa) * aa * 1.001;
  const V3 p = {q.point[0], q.point[1], q.point[2]};
  std::size_t traced = 0;
  const auto& nodes = cache_->nodes;
  const std::uint32_t nn = static_cast<std::uint32_t>(nodes.size());
  for (std::uint32_t i = 0; i < nn;) {
    const rc_amb_node& nd = nodes[i];
    if (q.point[0] < nd.lo.x || q.point[1] < nd.lo.y || q.point[2] < nd.lo.z ||
        q.point[0] > nd.hi.x || q.point[1] > nd.hi.y || q.point[2] > nd.hi.z ||
        !node_cone_may_hold(nd, q.normal, cwide, swide, true)) {
      i = nd.skip;
      continue;
    }
    if (nd.count == 0) {
      ++i;
      continue;
    }
    for (std::uint32_t k = nd.first; k < nd.first + nd.count; ++k) {
      if (!cache_->corral[k]) continue;
      const rc_amb_record& a = cache_->records[k];
      const std::uint32_t lvl = static_cast<std::uint32_t>(a.val.w);
      if (lvl > q.level || (lvl == q.level && a.pos.w < 0.9f * q.weight)) continue;
      const V3 an = xyz(a.nrm);
      if (std::fabs(dot(an, q.normal)) <= mincos) continue;
      const V3 ck = {p[0] - a.pos.x, p[1] - a.pos.y, p[2] - a.pos.z};
      double d = dot(ck, an);
      if (d < behind) continue;
      d /= a.nrm.w;
      double dt2 = d * d;
      if (dt2 >= lim2) continue;
      const V3 u = xyz(a.udir), v = cross(an, u);
      const double cu = dot(ck, u) / a.nrm.w, cv = dot(ck, v) / a.udir.w;
      dt2 += cu * cu + cv * cv;
      if (dt2 >= lim2) continue;
      bool t = false;
      if (leaks(q, k, segment_blocked, &t)) blocked.push_back(to_index_ ? (*to_index_)[k] : k);
      traced += t;
    }
    i = nd.skip;
  }
  return traced;
}

} // namespace radcl::ambient
