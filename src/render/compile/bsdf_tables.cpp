#include "radcl/render/compile/bsdf_tables.h"

#include "radcl/util/error.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <utility>

namespace radcl::render {

namespace {

using bsdf::Component;
using bsdf::Format;
using bsdf::Part;
using bsdf::TensorTree;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinLamb = 0.01 / kPi;     // a smaller minimum is not split off (Radiance)
constexpr double kMaxGreyLamb = 1.5 / kPi;  // nor one this large, for grey trees
constexpr double kDropHemi = 0.001;         // a residual with no larger maxHemi is dropped
constexpr double kFtiny = 1e-6;             // Radiance's FTINY in its strip loops
constexpr size_t kMaxElements = INT32_MAX;  // offsets are 32-bit on the device
constexpr size_t kMaxNodes = 1u << 24;      // of one merged tree (about 1 GB on the host)
constexpr size_t kMaxTreeFloats = 1u << 26; // its slice tables

struct Xyz {
  double x = 0, y = 0, z = 0;
};

rc_float4 float4_of(const Xyz& c) {
  return {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z), 0.0f};
}

bool transmission(Part p) {
  return p == Part::TransmitFront || p == Part::TransmitBack;
}

[[noreturn]] void too_large(const std::string& file, const std::string& direction) {
  throw FatalError("BSDF \"" + file + "\": \"" + direction + "\" too large for the device tables");
}

template <class T>
void check_room(const std::vector<T>& v, size_t more, const std::string& file,
                const std::string& direction) {
  if (v.size() + more > kMaxElements) too_large(file, direction);
}

// ---- Tensor trees: the Y, u' and v' trees merged, grids divided into single values. ----

// A position in a TensorTree: a node, and inside a leaf grid of resolution 2^g the sub-cell
// `o` at resolution 2^level (the whole grid at level 0, one value at level g).
struct Cursor {
  const TensorTree* t;
  int32_t k;
  int level;
  std::array<int, 4> o;

  int grid() const { return t->nodes[k]; }
  bool leaf() const { return grid() >= 0 && level == grid(); }
  Cursor child(int c) const {
    if (grid() < 0) return {t, t->nodes[k + 1 + c], 0, {}};
    if (leaf()) return *this;
    Cursor r = *this;
    for (int d = 0; d < t->ndim; ++d)
      r.o[d] = 2 * o[d] + ((c >> d) & 1);
    ++r.level;
    return r;
  }
  double value() const {
    const size_t n = size_t{1} << grid();
    size_t index = 0;
    for (int d = 0; d < t->ndim; ++d) // dimension 0 slowest, as TensorTree::lookup
      index = index * n + o[d];
    return t->values[t->nodes[k + 1] + index];
  }
};

struct Node {
  Xyz v;                   // a leaf's value
  int32_t kids = -1;       // a branch: offset of its 2^ndim children in Tree::kids; -1: a leaf
  int height = 0;          // levels of branches, this one included
  size_t fwd = 0, rev = 0; // a branch: offsets of its slice tables in Tree::table
  bool leaf() const { return kids < 0; }
};

// Which dimensions a slice table fixes and which the descent picks (bsdf_device_types.h).
struct SliceDims {
  int nfixed;
  std::array<int, 2> fixed, pick;
};

struct Tree {
  int ndim = 0;
  bool colour = false;
  std::vector<Node> nodes; // root at 0; children after their parent
  std::vector<int32_t> kids;
  std::vector<double> table;

  int32_t kid(const Node& n, int c) const { return kids[n.kids + c]; }

