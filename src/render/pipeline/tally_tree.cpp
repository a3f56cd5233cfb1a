#include "radcl/render/pipeline/tally_tree.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>

#include "radcl/luminance.h"
#include "radcl/rng.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace radcl::render {

namespace {

constexpr double kFtiny = 1e-6;

} // namespace

void TallyTree::reset(std::size_t primaries, std::uint32_t seed, bool trace, bool spread) {
  nodes_.assign(primaries, fresh_node(Kind::Primary, RC_NONE, 0));
  variance_.assign(spread ? primaries : 0, Vec3d{});
  hemis_.clear();
  requests_.clear();
  traced_.clear();
  trace_ = trace;
  seed_ = seed;
  for (std::size_t i = 0; i < primaries; ++i) {
    nodes_[i].pending = 1;
    if (trace) {
      nodes_[i].traced = static_cast<std::uint32_t>(i);
      traced_.emplace_back();
      traced_.back().node = static_cast<std::uint32_t>(i);
    }
  }
}

std::uint32_t TallyTree::ray_node(std::uint32_t parent, std::uint32_t rec) {
  Node n = fresh_node(Kind::Ray, parent, 1);
  n.traced = static_cast<std::uint32_t>(traced_.size());
  std::uint32_t id = static_cast<std::uint32_t>(nodes_.size());
  traced_.emplace_back();
  traced_.back().node = id;
  traced_[rec].kids.push_back(n.traced);
  nodes_.push_back(n);
  ++nodes_[parent].pending;
  return id;
}

std::vector<std::pair<const TallyTree::Traced*, int>> TallyTree::traced(std::size_t primary) const {
  std::vector<std::pair<const Traced*, int>> out;
  if (!trace_) return out;
  auto visit = [&](auto&& self, std::uint32_t rec, int depth) -> void {
    for (std::uint32_t k : traced_[rec].kids)
      self(self, k, depth + 1);
    out.emplace_back(&traced_[rec], depth);
  };
  visit(visit, static_cast<std::uint32_t>(primary), 0);
  return out;
}

void TallyTree::add(std::uint32_t node, const rc_float4& c, bool mirrored) {
  Node& n = nodes_[node];
  n.sum[0] += c.x;
  n.sum[1] += c.y;
  n.sum[2] += c.z;
  if (mirrored) {
    n.msum[0] += c.x;
    n.msum[1] += c.y;
    n.msum[2] += c.z;
  }
}

std::size_t TallyTree::run_length(const rc_ray* children, std::size_t k, std::size_t nchildren) {
  if (!(children[k].cell & RC_CELL_FLAG)) return 0;
  // A hemisphere's first samples are consecutive, division 0 first.
  const std::uint32_t which = RC_CELL_WHICH(children[k].cell);
  std::size_t m = 0;
  while (k + m < nchildren && (children[k + m].cell & RC_CELL_FLAG) &&
         RC_CELL_WHICH(children[k + m].cell) == which && RC_CELL_INDEX(children[k + m].cell) == m)
    ++m;
  return m;
}

void TallyTree::make_hemi(const rc_ray& ray, const rc_hit& hit, rc_ray* children, std::size_t k,
                          std::size_t m, std::uint32_t node, std::uint32_t hemi) {
  const rc_ray& c = children[k];
  Hemi& h = hemis_[hemi];
  h.ray = ray;
  h.hit = hit;
  h.which = RC_CELL_WHICH(c.cell);
  h.ns = static_cast<std::uint32_t>(std::lround(std::sqrt(static_cast<double>(m))));
  h.budget = RC_CELL_BUDGET(c.cell);
  h.ncells = static_cast<std::uint32_t>(m);
  h.second = false;
  const float pc[3] = {ray.coef.x, ray.coef.y, ray.coef.z};
  const float cc[3] = {c.coef.x, c.coef.y, c.coef.z};
  for (int i = 0; i < 3; ++i)
    h.acoef[i] = pc[i] > 0 ? static_cast<double>(cc[i]) / pc[i] : 0.0;
  h.node = node;
  h.first_cell = node + 1;
  Node& hn = nodes_[node];
  hn = fresh_node(Kind::Hemi, ray.tally, static_cast<std::int64_t>(m));
  hn.hemi = hemi;
  for (std::size_t j = 0; j < m; ++j) {
    Node& cn = nodes_[h.first_cell + j];
    // In trace mode the sample's own node counts.
    cn = fresh_node(Kind::Cell, node, trace_ ? 0 : 1);
    children[k + j].tally = h.first_cell + static_cast<std::uint32_t>(j);
    children[k + j].cell = 0;
  }
}

