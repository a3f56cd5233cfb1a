// rtrace's ray input as users feed it: the first byte picks the format ('a', 'f' or 'd' for
// -fa, -ff, -fd; any other byte by its value mod 3), the next two are -x and -y (signed bytes,
// as a user may type -x -3), the rest is standard input. Every ray is read as rtrace reads it
// (short records, NaN and Inf included) and its direction normalised; a zero direction is a flush
// request. The -x/-y count and flush rules (options::RayFlow) run as rtrace runs them and are
// checked: reading stops after exactly x*y records (y when x <= 1; a negative -y counts as
// Radiance's unsigned count does), and a flush interval is never exceeded.
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "fuzz_target.h"
#include "radcl/options/ray_io.h"

RADCL_FUZZ_TARGET(ray_input) {
  using namespace radcl::options;
  if (data.size() < 3) return;
  char format = data[0];
  if (format != 'a' && format != 'f' && format != 'd')
    format = "afd"[static_cast<unsigned char>(format) % 3];
  const int xres = static_cast<signed char>(data[1]);
  const int yres = static_cast<signed char>(data[2]);
  std::istringstream in(std::string(data.substr(3)));
  RayReader reader(in, format);
  RayFlow flow(xres, yres);
  const unsigned long count =
      xres > 1 ? static_cast<unsigned long>(xres) * static_cast<unsigned long>(yres)
               : static_cast<unsigned long>(yres);
  Vec3 org, dir;
  unsigned long records = 0;
  long since_flush = 0;
  bool stopped = false;
  for (; records < 100000 && reader.read(org, dir);) {
    ++records;
    bool bad = false;
    for (int k = 0; k < 3; ++k)
      bad |= !std::isfinite(org[k]) || !std::isfinite(dir[k]);
    const double len = bad ? 0.0 : normalize_direction(dir);
    bad |= !std::isfinite(len);
    if (bad || len > 0) { // a ray (a bad one is answered with zeros) counts toward the interval
      if (!bad) (void)RayOutput::empty(org, dir);
      if (flow.ray_done())
        since_flush = 0;
      else
        ++since_flush;
    } else if (flow.flush_request()) {
      since_flush = 0;
    }
    // A positive flush interval is never exceeded between flushes.
    if (flow.flush_interval() > 0 && since_flush >= flow.flush_interval()) std::abort();
    if (flow.record_done()) {
      stopped = true;
      break;
    }
  }
  if (stopped && records != count) std::abort();               // stopped early or late
  if (!stopped && count > 0 && records >= count) std::abort(); // ran past the count
  if (!stopped && flow.incomplete() != (count > 0)) std::abort();
}