  int32_t merge(const std::array<Cursor, 3>& cur, int ncur, int depth, const std::string& file,
                const std::string& name) {
    bool leaf = true;
    for (int i = 0; i < ncur; ++i)
      leaf = leaf && cur[i].leaf();
    const auto at = static_cast<int32_t>(nodes.size());
    if (nodes.size() >= kMaxNodes || depth > 64) too_large(file, name);
    nodes.emplace_back();
    if (leaf) {
      const double y = cur[0].value();
      Xyz v{y, y, y};
      if (ncur == 3) { // CIE 1976 u', v' to X and Z, as radcl::bsdf::f
        const double u = cur[1].value(), w = cur[2].value();
        if (w > 0) v = {y * 9 * u / (4 * w), y, y * (12 - 3 * u - 20 * w) / (4 * w)};
      }
      nodes[at].v = v;
      return at;
    }
    const auto first = static_cast<int32_t>(kids.size());
    kids.resize(kids.size() + (size_t{1} << ndim));
    int height = 0;
    for (int c = 0; c < (1 << ndim); ++c) {
      std::array<Cursor, 3> sub = cur;
      for (int i = 0; i < ncur; ++i)
        sub[i] = cur[i].child(c);
      const int32_t k = merge(sub, ncur, depth + 1, file, name);
      kids[first + c] = k;
      height = std::max(height, nodes[k].height);
    }
    nodes[at].kids = first;
    nodes[at].height = height + 1;
    return at;
  }

  template <class F> void each_leaf(int32_t n, F&& f) {
    if (nodes[n].leaf()) return f(nodes[n].v);
    for (int c = 0; c < (1 << ndim); ++c)
      each_leaf(kid(nodes[n], c), f);
  }

  // The leaves a lookup reaches: TT3 reads only the lower half of its incident dimension.
  template <class F> void each_reachable_leaf(F&& f) {
    if (ndim == 4 || nodes[0].leaf()) return each_leaf(0, f);
    for (int c = 0; c < 8; c += 2)
      each_leaf(kid(nodes[0], c), f);
  }

  // Radiance's split (bsdf_tables.h): returns the Lambertian part, subtracted from the leaves.
  Xyz split_lambertian() {
    const double inf = std::numeric_limits<double>::infinity();
    Xyz m{inf, inf, inf};
    each_reachable_leaf([&](Xyz& v) {
      m = {std::min(m.x, v.x), std::min(m.y, v.y), std::min(m.z, v.z)};
    });
    if (!(m.y > kMinLamb) || (!colour && m.y >= kMaxGreyLamb)) return {};
    if (!colour) m.x = m.z = m.y;
    each_leaf(0, [&](Xyz& v) { // the unread half may go below: clamped, as Radiance does
      v = {std::max(0.0, v.x - m.x), std::max(0.0, v.y - m.y), std::max(0.0, v.z - m.z)};
    });
    return m;
  }

  // The mean Y of node n over the picked dimensions in cell `at` of its (rev: reverse) table.
  double mean(const Node& n, size_t at, bool rev) const {
    return n.leaf() ? n.v.y : table[(rev ? n.rev : n.fwd) + at];
  }