void TallyTree::shaded(const rc_ray& ray, const rc_hit& hit, const rc_float4& total,
                       rc_ray* children, std::size_t nchildren, const TracedShadow* shadows,
                       std::size_t nshadows) {
  add(ray.tally, total, ray.flags & RC_RAY_MIRRORED);
  std::uint32_t rec = nodes_[ray.tally].traced;
  if (trace_) {
    traced_[rec].ray = ray;
    traced_[rec].hit = hit;
    traced_[rec].shaded = true;
    for (std::size_t k = 0; k < nshadows; ++k) {
      Traced t;
      t.is_shadow = true;
      t.shadow = shadows[k];
      traced_[rec].kids.push_back(static_cast<std::uint32_t>(traced_.size()));
      traced_.push_back(std::move(t));
    }
  }
  for (std::size_t k = 0; k < nchildren;) {
    const std::size_t m = run_length(children, k, nchildren);
    if (m == 0) {
      if (trace_)
        children[k].tally = ray_node(ray.tally, rec);
      else
        ++nodes_[children[k].tally].pending;
      ++k;
      continue;
    }
    const auto node = static_cast<std::uint32_t>(nodes_.size());
    nodes_.resize(nodes_.size() + 1 + m);
    hemis_.emplace_back();
    make_hemi(ray, hit, children, k, m, node, static_cast<std::uint32_t>(hemis_.size() - 1));
    ++nodes_[ray.tally].pending;
    if (trace_) // each sample gets a traced node under its cell
      for (std::size_t j = 0; j < m; ++j)
        children[k + j].tally = ray_node(children[k + j].tally, rec);
    k += m;
  }
  --nodes_[ray.tally].pending;
  settle(ray.tally, requests_);
}

bool TallyTree::count_children(const rc_ray* rays, const rc_ray* children, const std::uint32_t* off,
                               const std::uint32_t* count, const std::uint8_t* cells,
                               std::size_t n) {
  std::atomic<bool> unordered{false};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      if (i > 0 && rays[i].primary < rays[i - 1].primary)
        unordered.store(true, std::memory_order_relaxed);
      std::uint32_t nodes = 0, hemis = 0, plain = 0;
      // A ray the kernel says marked no hemisphere has plain children only: they need not be
      // read (most of a deep generation's rows).
      if (cells && !cells[i]) {
        new_nodes_[i] = 0;
        new_hemis_[i] = 0;
        plain_[i] = count[i];
        continue;
      }
      for (std::size_t k = 0; k < count[i];) {
        const std::size_t m = run_length(children + off[i], k, count[i]);
        if (m == 0) {
          ++plain;
          ++k;
        } else {
          nodes += static_cast<std::uint32_t>(1 + m);
          ++hemis;
          k += m;
        }
      }
      new_nodes_[i] = nodes;
      new_hemis_[i] = hemis;
      plain_[i] = plain;
    }
  });
  return unordered.load();
}

