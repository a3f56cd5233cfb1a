#include "radcl/render/picture/picture_loop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <sys/resource.h>
#include <unistd.h>

#include "picture_fill.h"
#include "radcl/image/view_ray.h"
#include "radcl/rng.h"
#include "radcl/util/error.h"

namespace radcl::render {
namespace {

using detail::FillSample;

// Whether two samples disagree, for the edge samples of antialias(): any channel off by more
// than pt relative, or the depths.
bool differ(const FillSample& a, const FillSample& b, double pt) {
  for (int c = 0; c < 3; ++c) {
    double d = std::fabs(a.v[c] - b.v[c]);
    if (d > pt * a.v[c] || d > pt * b.v[c]) return true;
  }
  return 2 * std::fabs(a.z - b.z) > pt * (a.z + b.z);
}

class Bar {
public:
  Bar(Renderer& r, const options::View& view, const PictureSettings& st, PictureStats& stats)
      : r_(r), view_(view), st_(st), stats_(stats) {}

  // Rows [top, top + grid's rows) counted from the top, `base` the bar's base rows (in the
  // bar); with `fixed`, the first is the previous bar's last, already final. The walk of
  // rpict's decisions is repeated, each time tracing the pixels it found certain, until the
  // bar is complete.
  void render(int top, std::vector<FillSample>& grid, const std::vector<int>& base, bool fixed,
              detail::PictureFill& fill, detail::FillState& state) {
    top_ = top;
    n_ = static_cast<int>(grid.size() / st_.xres);
    grid_ = &grid;
    while (!fill.walk(grid, base, fixed, state, pending_)) {
      trace();
      ++stats_.waves;
    }
  }

  // Edge samples on the finished bar (-pj > 0).
  void finish(bool fixed) {
    if (st_.pj > 0) antialias(fixed ? 1 : 0);
  }

private:
  Renderer& r_;
  const options::View& view_;
  const PictureSettings& st_;
  PictureStats& stats_;
  int top_ = 0, n_ = 0;
  std::vector<FillSample>* grid_ = nullptr;
  std::vector<std::pair<int, int>> pending_;

  // -pd: the origin moves over a disc of diameter pd across the view point, the ray still
  // passing through the point it aimed at on the focal plane (-vd's length away).
  void aperture(image::ViewRay& r, rc_rng_key key) const {
    const options::View& v = view_;
    double cosd = r.dir[0] * v.direction[0] + r.dir[1] * v.direction[1] + r.dir[2] * v.direction[2];
    if (cosd <= 1e-6) return;
    double t = v.focal / cosd;
    image::Vec3 focus = {r.org[0] + t * r.dir[0], r.org[1] + t * r.dir[1], r.org[2] + t * r.dir[2]};
    // Unit vectors across the view from the direction and up vector.
    const image::Vec3& d = v.direction;
    image::Vec3 h = {d[1] * v.up[2] - d[2] * v.up[1], d[2] * v.up[0] - d[0] * v.up[2],
                     d[0] * v.up[1] - d[1] * v.up[0]};
    double hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    for (double& c : h)
      c /= hl;
    image::Vec3 u = {h[1] * d[2] - h[2] * d[1], h[2] * d[0] - h[0] * d[2],
                     h[0] * d[1] - h[1] * d[0]};
    double rad = 0.5 * st_.pd * std::sqrt(rc_random(key, 4));
    double phi = 2 * 3.14159265358979323846 * rc_random(key, 5);
    for (int k = 0; k < 3; ++k)
      r.org[k] += rad * (std::cos(phi) * h[k] + std::sin(phi) * u[k]);
    image::Vec3 nd = {focus[0] - r.org[0], focus[1] - r.org[1], focus[2] - r.org[2]};
    double l = std::sqrt(nd[0] * nd[0] + nd[1] * nd[1] + nd[2] * nd[2]);
    for (int k = 0; k < 3; ++k)
      r.dir[k] = nd[k] / l;
  }