  // Slice tables of every branch, children first (they follow their parents in `nodes`).
  void slices(const SliceDims& s, bool rev, const std::string& file, const std::string& name) {
    for (size_t n = nodes.size(); n-- > 0;) {
      if (nodes[n].leaf()) continue;
      const Node& nd = nodes[n];
      const int h = nd.height;
      const size_t side = size_t{1} << h;
      const size_t size = s.nfixed == 1 ? side : side * side;
      if (h > 26 || table.size() + size > kMaxTreeFloats) too_large(file, name);
      (rev ? nodes[n].rev : nodes[n].fwd) = table.size();
      for (size_t cell = 0; cell < size; ++cell) {
        // The cell's index per fixed dimension, the half it lies in, its place in that half.
        std::array<size_t, 2> k{cell, 0};
        if (s.nfixed == 2) k = {cell >> h, cell & (side - 1)};
        int base = 0;
        std::array<size_t, 2> rel{};
        for (int d = 0; d < s.nfixed; ++d) {
          base |= static_cast<int>(k[d] >> (h - 1)) << s.fixed[d];
          rel[d] = k[d] & ((side >> 1) - 1);
        }
        double sum = 0;
        for (int q = 0; q < 4; ++q) {
          const Node& c = nodes[kid(nd, base | (q & 1) << s.pick[0] | (q >> 1) << s.pick[1])];
          const int shift = h - 1 - c.height;
          size_t at = rel[0] >> shift;
          if (s.nfixed == 2) at = (at << c.height) | (rel[1] >> shift);
          sum += mean(c, at, rev);
        }
        table.push_back(sum / 4);
      }
    }
  }
};

// Radiance's step for maxHemi: the smallest leaf of the Y tree as read, at least 1/32.
double smallest_leaf(const TensorTree& t, int32_t k) {
  if (t.nodes[k] >= 0) return std::ldexp(1.0, -t.nodes[k]);
  double m = 1;
  for (int c = 0; c < (1 << t.ndim); ++c)
    m = std::min(m, smallest_leaf(t, t.nodes[k + 1 + c]));
  return m / 2;
}

// The largest leaf of the Y tree as read (a leaf grid's cells count as leaves).
double largest_leaf(const TensorTree& t, int32_t k) {
  if (t.nodes[k] >= 0) return std::ldexp(1.0, -t.nodes[k]);
  double m = 0;
  for (int c = 0; c < (1 << t.ndim); ++c)
    m = std::max(m, largest_leaf(t, t.nodes[k + 1 + c]));
  return m / 2;
}

// pi times the largest mean of the residual over strips of the incident dimensions, from the
// root's forward slice table (whose cells are no wider than the strips: the tree has leaves
// at least as small as `step`).
double tree_max_hemi(const Tree& tr, double step) {
  const size_t side = size_t{1} << tr.nodes[0].height;
  const double limit = tr.ndim == 3 ? 0.5 - kFtiny : 1 - kFtiny;
  const size_t strips = static_cast<size_t>(std::ceil(limit / step));
  auto cells = [&](size_t i) { // the table cells of strip i along one dimension
    const auto a = static_cast<size_t>(std::floor(i * step * side));
    return std::pair{a, std::max(a + 1, static_cast<size_t>(std::ceil((i + 1) * step * side)))};
  };
  double best = 0;
  for (size_t i = 0; i < strips; ++i)
    for (size_t j = 0; j < (tr.ndim == 3 ? 1 : strips); ++j) {
      const auto [a0, a1] = cells(i);
      const auto [b0, b1] = tr.ndim == 3 ? std::pair<size_t, size_t>{0, 1} : cells(j);
      double sum = 0;
      for (size_t a = a0; a < std::min(side, a1); ++a)
        for (size_t b = b0; b < std::min(tr.ndim == 3 ? 1 : side, b1); ++b)
          sum += tr.mean(tr.nodes[0], tr.ndim == 3 ? a : a * side + b, false);
      const double n =
          double(std::min(side, a1) - a0) * (tr.ndim == 3 ? 1.0 : double(std::min(side, b1) - b0));
      best = std::max(best, sum / n);
    }
  return kPi * best;
}

} // namespace

std::uint32_t BsdfTables::add_basis(const bsdf::KlemsBasis& b, const std::string& file) {
  std::vector<double> key{static_cast<double>(b.rings())};
  for (int r = 0; r < b.rings(); ++r)
    key.insert(key.end(), {b.theta_lower(r), b.theta_upper(r), static_cast<double>(b.nphis(r))});
  if (auto it = bases_.find(key); it != bases_.end()) return it->second;
  check_room(vals, b.rings() + 1 + b.size(), file, b.name());
  check_room(ints, 4 + 2 * b.rings(), file, b.name());
  const auto at = static_cast<std::uint32_t>(ints.size());
  ints.insert(ints.end(), {b.rings(), b.size(), static_cast<int32_t>(vals.size()),
                           static_cast<int32_t>(vals.size() + b.rings() + 1)});
  vals.push_back(static_cast<float>(b.theta_lower(0)));
  for (int r = 0; r < b.rings(); ++r)
    vals.push_back(static_cast<float>(b.theta_upper(r)));
  for (int p = 0; p < b.size(); ++p)
    vals.push_back(static_cast<float>(b.lambda(p)));
  for (int r = 0; r < b.rings(); ++r)
    ints.insert(ints.end(), {b.nphis(r), b.first_patch(r)});
  bases_.emplace(std::move(key), at);
  return at;
}

