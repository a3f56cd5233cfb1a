// The BVH over irradiance-cache records (ambient/cache.h): every record in exactly one
// leaf, every record's region inside the boxes of the nodes above it, and skip links that
// visit each subtree once; the minimum radius as Radiance's setambres().
#include "radcl/luminance.h"
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <set>

#include "radcl/ambient/cache.h"
#include "radcl/ambient/dircode.h"

using namespace radcl;

namespace {

std::vector<ambient::AmbientRecord> random_records(int n, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<float> u(-10, 10), r(0.01f, 0.5f), s(-1, 1);
  std::vector<ambient::AmbientRecord> out;
  for (int i = 0; i < n; ++i) {
    ambient::AmbientRecord a;
    a.pos = {u(g), u(g), u(g)};
    ambient::Dir nd{s(g), s(g), s(g)};
    double l = std::sqrt(nd[0] * nd[0] + nd[1] * nd[1] + nd[2] * nd[2]);
    for (auto& c : nd)
      c /= l;
    // A unit u axis perpendicular to the normal.
    ambient::Dir t = std::fabs(nd[0]) < 0.6 ? ambient::Dir{1, 0, 0} : ambient::Dir{0, 1, 0};
    ambient::Dir ud{nd[1] * t[2] - nd[2] * t[1], nd[2] * t[0] - nd[0] * t[2],
                    nd[0] * t[1] - nd[1] * t[0]};
    l = std::sqrt(ud[0] * ud[0] + ud[1] * ud[1] + ud[2] * ud[2]);
    for (auto& c : ud)
      c /= l;
    a.ndir = ambient::encode_dir(nd);
    a.udir = ambient::encode_dir(ud);
    float r0 = r(g), r1 = r(g);
    a.rad = {std::min(r0, r1), std::max(r0, r1)};
    a.weight = 1;
    a.val = {float(i), 0, 0}; // identifies the record after reordering
    out.push_back(a);
  }
  return out;
}

// Walks the tree: every node's subtree is [i + 1, skip) and its boxes hold its records' regions.
// Returns the number of leaves.
std::size_t check_tree(const ambient::AmbientCacheBuffers& b, double aa) {
  std::vector<std::size_t> stack;
  std::size_t leaves = 0;
  for (std::size_t i = 0; i < b.nodes.size(); ++i) {
    const rc_amb_node& nd = b.nodes[i];
    EXPECT_GT(nd.skip, i);
    EXPECT_LE(nd.skip, b.nodes.size());
    while (!stack.empty() && b.nodes[stack.back()].skip <= i)
      stack.pop_back();
    if (nd.count) {
      ++leaves;
      EXPECT_EQ(nd.skip, i + 1);
      for (std::uint32_t k = nd.first; k < nd.first + nd.count; ++k) {
        const rc_amb_record& r = b.records[k];
        const float p[3] = {r.pos.x, r.pos.y, r.pos.z}, n[3] = {r.nrm.x, r.nrm.y, r.nrm.z};
        std::vector<std::size_t> up = stack;
        up.push_back(i);
        for (std::size_t a : up) {
          const rc_amb_node& box = b.nodes[a];
          // The record's normal inside the node's cone (cos h in lo.w) about its bin's axis.
          const float ax = box.bin < 2 ? n[0] : (box.bin < 4 ? n[1] : n[2]);
          EXPECT_GE(box.bin & 1u ? -ax : ax, box.lo.w) << "node " << a;
          EXPECT_NEAR(box.lo.w * box.lo.w + box.hi.w * box.hi.w, 1.0f, 1e-5f);
          const float lo[3] = {box.lo.x, box.lo.y, box.lo.z},
                      hi[3] = {box.hi.x, box.hi.y, box.hi.z};
          for (int c = 0; c < 3; ++c) {
            // The disc of radius aa * rad[1] and the slab of aa * rad[0] along the normal.
            const float e =
                0.999f * float(aa) *
                (r.udir.w * std::sqrt(std::max(0.0f, 1 - n[c] * n[c])) + r.nrm.w * std::fabs(n[c]));
            EXPECT_LE(lo[c], p[c] - e);
            EXPECT_GE(hi[c], p[c] + e);
          }
        }
      }
    }
    stack.push_back(i);
  }
  return leaves;
}

} // namespace