  // -pm: rpict's blend of this sample's ray with the previous view's ray through the same
  // image point, by a fraction in [-pm/2, pm/2]. False when the blend leaves no direction.
  bool motion(image::ViewRay& r, double h, double v, rc_rng_key key) const {
    if (!st_.previous || st_.pm <= 1e-6) return true;
    std::optional<image::ViewRay> last = image::view_ray(*st_.previous, h, v);
    if (!last) return true;
    double d = st_.pm * (0.5 - rc_random(key, 6));
    r.maxlen = (1 - d) * r.maxlen + d * last->maxlen;
    double len = 0;
    for (int k = 0; k < 3; ++k) {
      r.org[k] = (1 - d) * r.org[k] + d * last->org[k];
      r.dir[k] = (1 - d) * r.dir[k] + d * last->dir[k];
      len += r.dir[k] * r.dir[k];
    }
    len = std::sqrt(len);
    if (len == 0) return false;
    for (double& c : r.dir)
      c /= len;
    return true;
  }

  // Pixel jitter, stratified over each 8 x 8 tile of pixels: the tile's 64 jitter offsets
  // form a multi-jittered set (one in each 1/8 x 1/8 cell of the pixel square, and one in
  // each 1/64 column and row), dealt to the pixels in an order scrambled per tile. Like
  // Radiance's low-discrepancy sampling (-u-), this keeps the coverage of an edge crossing a
  // tile near its true value instead of adding per-pixel noise.
  std::array<double, 2> jitter(int x, int row, rc_rng_key key) const {
    std::uint32_t tile = static_cast<std::uint32_t>(row / 8) * 0x9E3779B1u ^
                         static_cast<std::uint32_t>(x / 8) * 0x85EBCA77u;
    rc_u32x4 b = rc_random_bits(rc_make_key(tile, 0x7117u, 0, st_.seed), 0);
    std::uint32_t a = (b.v[0] & 63u) | 1u, c = b.v[1] & 63u, d = b.v[2] & 63u;
    std::uint32_t k = static_cast<std::uint32_t>((x % 8) + 8 * (row % 8));
    std::uint32_t cell = ((a * k + c) & 63u) ^ d; // a bijection of 0..63
    std::uint32_t cx = cell % 8, cy = cell / 8;
    return {(cx + (cy + rc_random(key, 2)) / 8.0) / 8.0,
            (cy + (cx + rc_random(key, 3)) / 8.0) / 8.0};
  }

