// rpict's adaptive sampling rule (-ps/-pt) replayed on pixel values that arrive in waves.
//
// rpict samples base scanlines ystep apart from the top, each every hstep pixels (quincunx:
// alternate lines start half a step in), and fills between samples by bisection: a midpoint is
// traced when the two ends differ by more than -pt (or their depths, with -z), or when the
// budget says so. The budget is what forces rpict to keep sampling densely where it just had
// to: along a scanline, the span's budget is the larger count of pixels traced in the
// neighbouring spans of the line above; down the rows between two base lines, a column's
// budget is what the column to its left traced. Each decision is sequential in rpict, but a
// pixel's value does not depend on when it is traced (its random numbers are its own), so the
// decisions can be walked with the values known so far: every decision that is already
// determined is taken, the pixels certainly traced are gathered as one wave, and the walk is
// repeated until nothing is pending. The set of traced pixels is then exactly rpict's.
#pragma once

#include <array>
#include <utility>
#include <vector>

namespace radcl::render::detail {

struct FillSample {
  std::array<float, 3> v{0, 0, 0};
  float z = 0;
  bool traced = false; // value from a ray: final
  bool known = false;  // value known in this walk (traced, or interpolated from known ends)
};

// rpict's sampling steps for -ps (clamped to 1..16): across and down.
int fill_hstep(int ps);
int fill_ystep(int ps);

// What carries from one bar of rows to the next: the scanline counter (its parity staggers
// the lines) and the per-span counts of the last base line.
struct FillState {
  int lines = 0;
  std::vector<int> spans; // empty where rpict keeps none (hstep <= 2)
};

class PictureFill {
public:
  PictureFill(int xres, int ps, double pt, bool compare_depth);
  FillState start() const;

  // One walk over a bar: `grid` holds rows x xres samples, `base` its base rows (indices in
  // the bar, ascending); with `fixed`, base[0] is already final (the previous bar's last base
  // line). Appends (x, row) of the pixels that must be traced and are not yet to `want`.
  // True when the bar is complete (every pixel known); `state` is advanced only then.
  bool walk(std::vector<FillSample>& grid, const std::vector<int>& base, bool fixed,
            FillState& state, std::vector<std::pair<int, int>>& want);

private:
  struct Cut {
    int lo, hi; // bounds of a count (or budget) not yet known exactly
  };
  struct Line {
    int x0, y0, dx, dy; // position t is (x0 + t dx, y0 + t dy)
  };
  FillSample& at(const Line& l, int t) const {
    return (*grid_)[static_cast<std::size_t>(l.y0 + t * l.dy) * xres_ + (l.x0 + t * l.dx)];
  }
  void request(const Line& l, int t);
  bool differ(const FillSample& a, const FillSample& b) const;
  Cut fill(const Line& l, int off, int len, Cut b);
  void scanline(int row);
  void scanbar(int upper, int lower);

  int xres_, hstep_;
  double pt_;
  bool depth_;
  std::vector<FillSample>* grid_ = nullptr;
  std::vector<std::pair<int, int>>* want_ = nullptr;
  bool open_ = false; // some decision could not be taken in this walk
  int lines_ = 0;     // the walk's copy of the state
  std::vector<Cut> cuts_;
};

} // namespace radcl::render::detail
