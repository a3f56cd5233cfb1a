#include "picture_fill.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace radcl::render::detail {

namespace {
int clamp_ps(int ps) {
  return std::clamp(ps, 1, 16);
}
} // namespace

// The quincunx steps: across about ps sqrt 2, down about ps / sqrt 2 (rpict's rounding).
int fill_hstep(int ps) {
  return (clamp_ps(ps) * 140 + 49) / 99;
}
int fill_ystep(int ps) {
  return (clamp_ps(ps) * 99 + 70) / 140;
}

PictureFill::PictureFill(int xres, int ps, double pt, bool compare_depth)
    : xres_(xres), hstep_(fill_hstep(ps)), pt_(pt), depth_(compare_depth) {}

FillState PictureFill::start() const {
  FillState s;
  // Every place starts with the full budget, hstep; there is room for the most spans a line
  // has and the count an odd line keeps after its last.
  if (hstep_ > 2) s.spans.assign(static_cast<std::size_t>(xres_ / hstep_ + 4), hstep_);
  return s;
}

void PictureFill::request(const Line& l, int t) {
  if (!at(l, t).traced) want_->emplace_back(l.x0 + t * l.dx, l.y0 + t * l.dy);
}

// rpict's comparison, in its precision: the colours (float) differ in some channel by more
// than -pt times the smaller; with -z, the depths by more than -pt times their mean.
bool PictureFill::differ(const FillSample& a, const FillSample& b) const {
  if (depth_) {
    float d = a.z - b.z, s = a.z + b.z;
    if (2.0 * std::fabs(static_cast<double>(d)) > pt_ * s) return true;
  }
  for (int c = 0; c < 3; ++c) {
    float d = a.v[c] - b.v[c];
    if (d > pt_ * b.v[c] || -d > pt_ * a.v[c]) return true;
  }
  return false;
}

// The span [off, off + len] of a line, its ends known or pending, with budget b: its midpoint
// is traced, interpolated or (not yet decidable) left open, then both halves alike. Returns
// the bounds of the number of pixels the span traces.
PictureFill::Cut PictureFill::fill(const Line& l, int off, int len, Cut b) {
  if (len <= 1) return {0, 0};
  const int h = len >> 1;
  const FillSample& a = at(l, off);
  const FillSample& c = at(l, off + len);
  int d; // 1: traced, 0: interpolated, -1: open
  if (b.lo > 0)
    d = 1; // the budget forces it
  else if (!a.known || !c.known)
    d = -1;
  else if (differ(a, c))
    d = 1;
  else
    d = b.hi > 0 ? -1 : 0; // no difference: the budget alone decides
  Cut n{0, 0};
  if (d == 1) {
    request(l, off + h);
    n = {1, 1};
  } else if (d == 0) {
    FillSample& m = at(l, off + h);
    if (!m.traced) {
      // As rpict blends, in its float precision: far end times h/len plus near end times the
      // rest.
      const double r = static_cast<double>(h) / len, q = 1.0 - r;
      for (int k = 0; k < 3; ++k)
        m.v[k] = static_cast<float>(c.v[k] * r) + static_cast<float>(a.v[k] * q);
      m.z = static_cast<float>(c.z * r) + static_cast<float>(a.z * q);
      m.known = true;
    }
  } else {
    open_ = true;
    n = {0, 1};
  }
  Cut nl = fill(l, off, h, {(b.lo - 1) / 2, (b.hi - 1) / 2});
  Cut nr = fill(l, off + h, len - h, {b.lo / 2, b.hi / 2});
  return {n.lo + nl.lo + nr.lo, n.hi + nl.hi + nr.hi};
}

// A base scanline: its first pixel and every hstep-th after it (odd lines from hstep, even
// lines from hstep / 2, the last span cut to end at the last pixel), the spans between filled.
// A span's budget is half the larger of the two counts kept at its place from the line
// before; this line then keeps its own counts (odd lines one place to the right). Without
// kept counts (hstep <= 2) a span's budget is the count of the span before.
void PictureFill::scanline(int row) {
  const bool odd = (++lines_ & 1) != 0;
  const bool keep = !cuts_.empty();
  int xstep = hstep_;
  Cut before{xstep, xstep}, b{xstep, xstep};
  const Line l{0, row, 1, 0};
  request(l, 0);
  std::size_t k = 0;
  for (int i = odd ? xstep : xstep / 2; i < xres_ - 1 + xstep; i += xstep) {
    if (i >= xres_) {
      xstep += xres_ - 1 - i;
      i = xres_ - 1;
    }
    request(l, i);
    if (keep) {
      if (k + 1 >= cuts_.size()) throw std::logic_error("picture fill: span counts overrun");
      b = {std::max(cuts_[k].lo, cuts_[k + 1].lo), std::max(cuts_[k].hi, cuts_[k + 1].hi)};
    }
    const Cut half{b.lo / 2, b.hi / 2};
    Cut n = i <= xstep ? fill(l, 0, i, half) : fill(l, i - xstep, xstep, half);
    if (keep) cuts_[k++] = odd ? before : n;
    before = b = n;
  }
  if (keep && odd) cuts_[k] = before;
}

// The rows between two base lines, column by column from the left, each counted upwards from
// the lower line; a column's budget is half the count of the column before.
void PictureFill::scanbar(int upper, int lower) {
  const int ysize = lower - upper;
  Cut b{ysize, ysize};
  for (int x = 0; x < xres_; ++x)
    b = fill(Line{x, lower, 0, -1}, 0, ysize, {b.lo / 2, b.hi / 2});
}

bool PictureFill::walk(std::vector<FillSample>& grid, const std::vector<int>& base, bool fixed,
                       FillState& state, std::vector<std::pair<int, int>>& want) {
  grid_ = &grid;
  want_ = &want;
  open_ = false;
  const std::size_t asked = want.size();
  // Interpolated values are worked out again from the traced ones (the fixed row is final).
  for (std::size_t i = fixed ? xres_ : 0; i < grid.size(); ++i)
    grid[i].known = grid[i].traced;
  lines_ = state.lines;
  cuts_.clear();
  for (int v : state.spans)
    cuts_.push_back({v, v});
  for (std::size_t k = 0; k < base.size(); ++k) {
    if (k > 0 || !fixed) scanline(base[k]);
    if (k > 0) scanbar(base[k - 1], base[k]);
  }
  grid_ = nullptr;
  want_ = nullptr;
  if (want.size() > asked) return false;
  // The first decision left open waits on a pixel it asked for, so an open walk asks.
  if (open_) throw std::logic_error("picture fill: a decision is open with nothing to trace");
  state.lines = lines_;
  for (std::size_t j = 0; j < cuts_.size(); ++j)
    state.spans[j] = cuts_[j].lo;
  return true;
}

} // namespace radcl::render::detail