bool BsdfTables::add_klems(const Component& c, const std::string& file, rc_bsdf_comp& rec) {
  const bsdf::KlemsMatrix& m = c.klems;
  const int ni = m.in_basis.size(), no = m.out_basis.size();
  const size_t n = static_cast<size_t>(ni) * no;
  const bool colour = c.colour();
  auto low = [](const std::vector<float>& v) { return *std::min_element(v.begin(), v.end()); };
  Xyz lamb;
  if (low(m.y) > kMinLamb)
    lamb = colour ? Xyz{low(m.x), low(m.y), low(m.z)} : Xyz{low(m.y), low(m.y), low(m.y)};
  double hemi = 0;
  for (int i = 0; i < ni; ++i) {
    double sum = 0;
    for (int o = 0; o < no; ++o)
      sum += m.out_basis.lambda(o) * m.y[o * size_t(ni) + i];
    hemi = std::max(hemi, sum);
  }
  rec.lamb = float4_of(lamb);
  rec.max_hemi = static_cast<float>(hemi - kPi * lamb.y);
  double lo = kPi, hi = 0; // Radiance's minProjSA over both bases' patches
  for (const bsdf::KlemsBasis* b : {&m.in_basis, &m.out_basis})
    for (int p = 0; p < b->size(); ++p) {
      lo = std::min(lo, b->lambda(p));
      hi = std::max(hi, b->lambda(p));
    }
  rec.min_psa = static_cast<float>(lo);
  rec.max_psa = static_cast<float>(hi);
  if (rec.max_hemi <= kDropHemi) return false;

  rec.in_basis = add_basis(m.in_basis, file);
  rec.out_basis = add_basis(m.out_basis, file);
  rec.n_in = ni;
  rec.n_out = no;
  const bool reverse = transmission(c.part);
  check_room(vals, n * (colour ? 3 : 1) + n * (reverse ? 2 : 1), file, c.direction);
  // Residual values computed in double from the floats read, so lamb + residual rounds back.
  std::vector<double> y(n);
  for (size_t k = 0; k < n; ++k)
    y[k] = double(m.y[k]) - lamb.y;
  rec.values = static_cast<std::uint32_t>(vals.size());
  for (double v : y)
    vals.push_back(static_cast<float>(v));
  if (colour) {
    for (size_t k = 0; k < n; ++k)
      vals.push_back(static_cast<float>(double(m.x[k]) - lamb.x));
    for (size_t k = 0; k < n; ++k)
      vals.push_back(static_cast<float>(double(m.z[k]) - lamb.z));
  }
  rec.cdf = static_cast<std::uint32_t>(vals.size());
  for (int i = 0; i < ni; ++i) {
    double sum = 0;
    for (int o = 0; o < no; ++o)
      vals.push_back(static_cast<float>(sum += y[o * size_t(ni) + i] * m.out_basis.lambda(o)));
  }
  rec.rcdf = RC_NONE;
  if (reverse) {
    rec.rcdf = static_cast<std::uint32_t>(vals.size());
    for (int o = 0; o < no; ++o) {
      double sum = 0;
      for (int i = 0; i < ni; ++i)
        vals.push_back(static_cast<float>(sum += y[o * size_t(ni) + i] * m.in_basis.lambda(i)));
    }
  }
  return true;
}