TEST(AmbientCacheBvh, EveryRecordOnceInsideItsAncestors) {
  for (int n : {1, 2, 7, 9, 100, 5000}) {
    auto recs = random_records(n, 17u + n);
    const std::array<double, 3> centre{1, 2, 3};
    const double aa = 0.2;
    ambient::AmbientCacheBuffers b = ambient::build_ambient_cache(recs, centre, aa);
    ASSERT_EQ(b.records.size(), recs.size());
    std::set<int> seen;
    for (const rc_amb_record& r : b.records)
      seen.insert(int(r.val.x));
    EXPECT_EQ(seen.size(), recs.size());
    const std::size_t leaves = check_tree(b, aa);
    EXPECT_GE(leaves, (recs.size() + 7) / 8);
    // Positions are re-centred.
    bool found = false;
    for (const rc_amb_record& r : b.records)
      if (int(r.val.x) == 0) {
        EXPECT_NEAR(r.pos.x, recs[0].pos[0] - 1, 1e-5);
        EXPECT_NEAR(r.pos.z, recs[0].pos[2] - 3, 1e-5);
        found = true;
      }
    EXPECT_TRUE(found);
  }
}

// A walk that skips the nodes whose boxes miss the point or whose normal cones cannot come
// within theta of the lookup's normal still meets every record within theta that covers the
// point (the kernel's lookup and the leak test walk so).
TEST(AmbientCacheBvh, NormalConesKeepEveryAcceptableRecord) {
  auto recs = random_records(3000, 5u);
  // Surfaces of a room as well: many records share an axis-aligned normal.
  for (int i = 0; i < 1000; ++i) {
    ambient::AmbientRecord a = recs[static_cast<std::size_t>(i)];
    const int k = i % 6;
    ambient::Dir nd{0, 0, 0}, ud{0, 0, 0};
    nd[k / 2] = k % 2 ? -1 : 1;
    ud[(k / 2 + 1) % 3] = 1;
    a.ndir = ambient::encode_dir(nd);
    a.udir = ambient::encode_dir(ud);
    a.val = {float(3000 + i), 0, 0};
    recs.push_back(a);
  }
  const double aa = 0.2;
  ambient::AmbientCacheBuffers b = ambient::build_ambient_cache(recs, {0, 0, 0}, aa);
  check_tree(b, aa);
  std::mt19937 g(11);
  std::uniform_real_distribution<double> s(-1, 1), th(0.0, 1.5707963);
  std::size_t found = 0, skipped = 0;
  for (int q = 0; q < 1000; ++q) {
    const rc_amb_record& r = b.records[static_cast<std::size_t>(q) * 7 % b.records.size()];
    const float p[3] = {r.pos.x + 0.01f * float(s(g)), r.pos.y, r.pos.z};
    std::array<double, 3> n{s(g), s(g), s(g)};
    if (q % 2) n = {r.nrm.x + 0.3 * s(g), r.nrm.y + 0.3 * s(g), r.nrm.z + 0.3 * s(g)};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& c : n)
      c /= l;
    const double theta = th(g), ct = std::cos(theta), st = std::sin(theta);
    std::set<std::uint32_t> walked;
    for (std::uint32_t i = 0; i < b.nodes.size();) {
      const rc_amb_node& nd = b.nodes[i];
      if (p[0] < nd.lo.x || p[1] < nd.lo.y || p[2] < nd.lo.z || p[0] > nd.hi.x || p[1] > nd.hi.y ||
          p[2] > nd.hi.z || !ambient::node_cone_may_hold(nd, n, ct, st, false)) {
        skipped += nd.skip - i;
        i = nd.skip;
        continue;
      }
      for (std::uint32_t k = nd.first; k < nd.first + nd.count; ++k)
        walked.insert(k);
      i = nd.count ? nd.skip : i + 1;
    }
    for (std::uint32_t k = 0; k < b.records.size(); ++k) {
      const rc_amb_record& a = b.records[k];
      const double d = a.nrm.x * n[0] + a.nrm.y * n[1] + a.nrm.z * n[2];
      const double dx = p[0] - a.pos.x, dy = p[1] - a.pos.y, dz = p[2] - a.pos.z;
      const double reach = 0.9 * aa * std::min(a.nrm.w, a.udir.w);
      if (d > ct + 1e-6 && dx * dx + dy * dy + dz * dz < reach * reach) {
        EXPECT_TRUE(walked.count(k)) << "query " << q << " record " << k;
        ++found;
      }
    }
  }
  EXPECT_GT(found, 500u) << found; // the queries do meet records
  EXPECT_GT(skipped, 0u);
}

