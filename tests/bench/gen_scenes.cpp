// Scene generator for load benchmarks (tests/bench/scene_load.sh):
//   gen_scenes mesh N out.rtm      a terrain of about N triangles, with normals, uv and two
//                                  materials, written as a Radiance mesh, plus out.rad that
//                                  places it ("void mesh terrain 1 out.rtm 0 0")
//   gen_scenes polygons N out.rad  N quadrilaterals over four materials, as Radiance text
//   gen_scenes openplan N dir      an open-plan floor of NX x NY furnished office bays
//                                  (N = NX, NY = NX / 2 + 1) for tests/bench/peers.sh: each bay
//                                  an instance of office_unit.oct (desk, partitions, two
//                                  chair.oct instances, a plant mesh of 20,000 triangles);
//                                  writes plant.rtm, office_unit.rad and floor.rad into dir
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

// A closed, lumpy blob of about n triangles (a displaced sphere): dense geometry that is cheap
// to generate and looks like a plant or a sculpture.
TriangleMesh blob(long n_tris) {
  TriangleMesh m;
  const long nv = std::max(4L, std::lround(std::sqrt(n_tris / 4.0))), nu = 2 * nv;
  for (long j = 0; j <= nv; ++j)
    for (long i = 0; i < nu; ++i) {
      const double th = M_PI * double(j) / nv, ph = 2 * M_PI * double(i) / nu;
      const double r = 1 + 0.18 * std::sin(5 * th) * std::cos(7 * ph) + 0.06 * std::sin(23 * ph);
      m.positions.push_back(
          {r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th)});
    }
  m.vertex_flags.assign(m.positions.size(), 0);
  auto id = [nu](long i, long j) { return static_cast<std::uint32_t>(j * nu + (i % nu)); };
  for (long j = 0; j < nv; ++j)
    for (long i = 0; i < nu; ++i) {
      if (j > 0) m.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
      if (j + 1 < nv) m.triangles.push_back({id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)});
    }
  m.triangle_material.assign(m.triangles.size(), 0);
  Object o;
  o.type = RC_OBJ_PLASTIC;
  o.name = "leaf";
  o.fargs = {0.15, 0.35, 0.1, 0.01, 0.1};
  m.objects.objects.push_back(o);
  m.materials.push_back("leaf");
  return m;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  if (!f) throw radcl::FatalError("write error on \"" + path + "\"");
}