void TallyTree::shaded_slice(const rc_ray* rays, const rc_hit* hits, const rc_float4* totals,
                             rc_ray* children, const std::uint32_t* off, const std::uint32_t* count,
                             const std::uint8_t* cells, std::size_t n) {
  if (trace_) {
    for (std::size_t i = 0; i < n; ++i)
      shaded(rays[i], hits[i], totals[i], children + off[i], count[i]);
    return;
  }
  std::optional<PhaseProfile::StepClock> clock;
  if (prof_) clock.emplace(*prof_);
  const auto mark = [&](PhaseProfile::Step s) {
    if (clock) clock->mark(s);
  };
  new_nodes_.resize(n);
  new_hemis_.resize(n);
  plain_.resize(n);
  // Each ray's hemispheres and the nodes they need, then their places in serial order; and
  // whether the slice runs in primary order (see below), found on the way.
  const bool unordered = count_children(rays, children, off, count, cells, n);
  mark(PhaseProfile::StepTallyChildren);
  const auto node0 = static_cast<std::uint32_t>(nodes_.size());
  const auto hemi0 = static_cast<std::uint32_t>(hemis_.size());
  std::uint32_t tn = 0, th = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t a = new_nodes_[i], b = new_hemis_[i];
    new_nodes_[i] = tn;
    new_hemis_[i] = th;
    tn += a;
    th += b;
  }
  nodes_.resize(nodes_.size() + tn);
  hemis_.resize(hemis_.size() + th);
  mark(PhaseProfile::StepTallyOffsets);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      // Rays without a hemisphere (most, deeper down) need not be read again.
      if ((i + 1 < n ? new_hemis_[i + 1] : th) == new_hemis_[i]) continue;
      std::uint32_t node = node0 + new_nodes_[i], hemi = hemi0 + new_hemis_[i];
      rc_ray* ch = children + off[i];
      for (std::size_t k = 0; k < count[i];) {
        const std::size_t m = run_length(ch, k, count[i]);
        if (m == 0) {
          ++k;
          continue;
        }
        make_hemi(rays[i], hits[i], ch, k, m, node, hemi++);
        node += static_cast<std::uint32_t>(1 + m);
        k += m;
      }
    }
  });
  // In ray order, as shaded() would: the sums, the pending counts, the settling. Rays of
  // different primaries touch different trees, so where the slice runs in primary order (a
  // generation does; super-samples appended after it break the order) runs of whole primaries
  // go on every core, each keeping its rays' order and its own super-sample requests, which
  // are then joined in slice order: the serial order's result.
  const auto finish = [&](std::size_t a, std::size_t b, std::vector<SuperRequest>& req) {
    for (std::size_t i = a; i < b; ++i) {
      const rc_ray& ray = rays[i];
      add(ray.tally, totals[i], ray.flags & RC_RAY_MIRRORED);
      const std::uint32_t hemis = (i + 1 < n ? new_hemis_[i + 1] : th) - new_hemis_[i];
      // A plain child keeps its parent's tally (the kernel copies it), as does a hemisphere.
      nodes_[ray.tally].pending += static_cast<std::int64_t>(plain_[i]) + hemis - 1;
      settle(ray.tally, req);
    }
  };
  mark(PhaseProfile::StepTallyHemis);
  constexpr std::size_t kRun = 4096;
  if (unordered || n < 2 * kRun) {
    finish(0, n, requests_);
    mark(PhaseProfile::StepTallySettle);
    return;
  }
  // Cuts where a primary's rays begin (a primary may have thousands: searched, not walked).
  std::vector<std::size_t> cut{0};
  for (std::size_t at = kRun; at < n; at += kRun) {
    const std::size_t from = std::max(at, cut.back() + 1);
    const std::uint32_t p = rays[from - 1].primary;
    const std::size_t c = static_cast<std::size_t>(
        std::partition_point(rays + from, rays + n,
                             [p](const rc_ray& r) { return r.primary == p; }) -
        rays);
    if (c >= n) break;
    cut.push_back(c);
    at = c;
  }
  cut.push_back(n);
  std::vector<std::vector<SuperRequest>> req(cut.size() - 1);
  tbb::parallel_for(std::size_t{0}, req.size(),
                    [&](std::size_t r) { finish(cut[r], cut[r + 1], req[r]); });
  for (auto& q : req)
    for (auto& x : q)
      requests_.push_back(std::move(x));
  mark(PhaseProfile::StepTallySettle);
}

