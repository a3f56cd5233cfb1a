// bench_picture_mean PICTURE: the mean luminance (0.265 R + 0.670 G + 0.065 B) of a Radiance
// picture, for tests/bench/peers.sh to compare two renderers' pictures without Radiance's
// pvalue.
#include <cstdio>

#include "radcl/image/picture.h"
#include "radcl/util/error.h"

namespace {
int body(int argc, char** argv) {
  if (argc != 2) throw radcl::FatalError("usage: bench_picture_mean picture.hdr");
  const radcl::image::Picture p = radcl::image::read_picture(argv[1]);
  double sum = 0;
  for (const auto& c : p.colors())
    sum += 0.265 * c[0] + 0.670 * c[1] + 0.065 * c[2];
  std::printf("%.6g\n", p.pixels.empty() ? 0.0 : sum / static_cast<double>(p.pixels.size()));
  return 0;
}
} // namespace

int main(int argc, char** argv) {
  return radcl::run_main("bench_picture_mean", body, argc, argv);
}