// Bays of 6 x 4 m in a 2.7 m high floor plate with window bands on both long sides.
int gen_openplan(long nx, const std::string& dir, const std::string& command) {
  const long ny = nx / 2 + 1;
  const auto info = radcl::scene::write_mesh(blob(20000), dir + "/plant.rtm", {{command}});
  std::string unit =
      "# " + command +
      "\n"
      "void plastic desk_wood 0 0 5 .45 .32 .2 .02 .05\n"
      "void plastic panel_cloth 0 0 5 .3 .35 .45 0 0\n"
      "void instance chair_a 5 chair.oct -t 3 1.2 0 0 0\n"
      "void instance chair_b 7 chair.oct -rz 180 -t 3 2.8 0 0 0\n"
      "void mesh plant 7 plant.rtm -s 0.35 -t 5.3 3.3 0.6 0 0\n"
      "panel_cloth polygon part_s 0 0 12 0 0.05 0  6 0.05 0  6 0.05 1.2  0 0.05 1.2\n"
      "panel_cloth polygon part_w 0 0 12 0.05 0 0  0.05 0 1.2  0.05 4 1.2  0.05 4 0\n"
      "desk_wood polygon desk_top 0 0 12 2.2 1.6 0.75  3.8 1.6 0.75  3.8 2.4 0.75  "
      "2.2 2.4 0.75\n";
  // The desk's sides, facing out.
  const char* sides[] = {"2.2 1.6 0  3.8 1.6 0  3.8 1.6 0.75  2.2 1.6 0.75",
                         "3.8 1.6 0  3.8 2.4 0  3.8 2.4 0.75  3.8 1.6 0.75",
                         "3.8 2.4 0  2.2 2.4 0  2.2 2.4 0.75  3.8 2.4 0.75",
                         "2.2 2.4 0  2.2 1.6 0  2.2 1.6 0.75  2.2 2.4 0.75"};
  for (int k = 0; k < 4; ++k)
    unit += "desk_wood polygon desk_side" + std::to_string(k) + " 0 0 12 " + sides[k] + "\n";
  write_text(dir + "/office_unit.rad", unit);

  const double w = 6.0 * nx, h = 4.0 * ny;
  char buf[512];
  std::string floor = "# " + command +
                      "\n"
                      "void plastic floor_mat 0 0 5 .25 .22 .2 0 0\n"
                      "void plastic ceiling_mat 0 0 5 .8 .8 .8 0 0\n"
                      "void plastic wall_mat 0 0 5 .6 .6 .58 0 0\n"
                      "void glass window_glass 0 0 3 .86 .86 .86\n";
  auto quad = [&](const char* mat, const char* name, double a[4][3]) {
    std::snprintf(buf, sizeof buf, "%s polygon %s 0 0 12 %g %g %g  %g %g %g  %g %g %g  %g %g %g\n",
                  mat, name, a[0][0], a[0][1], a[0][2], a[1][0], a[1][1], a[1][2], a[2][0], a[2][1],
                  a[2][2], a[3][0], a[3][1], a[3][2]);
    floor += buf;
  };
  double f[4][3] = {{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}};
  double c[4][3] = {{0, 0, 2.7}, {0, h, 2.7}, {w, h, 2.7}, {w, 0, 2.7}};
  quad("floor_mat", "floor", f);
  quad("ceiling_mat", "ceiling", c);
  // South (y = 0, facing +y) and north (y = h, facing -y): wall, window band 0.9-2.4 m, wall.
  for (int side = 0; side < 2; ++side) {
    const double y = side ? h : 0;
    const double bands[3][2] = {{0, 0.9}, {0.9, 2.4}, {2.4, 2.7}};
    for (int b = 0; b < 3; ++b) {
      double q[4][3] = {
          {0, y, bands[b][0]}, {0, y, bands[b][1]}, {w, y, bands[b][1]}, {w, y, bands[b][0]}};
      if (side) std::swap(q[1], q[3]);
      const std::string name = std::string(side ? "north" : "south") + std::to_string(b);
      quad(b == 1 ? "window_glass" : "wall_mat", name.c_str(), q);
    }
  }
  double west[4][3] = {{0, 0, 0}, {0, h, 0}, {0, h, 2.7}, {0, 0, 2.7}};
  double east[4][3] = {{w, 0, 0}, {w, 0, 2.7}, {w, h, 2.7}, {w, h, 0}};
  quad("wall_mat", "west", west);
  quad("wall_mat", "east", east);
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      std::snprintf(buf, sizeof buf, "void instance bay_%ld_%ld 5 office_unit.oct -t %g %g 0 0 0\n",
                    i, j, 6.0 * i, 4.0 * j);
      floor += buf;
    }
  write_text(dir + "/floor.rad", floor);
  std::printf("%s: %ld x %ld bays of %zu plant triangles (%.2f million placed), %g x %g m\n",
              dir.c_str(), nx, ny, info.source_triangle.size(),
              1e-6 * double(nx * ny) * double(info.source_triangle.size()), w, h);
  return 0;
}

int body(int argc, char** argv) {
  if (argc != 4 || std::atol(argv[2]) <= 0)
    throw radcl::FatalError("usage: gen_scenes mesh|polygons|openplan N out");
  std::string command = "gen_scenes";
  for (int i = 1; i < argc; ++i)
    command += std::string(" ") + argv[i];
  const std::string kind = argv[1];
  if (kind == "mesh") return gen_mesh(std::atol(argv[2]), argv[3], command);
  if (kind == "polygons") return gen_polygons(std::atol(argv[2]), argv[3], command);
  if (kind == "openplan") return gen_openplan(std::atol(argv[2]), argv[3], command);
  throw radcl::FatalError("unknown scene kind \"" + kind + "\"");
}

} // namespace

int main(int argc, char** argv) {
  return radcl::run_main("gen_scenes", body, argc, argv);
}
