// rtrace's ray input as users feed it: the first byte picks the format ('a', 'f' or 'd' for
// -fa, -ff, -fd; any other byte by its value mod 3), the rest is standard input. Every ray is read
// as rtrace reads it (short records, NaN and Inf included) and its direction normalised; a zero
// direction is a flush request.
#include <cmath>
#include <sstream>

#include "fuzz_target.h"
#include "radcl/options/ray_io.h"

RADCL_FUZZ_TARGET(ray_input) {
  using namespace radcl::options;
  if (data.empty()) return;
  char format = data[0];
  if (format != 'a' && format != 'f' && format != 'd')
    format = "afd"[static_cast<unsigned char>(format) % 3];
  std::istringstream in(std::string(data.substr(1)));
  RayReader reader(in, format);
  Vec3 org, dir;
  for (int n = 0; n < 100000 && reader.read(org, dir); ++n) {
    const double len = normalize_direction(dir);
    if (len == 0) continue; // flush
    (void)RayOutput::empty(org, dir);
  }
}
