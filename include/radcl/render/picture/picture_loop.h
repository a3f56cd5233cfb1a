// rpict's picture loop on the wavefront renderer: rays through a view, rpict's adaptive
// sampling -ps/-pt (its base grid, its fill rule and its budgets: the same pixels are traced
// for the same values; src/render/picture/picture_fill.h), pixel jitter -pj, produced in bars of
// scanlines from the top so the picture can be written and reported as it grows.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "radcl/options/view.h"
#include "radcl/render/pipeline/renderer.h"

namespace radcl::render {

struct PictureSettings {
  int xres = 512, yres = 512; // final resolution (after normalize_aspect)
  int ps = 4;                 // -ps sample spacing, clamped to 1..16
  double pt = 0.05;           // -pt relative difference that forces a sample
  bool compare_depth = false; // depths that differ by -pt force a sample too (rpict with -z)
  double pj = 0.67;           // -pj pixel jitter
  double pd = 0;              // -pd aperture diameter (depth of field, focus at -vd's length)
  // -pm motion blur: with the previous frame's view, each sample's ray is blended towards the
  // ray through the same image point of that view by pm * (0.5 - random), as rpict does.
  double pm = 0;
  const options::View* previous = nullptr; // set up (setup_view); none outside sequences
  std::uint32_t seed = 0;
  int first_row = 0; // rows (from the top) already done, for -r recovery
};

struct PictureRows {
  int first = 0; // first row (0 = top) of this bar
  int count = 0;
  std::vector<std::array<float, 3>> pixels; // count x xres, top row first
  std::vector<float> depth;                 // distance to the first hit per pixel
  std::vector<std::uint8_t> traced;         // 1 where the fill traced the pixel, 0 interpolated
};

struct PictureStats {
  std::uint64_t primary_rays = 0;  // primary rays, the edge samples of -pj's antialiasing too
  std::uint64_t traced_pixels = 0; // pixels traced by the fill (the rest were interpolated)
  std::uint64_t pixels = 0;
  std::uint64_t waves = 0; // render() calls of the fill
};

// Calls `emit` for each finished bar, top to bottom. Returns what was traced.
PictureStats render_picture(Renderer& renderer, const options::View& view,
                            const PictureSettings& settings,
                            const std::function<void(const PictureRows&)>& emit);

} // namespace radcl::render