TEST(AmbientCacheBvh, NoRecordsNoNodes) {
  ambient::AmbientCacheBuffers b = ambient::build_ambient_cache({}, {0, 0, 0}, 0.1);
  EXPECT_TRUE(b.nodes.empty());
  EXPECT_TRUE(b.records.empty());
}

TEST(AmbientCacheBvh, MinimumRadiusAsSetambres) {
  EXPECT_DOUBLE_EQ(ambient::ambient_min_radius(25.6, 256), 0.1);
  EXPECT_DOUBLE_EQ(ambient::ambient_min_radius(25.6, 0), 1e-5);
  EXPECT_DOUBLE_EQ(ambient::ambient_max_radius(25.6, 256), 0.2 * 25.6); // 6.4 > a fifth
  EXPECT_DOUBLE_EQ(ambient::ambient_max_radius(1000, 1000), 64.0);
  EXPECT_DOUBLE_EQ(ambient::ambient_max_radius(25.6, 0), 0.2 * 25.6);
}

// -aw (Radiance's dumbamb): the log-domain running average of -av with the records' values.
TEST(AmbientValueWeight, AveragesInTheLogDomain) {
  std::vector<ambient::AmbientRecord> recs(3);
  recs[0].val = {1, 1, 1};
  recs[1].val = {4, 4, 4};
  recs[2].val = {0, 0, 0}; // black values are not counted
  const double k = std::log(0.5);
  // Grey -av 2 with weight 2: exp((2 ln 2 + ln 1 + ln 4 + 2 k) / 4) / 2 times -av.
  auto v = ambient::averaged_ambient_value({2, 2, 2}, 2, recs);
  double f = std::exp((2 * std::log(2.0) + std::log(4.0) + 2 * k) / 4) / 2;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(v[c], 2 * f, 1e-12);
  // A coloured -av keeps its colour, scaled by its brightness's new average.
  v = ambient::averaged_ambient_value({1, 0.5, 0.25}, 1, recs);
  double l = radcl::bright(1.0, 0.5, 0.25);
  f = std::exp((std::log(l) + std::log(4.0) + 2 * k) / 3) / l;
  EXPECT_NEAR(v[0], f, 1e-12);
  EXPECT_NEAR(v[1], 0.5 * f, 1e-12);
  EXPECT_NEAR(v[2], 0.25 * f, 1e-12);
  // Black -av: the records' geometric mean times 0.5, grey.
  v = ambient::averaged_ambient_value({0, 0, 0}, 1, recs);
  EXPECT_NEAR(v[1], 0.5 * 2.0, 1e-12);
  // -aw 0, or no value to average: -av unchanged.
  v = ambient::averaged_ambient_value({2, 3, 4}, 0, recs);
  EXPECT_EQ(v[1], 3);
  v = ambient::averaged_ambient_value({2, 3, 4}, 5, {});
  EXPECT_EQ(v[2], 4);
}

// A tree over the newest records joined to the one over the rest: one tree whose walk holds
// every record once, inside its ancestors' boxes, in the order a's records then b's, with b's
// source indices raised past a's input.
TEST(AmbientCacheBvh, JoinedTreesHoldBothRecordSets) {
  const double aa = 0.15;
  for (auto [na, nb] : {std::pair{0, 5}, {5, 0}, {1, 1}, {300, 7}, {2000, 600}}) {
    auto all = random_records(na + nb, 99u + na);
    std::span<const ambient::AmbientRecord> sa(all.data(), na), sb(all.data() + na, nb);
    ambient::AmbientCacheBuffers a = ambient::build_ambient_cache(sa, {0, 0, 0}, aa);
    ambient::AmbientCacheBuffers b = ambient::build_ambient_cache(sb, {0, 0, 0}, aa);
    ambient::AmbientCacheBuffers j =
        ambient::join_ambient_caches(a, b, static_cast<std::uint32_t>(na));
    ASSERT_EQ(j.records.size(), all.size());
    ASSERT_EQ(j.source.size(), all.size());
    ASSERT_EQ(j.corral.size(), all.size());
    if (!all.empty()) check_tree(j, aa);
    std::set<std::uint32_t> seen;
    for (std::size_t k = 0; k < j.records.size(); ++k) {
      // val.x names the record: its source index must point back at it.
      EXPECT_EQ(int(j.records[k].val.x), int(all[j.source[k]].val[0]));
      EXPECT_EQ(k < a.records.size(), j.source[k] < std::uint32_t(na));
      seen.insert(j.source[k]);
    }
    EXPECT_EQ(seen.size(), all.size());
  }
}