void TallyTree::supersampled(const SuperRequest& r, rc_ray* children, std::size_t nchildren) {
  const Hemi& h = hemis_[r.hemi];
  std::int64_t cells = 0;
  std::uint32_t last = RC_NONE;
  for (std::size_t k = 0; k < nchildren; ++k) {
    std::uint32_t cell = h.first_cell + RC_CELL_INDEX(children[k].cell);
    // Children come division by division; a division counts once towards the hemisphere.
    if (cell != last) ++cells;
    last = cell;
    ++nodes_[cell].count;
    if (trace_) {
      children[k].tally = ray_node(cell, nodes_[nodes_[h.node].parent].traced);
    } else {
      ++nodes_[cell].pending;
      children[k].tally = cell;
    }
    children[k].cell = 0;
  }
  // The placeholder that kept the hemisphere open while the samples were asked for.
  nodes_[h.node].pending += cells - 1;
  settle(h.node, requests_);
}

// Radiance's ambsupersamp: the budget spread over the divisions in proportion to the
// differences of each division's brightness from its neighbours (getambdiffs).
// Every hemisphere passes here as it resolves (millions in a run without the cache), so the
// working arrays are the thread's own, reused rather than allocated each time.
bool TallyTree::allocate(const Hemi& h, std::vector<std::uint32_t>& counts) const {
  const std::uint32_t ns = h.ns;
  double ab = bright(h.acoef);
  if (h.budget == 0 || ab <= 0 || ns < 2) return false; // no samples to spread, or no spread
  counts.assign(std::size_t{ns} * ns, 0);
  // Two neighbouring divisions whose samples brought nothing at all are black whatever the
  // arithmetic below (see there): found first, from the sums alone, the answer is the same
  // without a division per cell (without the cache every hemisphere passes here, and in a
  // room lit through a window most have such a pair).
  const auto nothing = [&](std::size_t c) {
    const Node& n = nodes_[h.first_cell + c];
    return n.sum[0] == 0 && n.sum[1] == 0 && n.sum[2] == 0;
  };
  for (std::uint32_t i = 0; i < ns; ++i)
    for (std::uint32_t j = 0; j < ns; ++j) {
      const std::size_t a = std::size_t{i} * ns + j;
      if (!nothing(a)) continue;
      if ((i && nothing(a - ns)) || (j && nothing(a - 1)) || (i && j && nothing(a - ns - 1)))
        return false;
    }
  const double normf = 1.0 / ab;
  // Each division's value as Radiance holds it: without the shaded ray's own coefficient.
  const float pc[3] = {h.ray.coef.x, h.ray.coef.y, h.ray.coef.z};
  thread_local std::vector<double> b, e;
  b.resize(counts.size());
  for (std::size_t c = 0; c < b.size(); ++c) {
    const Node& n = nodes_[h.first_cell + c];
    Vec3d v;
    for (int i = 0; i < 3; ++i)
      v[i] = pc[i] > 0 ? n.sum[i] / n.count / pc[i] : 0.0;
    b[c] = bright(v);
  }
  e.assign(b.size(), 0.0);
  // Two neighbouring black divisions: Radiance's estimate divides 0 by 0 there, and the NaN
  // that spreads through its sum stops all super-sampling of the hemisphere. radcl does the
  // same on purpose: which divisions get more samples depends on the first samples' values,
  // and where black divisions are common (rooms lit only through ambient rays) that choice
  // biases the hemisphere low (-14% on office_overcast at -ab 5 -aa 0 -as 256).
  bool black_pair = false;
  auto diff = [&](std::size_t a, std::size_t c) {
    double s = b[a] + b[c];
    if (s <= 0) {
      black_pair = true;
      return;
    }
    double d = b[a] - b[c];
    d *= d * normf / s;
    e[a] += d;
    e[c] += d;
  };
  for (std::uint32_t i = 0; i < ns; ++i)
    for (std::uint32_t j = 0; j < ns; ++j) {
      std::size_t a = std::size_t{i} * ns + j;
      if (i) diff(a, a - ns);
      if (j) diff(a, a - 1);
      if (i && j) diff(a, a - ns - 1);
    }
  if (black_pair) return false;
  // Corners and edges have fewer neighbours.
  auto scale = [&](std::size_t a, double f) { e[a] *= f; };
  scale(0, 8. / 3.);
  scale(ns - 1, 8. / 3.);
  scale(std::size_t{ns - 1} * ns, 8. / 3.);
  scale(std::size_t{ns - 1} * ns + ns - 1, 8. / 3.);
  for (std::uint32_t i = 1; i + 1 < ns; ++i) {
    scale(std::size_t{i} * ns, 8. / 5.);
    scale(std::size_t{i} * ns + ns - 1, 8. / 5.);
    scale(i, 8. / 5.);
    scale(std::size_t{ns - 1} * ns + i, 8. / 5.);
  }
  double rem = 0;
  for (std::size_t c = e.size(); c-- > 0;)
    rem += e[c];
  std::int64_t cnt = h.budget;
  rc_rng_key key = rc_make_key(h.ray.primary, h.ray.sample ^ 0xA11C0CA7u, h.ray.depth, seed_);
  bool any = false;
  for (std::size_t c = 0; c < e.size(); ++c) {
    if (rem <= kFtiny) break;
    double u = rc_random(key, h.which * 65536u + static_cast<std::uint32_t>(c));
    auto nss = static_cast<std::int64_t>(e[c] / rem * static_cast<double>(cnt) + u);
    if (nss > 0) {
      std::int64_t take = std::min(nss, cnt);
      counts[c] = static_cast<std::uint32_t>(take);
      any = any || take > 0;
      cnt -= take;
      if (cnt == 0) break;
    }
    rem -= e[c];
  }
  return any;
}

