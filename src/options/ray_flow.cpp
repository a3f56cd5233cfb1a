// rtrace's -x/-y rules: how many rays make a run and when output is flushed.
#include "radcl/options/ray_io.h"

namespace radcl::options {

RayFlow::RayFlow(int xres, int yres)
    : xres_(xres), interval_((yres == 0 || xres <= 1) ? xres : 0), next_flush_(interval_),
      remaining_(xres > 1 ? static_cast<unsigned long>(xres) * static_cast<unsigned long>(yres)
                          : static_cast<unsigned long>(yres)) {}

bool RayFlow::flush_request() {
  if (!pending_) return false;
  next_flush_ = interval_;
  pending_ = false;
  return true;
}

bool RayFlow::ray_done() {
  if (--next_flush_ == 0) {
    next_flush_ = xres_;
    return true;
  }
  pending_ = true;
  return false;
}

bool RayFlow::record_done() {
  return remaining_ != 0 && --remaining_ == 0;
}

} // namespace radcl::options