  // Traced pixels on an edge (a 4-neighbour differs by more than -pt) get four more jittered
  // samples, one per quarter of the jitter square, averaged with the first. One sample per
  // pixel, as rpict takes, makes an edge's coverage a coin toss per pixel; this makes it the
  // pixel's actual coverage, at the cost of rays on edges only.
  void antialias(int fixed) {
    const int w = st_.xres;
    std::vector<std::pair<int, int>> edge;
    for (int y = fixed; y < n_; ++y)
      for (int x = 0; x < w; ++x) {
        const FillSample& s = at(x, y);
        if (!s.traced) continue;
        bool e = (x > 0 && differ(s, at(x - 1, y), st_.pt)) ||
                 (x + 1 < w && differ(s, at(x + 1, y), st_.pt)) ||
                 (y > 0 && differ(s, at(x, y - 1), st_.pt)) ||
                 (y + 1 < n_ && differ(s, at(x, y + 1), st_.pt));
        if (e) edge.emplace_back(x, y);
      }
    if (edge.empty()) return;
    const std::uint32_t npix = static_cast<std::uint32_t>(st_.xres) * st_.yres;
    std::vector<PrimaryRay> rays;
    std::vector<std::size_t> which;
    for (auto [x, y] : edge) {
      int row = top_ + y, j = st_.yres - 1 - row;
      std::uint32_t pix = static_cast<std::uint32_t>(row) * st_.xres + x;
      for (std::uint32_t q = 0; q < 4; ++q) {
        std::uint32_t id = pix + (q + 1) * npix;
        rc_rng_key key = rc_make_key(id, 0, 0, st_.seed ^ 0x70696374u);
        double ux = ((q & 1) + rc_random(key, 2)) / 2, uy = ((q >> 1) + rc_random(key, 3)) / 2;
        double h = (x + 0.5 + st_.pj * (0.5 - ux)) / st_.xres;
        double v = (j + 0.5 + st_.pj * (0.5 - uy)) / st_.yres;
        std::optional<image::ViewRay> vr = image::view_ray(view_, h, v);
        if (!vr || !motion(*vr, h, v, key)) continue;
        if (st_.pd > 0) aperture(*vr, key);
        rays.push_back({vr->org, vr->dir, vr->maxlen, id});
        which.push_back(static_cast<std::size_t>(y) * st_.xres + x);
      }
    }
    std::vector<PrimaryResult> res(rays.size());
    r_.render(rays, res);
    stats_.primary_rays += rays.size();
    std::vector<int> count(grid_->size(), 1);
    std::vector<std::array<double, 3>> sum(grid_->size());
    for (auto [x, y] : edge) {
      std::size_t i = static_cast<std::size_t>(y) * st_.xres + x;
      for (int c = 0; c < 3; ++c)
        sum[i][c] = (*grid_)[i].v[c];
    }
    for (std::size_t k = 0; k < rays.size(); ++k) {
      for (int c = 0; c < 3; ++c)
        sum[which[k]][c] += res[k].value[c];
      ++count[which[k]];
    }
    for (auto [x, y] : edge) {
      std::size_t i = static_cast<std::size_t>(y) * st_.xres + x;
      for (int c = 0; c < 3; ++c)
        (*grid_)[i].v[c] = static_cast<float>(sum[i][c] / count[i]);
    }
  }

  FillSample& at(int x, int y) { return (*grid_)[static_cast<std::size_t>(y) * st_.xres + x]; }