std::uint32_t TallyTree::primary_of(std::uint32_t node) const {
  while (nodes_[node].kind != Kind::Primary) // trace mode: rays between it and the primary
    node = nodes_[node].parent;
  return node;
}

// The divisions' values are independent draws of stratified sampling, each with a mean of its
// own, so their plain spread would count the hemisphere's variation across divisions as noise.
// The collapsed-strata estimate pairs neighbours instead: a group of g neighbouring values
// contributes g / (g - 1) times its squared deviations from its mean, which estimates the sum
// of their variances, too high by the differences of the neighbours' means. Pairs run along
// the grid's rows (a third joins the last pair of an odd row) or along its columns, whichever
// gives less: a sharp edge in the hemisphere (a window, a sunlit patch) that one way crosses
// many pairs is crossed by fewer the other way (office_clear at -ab 2: the estimate 1.7 times
// the draws' spread along rows alone, 1.1 times with the choice).
// A super-sampled division (-as) enters with its samples' mean. Radiance puts those samples
// where neighbours differ most, so there the pairs' differences are mostly the divisions'
// different means and the estimate stays high (office_clear, -ab 1 -av .5 -as 256: 1.6 times
// the draws' spread); estimating those divisions from their own samples instead came out 20%
// low, as the choice of divisions follows the first samples' values (docs/options.md).
void TallyTree::add_spread(const Hemi& h, std::uint32_t parent) {
  const auto value = [&](std::uint32_t c, int i) {
    const Node& n = nodes_[h.first_cell + c];
    return n.sum[i] / n.count;
  };
  // The estimate over lines of `len` values, value k of line l at at(l, k).
  const auto collapsed = [&](std::uint32_t lines, std::uint32_t len, auto&& at) {
    Vec3d var{};
    for (std::uint32_t l = 0; l < lines; ++l)
      for (std::uint32_t a = 0; a + 1 < len; a += 2) {
        const std::uint32_t g = a + 3 == len ? 3 : 2;
        for (int i = 0; i < 3; ++i) {
          double mean = 0, dev = 0;
          for (std::uint32_t k = 0; k < g; ++k)
            mean += value(at(l, a + k), i) / g;
          for (std::uint32_t k = 0; k < g; ++k)
            dev += (value(at(l, a + k), i) - mean) * (value(at(l, a + k), i) - mean);
          var[i] += dev * g / (g - 1);
        }
        if (g == 3) break;
      }
    return var;
  };
  const std::uint32_t ns = h.ns;
  Vec3d var;
  if (ns >= 2 && h.ncells == ns * ns) {
    const Vec3d rows =
        collapsed(ns, ns, [ns](std::uint32_t l, std::uint32_t k) { return l * ns + k; });
    const Vec3d cols =
        collapsed(ns, ns, [ns](std::uint32_t l, std::uint32_t k) { return k * ns + l; });
    var = bright(rows) <= bright(cols) ? rows : cols;
  } else { // -lw dropped samples: the ones there, in order
    var = collapsed(1, h.ncells, [](std::uint32_t, std::uint32_t k) { return k; });
  }
  Vec3d& v = variance_[primary_of(parent)];
  for (int i = 0; i < 3; ++i)
    v[i] += var[i];
}

