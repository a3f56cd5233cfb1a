// How far radcl's ray queries are from the machine's limit: the same rays through radcl's
// query (SceneGeometry::intersect: double setup, exact filters, the hit rebuilt in double) and
// through Embree's float traversal alone (SceneGeometry::intersect_raw), on every host core,
// both in Embree packets of the same width (and raw Embree one ray at a time besides).
//
// The rays are those of an -aa 0 irradiance run (peers.sh P2): from each sensor, a stratified
// cosine-weighted hemisphere of n x n directions (the first bounce), then from each point
// they hit one cosine-weighted direction about the surface's normal facing the ray (the
// second bounce, incoherent), leaving the surface as the kernels' rays do.
//
// usage: bench_embree_rays OCTREE SENSORS [n (default 32)] [repeats (default 3)]
// Prints, per ray set, the best of the repeats: rays/s of each query and their ratio.
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "radcl/geometry/scene_geometry.h"
#include "radcl/scene/loader.h"
#include "radcl/util/error.h"

using radcl::geometry::Hit;
using radcl::geometry::Ray;
using radcl::geometry::Vec3d;

namespace {

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3d unit(const Vec3d& v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}

// A cosine-weighted direction about n from (u, v) in the unit square.
Vec3d cosine_dir(const Vec3d& n, double u, double v) {
  const Vec3d ux = unit(std::fabs(n[0]) < 0.6 ? cross(n, {1, 0, 0}) : cross(n, {0, 1, 0}));
  const Vec3d uy = cross(n, ux);
  const double r = std::sqrt(u), phi = 2 * 3.14159265358979323846 * v;
  const double x = r * std::cos(phi), y = r * std::sin(phi), z = std::sqrt(std::max(0.0, 1 - u));
  return unit({x * ux[0] + y * uy[0] + z * n[0], x * ux[1] + y * uy[1] + z * n[1],
               x * ux[2] + y * uy[2] + z * n[2]});
}

template <class F> double best_seconds(int repeats, const F& f) {
  double best = 1e300;
  for (int k = 0; k < repeats; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

void measure(const char* name, const radcl::geometry::SceneGeometry& g,
             const std::vector<Ray>& rays, int repeats) {
  std::vector<std::optional<Hit>> hits(rays.size());
  std::vector<float> t(rays.size());
  const double radcl_s = best_seconds(repeats, [&] { g.intersect(rays, hits); });
  const double raw_s = best_seconds(repeats, [&] { g.intersect_raw(rays, t); });
  const double raw1_s = best_seconds(repeats, [&] { g.intersect_raw(rays, t, 1); });
  const double n = static_cast<double>(rays.size());
  std::printf("%-14s %10zu rays  radcl %6.2f Mrays/s  raw Embree %6.2f Mrays/s  radcl/raw %.2f"
              "  (raw single rays %6.2f Mrays/s)\n",
              name, rays.size(), n / radcl_s / 1e6, n / raw_s / 1e6, raw_s / radcl_s,
              n / raw1_s / 1e6);
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s OCTREE SENSORS [n] [repeats]\n", argv[0]);
    return 1;
  }
  try {
    const int ns = argc > 3 ? std::atoi(argv[3]) : 32;
    const int repeats = argc > 4 ? std::atoi(argv[4]) : 3;
    radcl::scene::LoadedScene scene = radcl::scene::load_scene({argv[1]});
    radcl::geometry::SceneGeometry g(scene);
    std::ifstream in(argv[2]);
    if (!in) throw radcl::FatalError(std::string("cannot open sensor file \"") + argv[2] + "\"");
    std::vector<Ray> first;
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double x, y, z, dx, dy, dz;
    while (in >> x >> y >> z >> dx >> dy >> dz) {
      const Vec3d n = unit({dx, dy, dz});
      for (int i = 0; i < ns; ++i)
        for (int j = 0; j < ns; ++j) {
          Ray r;
          r.org = {x, y, z};
          r.dir = cosine_dir(n, (i + u01(rng)) / ns, (j + u01(rng)) / ns);
          r.tmin = 1e-5;
          r.free_origin = true;
          first.push_back(r);
        }
    }
    std::vector<std::optional<Hit>> hits(first.size());
    g.intersect(first, hits);
    // The second bounce leaves its surface as the kernels' rays do (rc_leave): from beside it on
    // the side it goes to, by max(epsilon, 8e-7 x the point's largest centred coordinate),
    // with no minimum distance (a negative tmin, RC_TMIN_OFF).
    const Vec3d c = g.centre();
    std::vector<Ray> second;
    for (std::size_t i = 0; i < first.size(); ++i) {
      if (!hits[i]) continue;
      Vec3d n = hits[i]->normal;
      if (!hits[i]->front) n = {-n[0], -n[1], -n[2]};
      const Vec3d& p = hits[i]->point;
      const double off =
          std::max(g.epsilon(), 8e-7 * std::max({std::fabs(p[0] - c[0]), std::fabs(p[1] - c[1]),
                                                 std::fabs(p[2] - c[2])}));
      Ray r;
      r.org = {p[0] + off * n[0], p[1] + off * n[1], p[2] + off * n[2]};
      r.dir = cosine_dir(n, u01(rng), u01(rng));
      r.tmin = -1;
      second.push_back(r);
    }
    std::printf("%s: %d host threads, rays in packets of %d (RADCL_RAY_PACKET)\n", argv[1],
                tbb::info::default_concurrency(), g.packet_width());
    measure("first bounce", g, first, repeats);
    measure("second bounce", g, second, repeats);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_embree_rays: %s\n", e.what());
    return 1;
  }
}