  void trace() {
    std::sort(pending_.begin(), pending_.end());
    pending_.erase(std::unique(pending_.begin(), pending_.end()), pending_.end());
    std::vector<PrimaryRay> rays;
    std::vector<std::size_t> which;
    for (auto [x, y] : pending_) {
      int row = top_ + y;         // from the top
      int j = st_.yres - 1 - row; // from the bottom, as view positions count
      std::uint32_t id = static_cast<std::uint32_t>(row) * st_.xres + x;
      rc_rng_key key = rc_make_key(id, 0, 0, st_.seed ^ 0x70696374u);
      std::array<double, 2> u = jitter(x, row, key);
      double h = (x + 0.5 + st_.pj * (0.5 - u[0])) / st_.xres;
      double v = (j + 0.5 + st_.pj * (0.5 - u[1])) / st_.yres;
      std::optional<image::ViewRay> vr = image::view_ray(view_, h, v);
      FillSample& s = at(x, y);
      s.known = true;
      s.traced = true;
      if (!vr || !motion(*vr, h, v, key)) { // outside a fisheye: black at distance 0
        s.v = {0, 0, 0};
        s.z = 0;
        continue;
      }
      if (st_.pd > 0) aperture(*vr, key);
      rays.push_back({vr->org, vr->dir, vr->maxlen, id}); // the pixel keys its numbers
      which.push_back(static_cast<std::size_t>(y) * st_.xres + x);
    }
    stats_.traced_pixels += pending_.size();
    pending_.clear();
    if (rays.empty()) return;
    std::vector<PrimaryResult> res(rays.size());
    r_.render(rays, res);
    stats_.primary_rays += rays.size();
    for (std::size_t i = 0; i < rays.size(); ++i) {
      FillSample& s = (*grid_)[which[i]];
      for (int c = 0; c < 3; ++c)
        s.v[c] = static_cast<float>(res[i].value[c]);
      s.z = static_cast<float>(res[i].t);
    }
  }
};

// Memory of a bar of rows: its samples and the renderer's waves for them, about 2 KB a sample
// (measured: 1.2-1.9 KB at -ps 4 and 1 on a picture 200,000 pixels wide, 2026-12-06).
constexpr double kBytesPerSample = 2048;

// The memory this process may use: the machine's, or less under a limit (ulimit -v).
double usable_memory() {
  double m =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  struct rlimit rl {};
  if (::getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
    m = std::min(m, static_cast<double>(rl.rlim_cur));
  return m;
}

// A picture whose rows cannot fit is refused before anything is written, with what it needs.
void check_rows_fit(int xres, int step) {
  const double need = static_cast<double>(xres) * (step + 1) * kBytesPerSample;
  const double have = usable_memory();
  if (have > 0 && need > have) {
    char msg[256];
    std::snprintf(msg, sizeof msg,
                  "a picture %d pixels wide needs about %.1f GB of memory for its rows at -ps %d "
                  "(%.1f GB usable here)",
                  xres, need / 1e9, step, have / 1e9);
    throw FatalError(msg);
  }
}

} // namespace

PictureStats render_picture(Renderer& renderer, const options::View& view,
                            const PictureSettings& st,
                            const std::function<void(const PictureRows&)>& emit) {
  PictureStats stats;
  check_rows_fit(st.xres, std::clamp(st.ps, 1, 16));
  if (st.xres <= 0 || st.first_row >= st.yres) return stats;
  // rpict's base lines: every ystep rows from the first row to compute, the last one at the
  // bottom row (the last interval shorter).
  const int ystep = detail::fill_ystep(st.ps);
  std::vector<int> lines;
  for (int y = st.first_row; y < st.yres - 1 + ystep; y += ystep)
    lines.push_back(std::min(y, st.yres - 1));
  // Bars of whole intervals between base lines, tall enough to make good waves; each shares
  // its first base line with the previous bar's last.
  const std::size_t per_bar =
      static_cast<std::size_t>(std::max(1, (1 << 17) / std::max(1, st.xres) / ystep));
  detail::PictureFill fill(st.xres, st.ps, st.pt, st.compare_depth);
  detail::FillState state = fill.start();
  Bar worker(renderer, view, st, stats);
  std::vector<FillSample> carry; // the last base line as the fill left it (before antialias)
  for (std::size_t first = 0; first < lines.size();) {
    const bool fixed = !carry.empty();
    const std::size_t last = std::min(lines.size() - 1, first + (fixed ? per_bar : per_bar - 1));
    const int top = lines[first];
    const int n = lines[last] - top + 1;
    std::vector<int> base;
    for (std::size_t k = first; k <= last; ++k)
      base.push_back(lines[k] - top);
    std::vector<FillSample> grid(static_cast<std::size_t>(n) * st.xres);
    if (fixed) std::copy(carry.begin(), carry.end(), grid.begin());
    worker.render(top, grid, base, fixed, fill, state);
    carry.assign(grid.end() - st.xres, grid.end());
    worker.finish(fixed);
    PictureRows out;
    const int skip = fixed ? 1 : 0;
    out.first = top + skip;
    out.count = n - skip;
    out.pixels.resize(static_cast<std::size_t>(out.count) * st.xres);
    out.depth.resize(out.pixels.size());
    out.traced.resize(out.pixels.size());
    for (int y = skip; y < n; ++y)
      for (int x = 0; x < st.xres; ++x) {
        const FillSample& s = grid[static_cast<std::size_t>(y) * st.xres + x];
        std::size_t o = static_cast<std::size_t>(y - skip) * st.xres + x;
        out.pixels[o] = s.v;
        out.depth[o] = s.z;
        out.traced[o] = s.traced ? 1 : 0;
      }
    stats.pixels += out.pixels.size();
    if (out.count > 0) emit(out);
    first = last;
    if (last == lines.size() - 1) break;
  }
  return stats;
}

} // namespace radcl::render
