// Rays through a view (Radiance's viewray(), ../shared/docs/radiance/cli-rtrace-rpict.md §5.2),
// shared by rpict and anything that needs vwrays-style camera rays.
#pragma once

#include <array>
#include <optional>

#include "radcl/options/view.h"

namespace radcl::image {

using Vec3 = std::array<double, 3>;

struct ViewRay {
  Vec3 org{};
  Vec3 dir{};        // unit
  double maxlen = 0; // 0: unlimited (-va clipping otherwise)
};

// The ray for image position (x, y) in [0,1]^2, origin lower left, of a view prepared by
// options::setup_view(). Empty for positions outside a fisheye's circle.
std::optional<ViewRay> view_ray(const options::View& v, double x, double y);

// rpict's normaspect(): adjusts the resolution to the view's aspect and the pixel aspect
// `pa` (0 = keep x and y, and compute pa). Returns the resulting pixel aspect.
double normalize_aspect(double view_aspect, int& xres, int& yres, double pa);

// sqrt(vn2 / hn2): the view's height over width.
double view_aspect(const options::View& v);

} // namespace radcl::image