TallyTree::Vec3d TallyTree::std_error(std::size_t primary) const {
  const Vec3d& v = variance_.at(primary);
  return {std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2])};
}

void TallyTree::settle(std::uint32_t id, std::vector<SuperRequest>& requests) {
  for (;;) {
    Node& n = nodes_[id];
    if (n.pending != 0 || n.kind == Kind::Primary) return; // waiting, or a finished primary
    if (n.kind == Kind::Cell) { // a division: its hemisphere waits for one fewer
      id = n.parent;
      --nodes_[id].pending;
      continue;
    }
    if (n.kind == Kind::Ray) { // a traced ray: its sum is final and goes to its parent
      Node& p = nodes_[n.parent];
      for (int i = 0; i < 3; ++i) {
        p.sum[i] += n.sum[i];
        p.msum[i] += n.msum[i];
      }
      --p.pending;
      id = n.parent;
      continue;
    }
    Hemi& h = hemis_[n.hemi];
    if (!h.second) {
      h.second = true;
      thread_local std::vector<std::uint32_t> counts;
      if (allocate(h, counts)) {
        nodes_[id].pending = 1;
        requests.push_back(SuperRequest{n.hemi, h.ray, h.hit, h.which, counts});
        return;
      }
    }
    // Resolved: the sum of the divisions' averages goes to the parent.
    Vec3d v{}, mv{};
    for (std::uint32_t c = 0; c < h.ncells; ++c) {
      const Node& cell = nodes_[h.first_cell + c];
      if (cell.count == 1) { // x / 1 is x, bit for bit: no division for most cells
        for (int i = 0; i < 3; ++i) {
          v[i] += cell.sum[i];
          mv[i] += cell.msum[i];
        }
        continue;
      }
      for (int i = 0; i < 3; ++i) {
        v[i] += cell.sum[i] / cell.count;
        mv[i] += cell.msum[i] / cell.count;
      }
    }
    std::uint32_t parent = n.parent;
    if (!variance_.empty() && h.ray.ambient_depth == 0) add_spread(h, parent);
    Node& p = nodes_[parent];
    for (int i = 0; i < 3; ++i) {
      p.sum[i] += v[i];
      p.msum[i] += mv[i];
    }
    --p.pending;
    id = parent;
  }
}

} // namespace radcl::render
