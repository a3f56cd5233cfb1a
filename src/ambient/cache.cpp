#include "radcl/ambient/cache.h"

#include <algorithm>
#include <cmath>
#include <embree3/rtcore.h>
#include <new>

#include "radcl/ambient/dircode.h"
#include "radcl/luminance.h"
#include "radcl/util/error.h"

namespace radcl::ambient {
namespace {

constexpr unsigned kMaxLeaf = 8;

// Nodes live in Embree's builder memory (rtcThreadLocalAlloc): trivially destructible.
struct Node {
  bool leaf = false;
};
struct Inner : Node {
  Node* kids[2] = {nullptr, nullptr};
  RTCBounds box[2];
};
struct Leaf : Node {
  unsigned n = 0;
  unsigned ids[kMaxLeaf];
};

void* create_node(RTCThreadLocalAllocator alloc, unsigned, void*) {
  return new (rtcThreadLocalAlloc(alloc, sizeof(Inner), 16)) Inner;
}
void set_children(void* node, void** kids, unsigned n, void*) {
  for (unsigned i = 0; i < n && i < 2; ++i)
    static_cast<Inner*>(node)->kids[i] = static_cast<Node*>(kids[i]);
}
void set_bounds(void* node, const RTCBounds** box, unsigned n, void*) {
  for (unsigned i = 0; i < n && i < 2; ++i)
    static_cast<Inner*>(node)->box[i] = *box[i];
}
void* create_leaf(RTCThreadLocalAllocator alloc, const RTCBuildPrimitive* prims, size_t n, void*) {
  Leaf* l = new (rtcThreadLocalAlloc(alloc, sizeof(Leaf), 16)) Leaf;
  l->leaf = true;
  l->n = static_cast<unsigned>(std::min<size_t>(n, kMaxLeaf));
  for (unsigned i = 0; i < l->n; ++i)
    l->ids[i] = prims[i].primID;
  return l;
}

rc_float4 f4(double x, double y, double z, double w) {
  return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z),
          static_cast<float>(w)};
}

// The orientation bin of a unit normal: twice its dominant axis, plus one where that component
// is negative (rc_amb_node).
std::uint32_t normal_bin(const rc_float4& n) {
  const float a[3] = {std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
  const int k = a[0] >= a[1] && a[0] >= a[2] ? 0 : (a[1] >= a[2] ? 1 : 2);
  const float c = k == 0 ? n.x : (k == 1 ? n.y : n.z);
  return static_cast<std::uint32_t>(2 * k + (c < 0 ? 1 : 0));
}
// Cosine of the angle between unit n and the axis of `bin`.
double axis_cos(const rc_float4& n, std::uint32_t bin) {
  const double c = bin < 2 ? n.x : (bin < 4 ? n.y : n.z);
  return bin & 1u ? -c : c;
}

class Flattener {
public:
  Flattener(const std::vector<rc_amb_record>& in, const std::vector<std::uint32_t>& corral,
            const std::vector<std::uint32_t>& source, std::uint32_t bin, AmbientCacheBuffers& out)
      : in_(in), corral_(corral), source_(source), bin_(bin), out_(out) {}

  // Appends `node` (whose box is `box`) and its subtree; returns the cosine of the subtree's
  // normal cone about the bin's axis.
  double add(const Node* node, const RTCBounds& box) {
    const std::size_t at = out_.nodes.size();
    rc_amb_node n{};
    n.lo = f4(box.lower_x, box.lower_y, box.lower_z, 0);
    n.hi = f4(box.upper_x, box.upper_y, box.upper_z, 0);
    n.bin = bin_;
    out_.nodes.push_back(n);
    double c = 1;
    if (node->leaf) {
      const Leaf* l = static_cast<const Leaf*>(node);
      out_.nodes[at].first = static_cast<std::uint32_t>(out_.records.size());
      out_.nodes[at].count = l->n;
      for (unsigned i = 0; i < l->n; ++i) {
        const rc_amb_record& r = in_[l->ids[i]];
        c = std::min(c, axis_cos(r.nrm, bin_));
        out_.records.push_back(r);
        out_.corral.push_back(corral_[l->ids[i]]);
        out_.source.push_back(source_[l->ids[i]]);
      }
    } else {
      const Inner* in = static_cast<const Inner*>(node);
      for (int k = 0; k < 2; ++k)
        if (in->kids[k]) c = std::min(c, add(in->kids[k], in->box[k]));
    }
    // A little wider than the records' own cone: float normals and the tests' rounding.
    const double h = std::acos(std::clamp(c, -1.0, 1.0)) + 1e-3;
    out_.nodes[at].lo.w = static_cast<float>(std::cos(h));
    out_.nodes[at].hi.w = static_cast<float>(std::sin(h));
    out_.nodes[at].skip = static_cast<std::uint32_t>(out_.nodes.size());
    return c;
  }

private:
  const std::vector<rc_amb_record>& in_;
  const std::vector<std::uint32_t>& corral_;
  const std::vector<std::uint32_t>& source_;
  std::uint32_t bin_;
  AmbientCacheBuffers& out_;
};

// One Embree device for every build: a cache build uploads its tree a few hundred times, and
// a new device per build (thread pool and CPU checks) cost more than building small trees.
RTCDevice builder_device() {
  static const RTCDevice dev = rtcNewDevice(nullptr);
  if (!dev) throw FatalError("cannot create an Embree device for the ambient cache");
  return dev;
}

} // namespace