bool BsdfTables::add_tree(const Component& c, const std::string& file, rc_bsdf_comp& rec) {
  const bsdf::TreeSet& ts = c.tree;
  Tree tr;
  tr.ndim = ts.y.ndim;
  tr.colour = c.colour();
  const std::string& name = c.direction;
  tr.merge({Cursor{&ts.y, 0, 0, {}}, Cursor{&ts.u, 0, 0, {}}, Cursor{&ts.v, 0, 0, {}}},
           tr.colour ? 3 : 1, 0, file, name);
  const Xyz lamb = tr.split_lambertian();
  tr.slices(tr.ndim == 3 ? SliceDims{1, {0, 0}, {1, 2}} : SliceDims{2, {0, 1}, {2, 3}}, false, file,
            name);
  rec.lamb = float4_of(lamb);
  const double small = smallest_leaf(ts.y, 0), large = largest_leaf(ts.y, 0);
  rec.min_psa = static_cast<float>(kPi * small * small);
  rec.max_psa = static_cast<float>(kPi * large * large);
  rec.max_hemi = static_cast<float>(tree_max_hemi(tr, std::max(small, 1.0 / 32)));
  if (rec.max_hemi <= kDropHemi) return false;
  // TT4 transmission is sampled through reciprocity too (TT3 is not, as in Radiance).
  const bool reverse = tr.ndim == 4 && transmission(c.part);
  if (reverse) tr.slices({2, {2, 3}, {0, 1}}, true, file, name);

  // Pre-order: a branch, its tables, then its subtrees.
  const size_t nkid = size_t{1} << tr.ndim;
  check_room(vals, tr.table.size() + (tr.colour ? 3 : 1) * tr.nodes.size(), file, name);
  check_room(ints, tr.nodes.size() * 3 + tr.kids.size(), file, name);
  auto emit = [&](auto&& self, const Node& nd) -> int32_t {
    const auto at = static_cast<int32_t>(ints.size());
    if (nd.leaf()) {
      ints.push_back(static_cast<int32_t>(vals.size()));
      vals.push_back(static_cast<float>(nd.v.y));
      if (tr.colour) vals.insert(vals.end(), {float(nd.v.x), float(nd.v.z)});
      return at;
    }
    const size_t cells = tr.ndim == 3 ? size_t{1} << nd.height : size_t{1} << 2 * nd.height;
    ints.push_back(-nd.height);
    for (bool rev : {false, true}) {
      ints.push_back(rev && !reverse ? -1 : static_cast<int32_t>(vals.size()));
      if (rev && !reverse) continue;
      for (size_t k = 0; k < cells; ++k)
        vals.push_back(static_cast<float>(tr.mean(nd, k, rev)));
    }
    ints.resize(ints.size() + nkid);
    for (size_t k = 0; k < nkid; ++k) {
      const int32_t child = self(self, tr.nodes[tr.kid(nd, int(k))]);
      ints[at + 3 + k] = child;
    }
    return at;
  };
  rec.root = static_cast<std::uint32_t>(emit(emit, tr.nodes[0]));
  return true;
}

std::uint32_t BsdfTables::add(const bsdf::BsdfData& data) {
  rc_bsdf file{};
  const auto index = static_cast<std::uint32_t>(files.size());
  file.format = data.format == Format::Klems         ? RC_BSDF_KLEMS
                : data.format == Format::TensorTree3 ? RC_BSDF_TT3
                                                     : RC_BSDF_TT4;
  bool present[4] = {};
  for (int p = 0; p < 4; ++p) {
    file.comp[p] = RC_NONE;
    const Component* c = data.find(static_cast<Part>(p));
    if (!c) continue;
    present[p] = true;
    rc_bsdf_comp rec{};
    rec.format = c->format == Format::Klems         ? RC_BSDF_KLEMS
                 : c->format == Format::TensorTree3 ? RC_BSDF_TT3
                                                    : RC_BSDF_TT4;
    rec.part = static_cast<rc_u32>(p);
    rec.colour = c->colour() ? 1u : 0u;
    rec.file = index;
    rec.rcdf = RC_NONE;
    const bool kept =
        c->format == Format::Klems ? add_klems(*c, data.name, rec) : add_tree(*c, data.name, rec);
    file.lamb[p] = rec.lamb;
    if (!kept) continue;
    file.comp[p] = static_cast<std::uint32_t>(comps.size());
    comps.push_back(rec);
  }
  const int tf = static_cast<int>(Part::TransmitFront), tb = static_cast<int>(Part::TransmitBack);
  if (!present[tf] && present[tb]) file.lamb[tf] = file.lamb[tb];
  if (!present[tb] && present[tf]) file.lamb[tb] = file.lamb[tf];
  files.push_back(file);
  return index;
}

} // namespace radcl::render
