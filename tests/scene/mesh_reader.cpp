// Radiance triangle meshes: octa.rtm (written by obj2mesh from teapot_like.obj) checked
// against the .obj itself, and small meshes written here to reach joiner triangles, stored
// materials and the consistency checks.
#include "radcl/scene/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "radcl/scene/portable_io.h"
#include "radcl/util/error.h"
#include "temp_dir.h"
#include "test_env.h"

namespace radcl::scene {
namespace {

namespace fs = std::filesystem;

// tests/data, also when the harness did not pass RADCL_TEST_DATA through.
std::string data(const std::string& name) {
  if (std::getenv("RADCL_TEST_DATA")) return test::data(name);
  return (fs::path(__FILE__).parent_path().parent_path() / "data" / name).string();
}

struct Obj {
  std::vector<std::array<double, 3>> v, vn;
  std::vector<std::array<double, 2>> vt;
  struct Corner {
    int v, t, n;
  };
  std::vector<std::array<Corner, 3>> faces;
};

Obj read_obj(const std::string& path) {
  Obj o;
  std::ifstream f(path);
  std::string line;
  while (std::getline(f, line)) {
    std::istringstream ss(line);
    std::string tag;
    ss >> tag;
    if (tag == "v" || tag == "vn") {
      std::array<double, 3> a{};
      ss >> a[0] >> a[1] >> a[2];
      (tag == "v" ? o.v : o.vn).push_back(a);
    } else if (tag == "vt") {
      std::array<double, 2> a{};
      ss >> a[0] >> a[1];
      o.vt.push_back(a);
    } else if (tag == "f") {
      std::array<Obj::Corner, 3> face{};
      for (auto& c : face) {
        std::string w;
        ss >> w;
        char slash;
        std::istringstream ws(w);
        ws >> c.v >> slash >> c.t >> slash >> c.n;
        --c.v, --c.t, --c.n;
      }
      o.faces.push_back(face);
    }
  }
  return o;
}

double dist(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

TEST(MeshReader, OctaMatchesObj) {
  const Obj obj = read_obj(data("scenes/teapot_like.obj"));
  ASSERT_EQ(obj.faces.size(), 8u);
  const TriangleMesh m = read_mesh(data("scenes/octa.rtm"));

  EXPECT_EQ(m.positions.size(), obj.v.size()); // every vertex shares one normal and uv
  ASSERT_EQ(m.triangles.size(), obj.faces.size());
  ASSERT_EQ(m.triangle_material.size(), m.triangles.size());
  ASSERT_EQ(m.normals.size(), m.positions.size());
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  // obj2mesh without -a stores no materials: all faces are void.
  EXPECT_TRUE(m.materials.empty());
  EXPECT_TRUE(m.objects.objects.empty());
  for (auto mat : m.triangle_material)
    EXPECT_EQ(mat, -1);

  // Quantisation step of positions is cube size / 2^32 (cube 2.00002 here).
  const double eps = 1e-8;
  std::vector<bool> used(m.triangles.size(), false);
  for (const auto& face : obj.faces) {
    bool found = false;
    for (std::size_t t = 0; t < m.triangles.size() && !found; ++t) {
      if (used[t]) continue;
      for (int rot = 0; rot < 3 && !found; ++rot) {
        bool match = true;
        for (int k = 0; k < 3; ++k)
          match &= dist(m.positions[m.triangles[t][(k + rot) % 3]], obj.v[face[k].v]) < eps;
        if (!match) continue;
        found = used[t] = true;
        for (int k = 0; k < 3; ++k) {
          const auto vi = m.triangles[t][(k + rot) % 3];
          EXPECT_EQ(m.vertex_flags[vi], TriangleMesh::kHasNormal | TriangleMesh::kHasUV);
          for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(m.normals[vi][c], obj.vn[face[k].n][c], 1e-3);
          for (int c = 0; c < 2; ++c)
            EXPECT_NEAR(m.uvs[vi][c], obj.vt[face[k].t][c], 1e-6);
        }
      }
    }
    EXPECT_TRUE(found) << "face with vertex " << face[0].v + 1 << " not in the mesh";
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(m.bbox_min[c], -1.0, eps);
    EXPECT_NEAR(m.bbox_max[c], 1.0, eps);
  }
}

// ---------------------------------------------------------------- synthetic meshes

struct MeshSpec {
  std::vector<std::pair<std::string, std::string>> materials = {{"plastic", "red"},
                                                                {"plastic", "blue"}};
  int local_index = 2;        // third vertex of the local triangle
  int local_mat = 1;          // its sole material
  std::int32_t j1_vertex = 2; // patch 0, vertex 2
  std::int16_t j2_mat = 1;
};

// Two patches: patch 0 has 3 vertices with uv and one local triangle; patch 1 has 2 vertices
// without uv, a single-joiner and a double-joiner triangle reaching into patch 0.
std::string mesh_bytes(const MeshSpec& spec) {
  std::string s = "#?RADIANCE\nobj2mesh test\nFORMAT=Radiance_tmesh\n\n";
  put_int(s, 319 + 4, 2);
  for (const char* c : {"0", "0", "0", "1"})
    put_str(s, c);
  for (double f : {0.0, 1.0, 0.0, 1.0}) // u lo, u hi, v lo, v hi
    put_flt(s, f);
  s.push_back('\0'); // empty triangle octree
  put_str(s, "plastic");
  put_str(s, "polygon");
  put_str(s, "");
  for (const auto& [type, name] : spec.materials) {
    put_int(s, type == "plastic" ? 0 : 1, 1);
    put_int(s, -1, 4);
    put_str(s, name);
    put_int(s, 0, 2);
    put_int(s, 5, 2);
    for (double f : {0.5, 0.5, 0.5, 0.0, 0.0})
      put_flt(s, f);
  }
  s.push_back(static_cast<char>(0xff));
  put_int(s, 2, 4); // patches
  // patch 0
  put_int(s, 1 | 4, 1);
  put_int(s, 3, 2);
  const std::uint32_t q = 1u << 30; // a quarter of the cube
  for (auto v : {std::array<std::uint32_t, 3>{0, 0, 0}, {q, 0, 0}, {0, q, 0}})
    for (auto c : v)
      put_int(s, c, 4);
  for (auto uv : {std::array<std::uint32_t, 2>{1, 1}, {q, 1}, {1, q}})
    for (auto c : uv)
      put_int(s, c, 4);
  put_int(s, 1, 2);
  for (int v : {0, 1, spec.local_index})
    put_int(s, v, 1);
  put_int(s, 1, 2); // sole material follows
  put_int(s, spec.local_mat, 2);
  put_int(s, 0, 2);
  put_int(s, 0, 2);
  // patch 1
  put_int(s, 1, 1);
  put_int(s, 2, 2);
  for (auto v : {std::array<std::uint32_t, 3>{0, 0, q}, {q, q, 0}})
    for (auto c : v)
      put_int(s, c, 4);
  put_int(s, 0, 2); // no local triangles
  put_int(s, 1, 2);
  put_int(s, 0, 2);
  put_int(s, 1, 2); // one single joiner
  put_int(s, spec.j1_vertex, 4);
  put_int(s, 0, 1);
  put_int(s, 1, 1);
  put_int(s, 0, 2);
  put_int(s, 1, 2); // one double joiner
  put_int(s, 0, 4);
  put_int(s, 1, 4);
  put_int(s, 1, 1);
  put_int(s, spec.j2_mat, 2);
  return s;
}

fs::path write_temp(const std::string& name, const std::string& contents) {
  static const test::TempFolder dir("mesh_reader"); // removed at exit
  fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << contents;
  return p;
}

std::string error_of(const std::string& name, const std::string& contents) {
  const auto p = write_temp(name, contents);
  std::string msg = "(no error)";
  try {
    read_mesh(p.string());
  } catch (const FatalError& e) {
    msg = e.what();
  }
  fs::remove(p);
  return msg;
}

TEST(MeshReader, PatchesJoinersAndMaterials) {
  const auto p = write_temp("good.rtm", mesh_bytes({}));
  const TriangleMesh m = read_mesh(p.string());
  fs::remove(p);
  ASSERT_EQ(m.positions.size(), 5u);
  EXPECT_NEAR(m.positions[1][0], 0.25, 1e-9);
  EXPECT_NEAR(m.positions[4][1], 0.25, 1e-9);
  EXPECT_NEAR(m.positions[3][2], 0.25, 1e-9);
  EXPECT_EQ(m.materials, (std::vector<std::string>{"red", "blue"}));
  ASSERT_EQ(m.objects.objects.size(), 2u);
  EXPECT_EQ(m.objects.objects[1].type, RC_OBJ_PLASTIC);
  using Tri = std::array<std::uint32_t, 3>;
  ASSERT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.triangles[0], (Tri{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Tri{2, 3, 4})); // joiner: patch 0 vertex 2, then local 0, 1
  EXPECT_EQ(m.triangles[2], (Tri{0, 1, 4}));
  EXPECT_EQ(m.triangle_material, (std::vector<std::int32_t>{1, 0, 1}));
  EXPECT_TRUE(m.normals.empty());
  ASSERT_EQ(m.uvs.size(), 5u);
  EXPECT_NEAR(m.uvs[1][0], 0.25, 1e-6);
  EXPECT_EQ(m.vertex_flags, (std::vector<std::uint8_t>{2, 2, 2, 0, 0}));
}

TEST(MeshReader, ConsistencyErrors) {
  MeshSpec s;
  s.local_index = 5;
  EXPECT_NE(error_of("a.rtm", mesh_bytes(s)).find("): bad local triangle index"),
            std::string::npos);
  s = {};
  s.local_mat = 2;
  EXPECT_NE(error_of("b.rtm", mesh_bytes(s)).find("): bad local triangle material"),
            std::string::npos);
  s = {};
  s.j1_vertex = 7 << 8;
  EXPECT_NE(error_of("c.rtm", mesh_bytes(s)).find("): bad j1 triangle joiner"), std::string::npos);
  s = {};
  s.j2_mat = -1; // void is not allowed once the mesh stores materials
  EXPECT_NE(error_of("d.rtm", mesh_bytes(s)).find("): bad j2 triangle material"),
            std::string::npos);
  s = {};
  s.materials = {{"plastic", "red"}, {"polygon", "p"}};
  EXPECT_NE(error_of("e.rtm", mesh_bytes(s)).find("): non-modifier in mesh (polygon \"p\")"),
            std::string::npos);
  // Without stored materials every face is void whatever index it carries.
  s = {};
  s.materials.clear();
  s.local_mat = 3;
  const auto p = write_temp("f.rtm", mesh_bytes(s));
  const TriangleMesh m = read_mesh(p.string());
  fs::remove(p);
  EXPECT_EQ(m.triangle_material, (std::vector<std::int32_t>{-1, -1, -1}));
}

TEST(MeshReader, EveryTruncationIsAnError) {
  const std::string good = mesh_bytes({});
  for (std::size_t n = 0; n < good.size(); ++n) {
    const std::string msg = error_of("cut.rtm", good.substr(0, n));
    EXPECT_TRUE(msg.find("truncated mesh") != std::string::npos ||
                msg.find("not a mesh file") != std::string::npos)
        << n << ": " << msg;
  }
}

TEST(MeshReader, BadHeaderAndMagic) {
  std::string s = mesh_bytes({});
  std::string wrong = s;
  wrong.replace(wrong.find("Radiance_tmesh"), 14, "Radiance_otree");
  EXPECT_NE(error_of("g.rtm", wrong).find("not a mesh file"), std::string::npos);
  std::string magic = s;
  magic[magic.find("\n\n") + 3] = 0x3f; // objsize 0
  EXPECT_NE(error_of("h.rtm", magic).find("incompatible mesh format"), std::string::npos);
  try {
    read_mesh("/nonexistent/m.rtm");
    FAIL();
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "cannot open mesh file \"/nonexistent/m.rtm\"");
  }
}

} // namespace
} // namespace radcl::scene