double ambient_min_radius(double cube_size, int ar) {
  const double r = ar > 0 ? cube_size / ar : 0.0;
  return r <= 1e-6 ? 1e-5 : r;
}

double ambient_max_radius(double cube_size, int ar) {
  double r = ar > 0 ? std::min(64 * cube_size / ar, 0.2 * cube_size) : 0.2 * cube_size;
  const double lo = ambient_min_radius(cube_size, ar);
  return r <= lo ? 64 * lo : r;
}

AmbientCacheBuffers build_ambient_cache(std::span<const ambient::AmbientRecord> records,
                                        const std::array<double, 3>& centre, double aa) {
  AmbientCacheBuffers out;
  std::vector<rc_amb_record> recs;
  std::vector<std::uint32_t> corral, source;
  std::vector<RTCBuildPrimitive> prims;
  for (std::size_t ri = 0; ri < records.size(); ++ri) {
    const ambient::AmbientRecord& r = records[ri];
    if (!(r.rad[0] > 0) || !(r.rad[1] > 0)) continue;
    const auto n = ambient::decode_dir(r.ndir), u = ambient::decode_dir(r.udir);
    const double p[3] = {r.pos[0] - centre[0], r.pos[1] - centre[1], r.pos[2] - centre[2]};
    rc_amb_record a{};
    a.pos = f4(p[0], p[1], p[2], r.weight);
    a.nrm = f4(n[0], n[1], n[2], r.rad[0]);
    a.udir = f4(u[0], u[1], u[2], r.rad[1]);
    a.val = f4(r.val[0], r.val[1], r.val[2], r.lvl);
    a.grad = f4(r.gpos[0], r.gpos[1], r.gdir[0], r.gdir[1]);
    // The region a lookup accepts: within aa * rad[1] in the record's plane and aa * rad[0]
    // along its normal (the behind test's slack included), boxed per axis.
    const double rp = aa * r.rad[1], rn = aa * r.rad[0] + 0.002;
    RTCBuildPrimitive b{};
    float lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      const double e = rp * std::sqrt(std::max(0.0, 1.0 - n[k] * n[k])) + rn * std::fabs(n[k]);
      lo[k] = static_cast<float>(p[k] - e) - 1e-6f * static_cast<float>(1 + std::fabs(p[k]));
      hi[k] = static_cast<float>(p[k] + e) + 1e-6f * static_cast<float>(1 + std::fabs(p[k]));
    }
    b.lower_x = lo[0];
    b.lower_y = lo[1];
    b.lower_z = lo[2];
    b.upper_x = hi[0];
    b.upper_y = hi[1];
    b.upper_z = hi[2];
    b.geomID = 0;
    b.primID = static_cast<unsigned>(recs.size());
    prims.push_back(b);
    recs.push_back(a);
    corral.push_back(r.corral);
    source.push_back(static_cast<std::uint32_t>(ri));
  }
  if (recs.empty()) return out;

  // One tree per orientation bin, in bin order (rc_amb_node).
  RTCDevice dev = builder_device();
  out.records.reserve(recs.size());
  out.corral.reserve(recs.size());
  out.source.reserve(recs.size());
  for (std::uint32_t bin = 0; bin < RC_AMB_BINS; ++bin) {
    std::vector<RTCBuildPrimitive> part;
    for (const RTCBuildPrimitive& b : prims)
      if (normal_bin(recs[b.primID].nrm) == bin) part.push_back(b);
    if (part.empty()) continue;
    RTCBounds all{};
    all.lower_x = all.lower_y = all.lower_z = INFINITY;
    all.upper_x = all.upper_y = all.upper_z = -INFINITY;
    for (const RTCBuildPrimitive& b : part) {
      all.lower_x = std::min(all.lower_x, b.lower_x);
      all.lower_y = std::min(all.lower_y, b.lower_y);
      all.lower_z = std::min(all.lower_z, b.lower_z);
      all.upper_x = std::max(all.upper_x, b.upper_x);
      all.upper_y = std::max(all.upper_y, b.upper_y);
      all.upper_z = std::max(all.upper_z, b.upper_z);
    }
    RTCBVH bvh = rtcNewBVH(dev);
    RTCBuildArguments a = rtcDefaultBuildArguments();
    a.byteSize = sizeof(a);
    a.buildFlags = RTC_BUILD_FLAG_NONE;
    a.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
    a.maxBranchingFactor = 2;
    a.maxDepth = 1024;
    a.sahBlockSize = 1;
    a.minLeafSize = 1;
    a.maxLeafSize = kMaxLeaf;
    a.traversalCost = 1.0f;
    a.intersectionCost = 1.0f;
    a.bvh = bvh;
    a.primitives = part.data();
    a.primitiveCount = part.size();
    a.primitiveArrayCapacity = part.size();
    a.createNode = create_node;
    a.setNodeChildren = set_children;
    a.setNodeBounds = set_bounds;
    a.createLeaf = create_leaf;
    void* root = rtcBuildBVH(&a);
    if (!root) {
      rtcReleaseBVH(bvh);
      throw FatalError("cannot build the ambient cache's BVH");
    }
    Flattener(recs, corral, source, bin, out).add(static_cast<const Node*>(root), all);
    rtcReleaseBVH(bvh);
  }
  if (out.records.size() != recs.size())
    throw FatalError("ambient cache BVH lost records"); // a leaf larger than kMaxLeaf
  return out;
}

