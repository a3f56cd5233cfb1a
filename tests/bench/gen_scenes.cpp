// Scene generator for load benchmarks (tests/bench/scene_load.sh):
//   gen_scenes mesh N out.rtm      a terrain of about N triangles, with normals, uv and two
//                                  materials, written as a Radiance mesh, plus out.rad that
//                                  places it ("void mesh terrain 1 out.rtm 0 0")
//   gen_scenes polygons N out.rad  N quadrilaterals over four materials, as Radiance text
// Output is deterministic, so timings of different builds load the same files.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "radcl/scene/mesh_writer.h"
#include "radcl/util/error.h"

namespace {

using radcl::scene::Object;
using radcl::scene::TriangleMesh;

double height(double x, double y) {
  return 0.8 * std::sin(1.3 * x) * std::cos(0.9 * y) + 0.25 * std::sin(4.1 * x + 2.7 * y) +
         0.05 * std::cos(13.0 * x - 11.0 * y);
}

// A square terrain of n x n cells, two triangles each, normals from the height gradient.
TriangleMesh terrain(long n) {
  TriangleMesh m;
  const double extent = 20.0, h = 1e-5;
  const auto side = static_cast<std::size_t>(n + 1);
  m.positions.reserve(side * side);
  for (long j = 0; j <= n; ++j)
    for (long i = 0; i <= n; ++i) {
      const double u = double(i) / n, v = double(j) / n;
      const double x = (u - 0.5) * extent, y = (v - 0.5) * extent;
      const double gx = (height(x + h, y) - height(x - h, y)) / (2 * h);
      const double gy = (height(x, y + h) - height(x, y - h)) / (2 * h);
      const double len = std::sqrt(gx * gx + gy * gy + 1);
      m.positions.push_back({x, y, height(x, y)});
      m.normals.push_back({float(-gx / len), float(-gy / len), float(1 / len)});
      m.uvs.push_back({float(u), float(v)});
    }
  m.vertex_flags.assign(m.positions.size(), TriangleMesh::kHasNormal | TriangleMesh::kHasUV);
  auto id = [side](long i, long j) { return static_cast<std::uint32_t>(j * side + i); };
  for (long j = 0; j < n; ++j)
    for (long i = 0; i < n; ++i) {
      const std::int32_t mat = m.positions[id(i, j)][2] > 0.3 ? 1 : 0; // rock above grass
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      m.triangle_material.insert(m.triangle_material.end(), 2, mat);
    }
  for (const char* name : {"grass", "rock"}) {
    Object o;
    o.type = RC_OBJ_PLASTIC;
    o.name = name;
    o.fargs = name[0] == 'g' ? std::vector<double>{0.1, 0.3, 0.05, 0, 0}
                             : std::vector<double>{0.35, 0.3, 0.25, 0.02, 0.1};
    m.objects.objects.push_back(o);
    m.materials.push_back(name);
  }
  return m;
}

int gen_mesh(long n_tris, const std::string& out, const std::string& command) {
  const long n = std::max(1L, std::lround(std::sqrt(n_tris / 2.0)));
  radcl::scene::MeshWriteOptions opt;
  opt.header_lines = {command};
  const auto info = radcl::scene::write_mesh(terrain(n), out, opt);
  std::string rad = out;
  const auto dot = rad.rfind('.');
  rad = (dot == std::string::npos ? rad : rad.substr(0, dot)) + ".rad";
  std::ofstream(rad) << "# " << command << "\nvoid mesh terrain\n1 " << out << "\n0\n0\n";
  std::printf("%s: %zu triangles, %zu vertices, %zu patches, %zu octree leaves; %s\n", out.c_str(),
              info.source_triangle.size(), info.vertices, info.patches, info.octree_leaves,
              rad.c_str());
  return 0;
}

// Tiles of varying size and tilt scattered over a 100 m field, in four materials.
int gen_polygons(long n, const std::string& out, const std::string& command) {
  std::FILE* f = std::fopen(out.c_str(), "w");
  if (!f) throw radcl::FatalError("cannot open \"" + out + "\"");
  std::fprintf(f, "# %s\n", command.c_str());
  std::fprintf(f, "void plastic white\n0\n0\n5 .7 .7 .7 0 0\n"
                  "void plastic red\n0\n0\n5 .6 .1 .1 .02 .05\n"
                  "void metal steel\n0\n0\n5 .5 .5 .55 .9 .1\n"
                  "void trans frosted\n0\n0\n7 .8 .8 .8 0 0 .5 .2\n");
  const char* mats[] = {"white", "red", "steel", "frosted"};
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  auto rnd = [&state] { // splitmix64 in [0, 1)
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return double((z ^ (z >> 31)) >> 11) / 9007199254740992.0;
  };
  for (long i = 0; i < n; ++i) {
    const double cx = rnd() * 100, cy = rnd() * 100, cz = rnd() * 10;
    const double s = 0.05 + rnd() * 0.5, tilt = rnd() * 1.5, turn = rnd() * 6.2832;
    // Edge vectors a (horizontal) and b (tilted), so the quad is planar and convex.
    const double ax = std::cos(turn) * s, ay = std::sin(turn) * s;
    const double bx = -std::sin(turn) * std::cos(tilt) * s,
                 by = std::cos(turn) * std::cos(tilt) * s, bz = std::sin(tilt) * s;
    std::fprintf(f, "%s polygon p%ld\n0\n0\n12", mats[i % 4], i);
    const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corner)
      std::fprintf(f, " %.10g %.10g %.10g", cx + c[0] * ax + c[1] * bx, cy + c[0] * ay + c[1] * by,
                   cz + c[1] * bz);
    std::fprintf(f, "\n");
  }
  if (std::fclose(f) != 0) throw radcl::FatalError("write error on \"" + out + "\"");
  std::printf("%s: %ld polygons\n", out.c_str(), n);
  return 0;
}

int body(int argc, char** argv) {
  if (argc != 4 || std::atol(argv[2]) <= 0)
    throw radcl::FatalError("usage: gen_scenes mesh|polygons N out");
  std::string command = "gen_scenes";
  for (int i = 1; i < argc; ++i)
    command += std::string(" ") + argv[i];
  const std::string kind = argv[1];
  if (kind == "mesh") return gen_mesh(std::atol(argv[2]), argv[3], command);
  if (kind == "polygons") return gen_polygons(std::atol(argv[2]), argv[3], command);
  throw radcl::FatalError("unknown scene kind \"" + kind + "\"");
}

} // namespace

int main(int argc, char** argv) {
  return radcl::run_main("gen_scenes", body, argc, argv);
}