AmbientCacheBuffers join_ambient_caches(const AmbientCacheBuffers& a, const AmbientCacheBuffers& b,
                                        std::uint32_t b_offset) {
  AmbientCacheBuffers out = a;
  rejoin_ambient_caches(out, a.nodes.size(), a.records.size(), b, b_offset);
  return out;
}

void rejoin_ambient_caches(AmbientCacheBuffers& ab, std::size_t a_nodes, std::size_t a_records,
                           const AmbientCacheBuffers& b, std::uint32_t b_offset) {
  ab.nodes.resize(a_nodes);
  ab.records.resize(a_records);
  ab.corral.resize(a_records);
  ab.source.resize(a_records);
  // The forests side by side: a's trees, then b's (the traversal walks one after another).
  const auto na = static_cast<std::uint32_t>(a_nodes);
  const auto ra = static_cast<std::uint32_t>(a_records);
  for (rc_amb_node n : b.nodes) {
    n.skip += na;
    if (n.count) n.first += ra;
    ab.nodes.push_back(n);
  }
  ab.records.insert(ab.records.end(), b.records.begin(), b.records.end());
  ab.corral.insert(ab.corral.end(), b.corral.begin(), b.corral.end());
  for (std::uint32_t x : b.source)
    ab.source.push_back(x + b_offset);
}

std::array<double, 3> averaged_ambient_value(const std::array<double, 3>& av, int aw,
                                             std::span<const ambient::AmbientRecord> records) {
  if (aw <= 0) return av;
  double sum = 0;
  std::size_t n = 0;
  for (const ambient::AmbientRecord& a : records) {
    double b = bright(a.val[0], a.val[1], a.val[2]);
    if (b > 1e-6) { // Radiance's FTINY
      sum += std::log(b);
      ++n;
    }
  }
  if (n == 0) return av;
  const double k = std::log(0.5); // each bounce absorbs half on average (AVGREFL)
  const double l = bright(av[0], av[1], av[2]);
  if (l > 1e-6) {
    double f = std::exp((std::log(l) * aw + sum + k * static_cast<double>(n)) /
                        (aw + static_cast<double>(n))) /
               l;
    return {av[0] * f, av[1] * f, av[2] * f};
  }
  double g = std::exp(sum / static_cast<double>(n) + k);
  return {g, g, g};
}

} // namespace radcl::ambient
