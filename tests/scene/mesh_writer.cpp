// The mesh writer: obj2mesh's own output for teapot_like.obj reproduced byte for byte, round
// trips through read_mesh() (small meshes, one of several hundred patches, octa.rtm itself),
// an octree that finds every triangle where Radiance looks for it, and the meshes obj2mesh
// refuses.
#include "radcl/scene/mesh_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "files.h"
#include "radcl/scene/octree_reader.h"
#include "radcl/scene/portable_io.h"
#include "radcl/util/error.h"
#include "temp_dir.h"
#include "test_env.h"

namespace radcl::scene {
namespace {

namespace fs = std::filesystem;
using V3 = std::array<double, 3>;

std::string data(const std::string& name) {
  if (std::getenv("RADCL_TEST_DATA")) return test::data(name);
  return (fs::path(__FILE__).parent_path().parent_path() / "data" / name).string();
}

// teapot_like.obj as obj2mesh sees it: each vertex has one normal and one uv.
TriangleMesh mesh_from_obj(const std::string& path) {
  TriangleMesh m;
  std::ifstream f(path);
  std::string line;
  std::vector<std::array<float, 3>> vn;
  std::vector<std::array<float, 2>> vt;
  while (std::getline(f, line)) {
    std::istringstream ss(line);
    std::string tag;
    ss >> tag;
    if (tag == "v") {
      V3 p{};
      ss >> p[0] >> p[1] >> p[2];
      m.positions.push_back(p);
    } else if (tag == "vn") {
      std::array<float, 3> n{};
      ss >> n[0] >> n[1] >> n[2];
      vn.push_back(n);
    } else if (tag == "vt") {
      std::array<float, 2> t{};
      ss >> t[0] >> t[1];
      vt.push_back(t);
    } else if (tag == "f") {
      std::array<std::uint32_t, 3> tri{};
      for (auto& v : tri) {
        std::string w;
        ss >> w;
        int iv = 0, it = 0, in = 0;
        char s1, s2;
        std::istringstream(w) >> iv >> s1 >> it >> s2 >> in;
        v = static_cast<std::uint32_t>(iv - 1);
        m.normals.resize(m.positions.size());
        m.uvs.resize(m.positions.size());
        m.vertex_flags.resize(m.positions.size());
        m.normals[v] = vn.at(static_cast<std::size_t>(in - 1));
        m.uvs[v] = vt.at(static_cast<std::size_t>(it - 1));
        m.vertex_flags[v] = TriangleMesh::kHasNormal | TriangleMesh::kHasUV;
      }
      m.triangles.push_back(tri);
      m.triangle_material.push_back(kVoid); // obj2mesh without -a: all void
    }
  }
  return m;
}

TriangleMesh round_trip(const TriangleMesh& m, MeshWriteInfo* info,
                        const MeshWriteOptions& opt = {}) {
  const radcl::test::TempFolder tmp("mesh_writer");
  const fs::path p = tmp / "m.rtm";
  *info = write_mesh(m, p.string(), opt);
  return read_mesh(p.string());
}

// Every triangle read back matches its source (any rotation of its corners, as joiners
// rotate them) to `pos_tol` in position, the normal code's precision and the uv code's.
void expect_same_triangles(const TriangleMesh& in, const TriangleMesh& out,
                           const MeshWriteInfo& info, double pos_tol) {
  ASSERT_EQ(out.triangles.size(), info.source_triangle.size());
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    const std::uint32_t s = info.source_triangle[t];
    ASSERT_LT(s, in.triangles.size());
    int rot = -1;
    for (int r = 0; r < 3 && rot < 0; ++r) {
      bool ok = true;
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c)
          ok &= std::abs(out.positions[out.triangles[t][(k + r) % 3]][c] -
                         in.positions[in.triangles[s][k]][c]) <= pos_tol;
      if (ok) rot = r;
    }
    ASSERT_GE(rot, 0) << "triangle " << t << " (source " << s << ") moved";
    const std::int32_t in_mat = s < in.triangle_material.size() ? in.triangle_material[s] : -1;
    const std::int32_t out_mat = out.triangle_material[t];
    if (in_mat < 0)
      EXPECT_EQ(out_mat, -1);
    else
      EXPECT_EQ(out.materials.at(static_cast<std::size_t>(out_mat)),
                in.materials.at(static_cast<std::size_t>(in_mat)));
    for (int k = 0; k < 3; ++k) {
      const auto vi = in.triangles[s][k], vo = out.triangles[t][(k + rot) % 3];
      if (out.vertex_flags[vo] & TriangleMesh::kHasNormal) {
        ASSERT_TRUE(in.vertex_flags[vi] & TriangleMesh::kHasNormal);
        double len = 0;
        for (int c = 0; c < 3; ++c)
          len += double{in.normals[vi][c]} * in.normals[vi][c];
        for (int c = 0; c < 3; ++c) // 13-bit components: < 1e-4 apart
          EXPECT_NEAR(out.normals[vo][c], in.normals[vi][c] / std::sqrt(len), 2e-4);
      }
      if (out.vertex_flags[vo] & TriangleMesh::kHasUV) {
        ASSERT_TRUE(in.vertex_flags[vi] & TriangleMesh::kHasUV);
        for (int c = 0; c < 2; ++c)
          EXPECT_NEAR(out.uvs[vo][c], in.uvs[vi][c], 1e-6);
      }
    }
  }
}

// A height field of n x n quads with analytic normals, uv, and materials by quadrant.
TriangleMesh grid(int n, bool with_materials) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      const double z = 0.2 * std::sin(6 * x) * std::cos(5 * y);
      const double dx = 1.2 * std::cos(6 * x) * std::cos(5 * y);
      const double dy = -1.0 * std::sin(6 * x) * std::sin(5 * y);
      const double l = std::sqrt(dx * dx + dy * dy + 1);
      m.positions.push_back({x * 3 - 1, y * 3 + 2, z});
      m.normals.push_back({float(-dx / l), float(-dy / l), float(1 / l)});
      m.uvs.push_back({float(x), float(y)});
      m.vertex_flags.push_back(TriangleMesh::kHasNormal | TriangleMesh::kHasUV);
    }
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t mat = with_materials ? (i * 2 / n) + 2 * (j * 2 / n) : kVoid;
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      m.triangle_material.insert(m.triangle_material.end(), 2, mat);
    }
  if (with_materials) {
    for (const char* name : {"red", "green", "blue", "grey"}) {
      Object o;
      o.type = RC_OBJ_PLASTIC;
      o.name = name;
      o.fargs = {0.5, 0.25, 0.125, 0.0, 0.0};
      m.objects.objects.push_back(o);
      m.materials.push_back(name);
    }
  }
  return m;
}

TEST(MeshWriter, ReproducesObj2meshBytes) {
  const TriangleMesh m = mesh_from_obj(data("scenes/teapot_like.obj"));
  MeshWriteOptions opt;
  opt.header_lines = {"obj2mesh teapot_like.obj"};
  std::string bytes;
  const MeshWriteInfo info = encode_mesh(m, bytes, opt);
  EXPECT_EQ(info.vertices, 6u);
  EXPECT_EQ(info.patches, 1u);
  // Byte for byte, except that TriangleMesh keeps uv in float: obj2mesh encoded the .obj's
  // double 0.2, so one uv code may differ in its last bits.
  const std::string ref = radcl::test::read_file(data("scenes/octa.rtm"));
  ASSERT_EQ(bytes.size(), ref.size());
  std::vector<std::size_t> diff;
  for (std::size_t i = 0; i < ref.size(); ++i)
    if (bytes[i] != ref[i]) diff.push_back(i);
  if (diff.empty()) return;
  // The patch ends with 6 x 2 uv codes, then 34 bytes of triangles and counts.
  const std::size_t uv_start = ref.size() - 34 - 48;
  ASSERT_GE(diff.front(), uv_start);
  const std::size_t word = uv_start + (diff.front() - uv_start) / 4 * 4;
  ASSERT_LT(diff.back(), word + 4) << "differences beyond one uv code";
  auto code = [&](const std::string& s) {
    return decode_int(reinterpret_cast<const unsigned char*>(s.data()) + word, 4);
  };
  EXPECT_LT(std::abs(code(bytes) - code(ref)), 256) << "at byte " << word;
}

TEST(MeshWriter, OctaRoundTripGivesTheSameMesh) {
  const TriangleMesh a = read_mesh(data("scenes/octa.rtm"));
  MeshWriteInfo info;
  const TriangleMesh b = round_trip(a, &info);
  EXPECT_EQ(b.triangles.size(), a.triangles.size());
  EXPECT_EQ(b.positions.size(), a.positions.size());
  EXPECT_EQ(b.materials, a.materials);
  EXPECT_EQ(b.vertex_flags, a.vertex_flags);
  expect_same_triangles(a, b, info, 2.1 / 4294967296.0 * 4);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(b.bbox_min[c], a.bbox_min[c], 1e-9);
    EXPECT_NEAR(b.bbox_max[c], a.bbox_max[c], 1e-9);
  }
}

TEST(MeshWriter, SmallMeshWithMaterialsNormalsAndUV) {
  const TriangleMesh m = grid(6, true);
  MeshWriteInfo info;
  MeshWriteOptions keep;
  keep.obj2mesh_normals = false;
  const TriangleMesh r = round_trip(m, &info, keep);
  EXPECT_EQ(info.skipped_degenerate, 0u);
  EXPECT_EQ(r.triangles.size(), m.triangles.size());
  EXPECT_EQ(r.positions.size(), m.positions.size()); // shared vertices stay shared
  EXPECT_EQ(r.materials, m.materials);
  ASSERT_EQ(r.objects.objects.size(), 4u);
  EXPECT_EQ(r.objects.objects[2].type, RC_OBJ_PLASTIC);
  EXPECT_NEAR(r.objects.objects[2].fargs[1], 0.25, 1e-9);
  for (auto f : r.vertex_flags)
    EXPECT_EQ(f, TriangleMesh::kHasNormal | TriangleMesh::kHasUV);
  expect_same_triangles(m, r, info, 4.0 * 3.00002 / 4294967296.0);
}

TEST(MeshWriter, Obj2meshDropsNormalsOfFlatTriangles) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.uvs.assign(4, {0, 0});
  m.vertex_flags.assign(4, TriangleMesh::kHasNormal);
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  MeshWriteInfo info;
  const TriangleMesh r = round_trip(m, &info);
  ASSERT_EQ(r.triangles.size(), 2u);
  int with_normals = 0;
  for (std::size_t t = 0; t < 2; ++t) {
    const int flags = r.vertex_flags[r.triangles[t][0]];
    with_normals += (flags & TriangleMesh::kHasNormal) != 0;
    // The flat one (source 0) lost its normals, the bent one kept them.
    EXPECT_EQ((flags & TriangleMesh::kHasNormal) != 0, info.source_triangle[t] == 1);
  }
  EXPECT_EQ(with_normals, 1);
  // Normals all against the winding: obj2mesh turns the triangle over.
  m.normals.assign(4, {0, 0, -1});
  m.triangles = {{0, 1, 2}};
  const TriangleMesh f = round_trip(m, &info);
  const auto& p = f.positions;
  const auto& t = f.triangles[0];
  const double nz = (p[t[1]][0] - p[t[0]][0]) * (p[t[2]][1] - p[t[0]][1]) -
                    (p[t[1]][1] - p[t[0]][1]) * (p[t[2]][0] - p[t[0]][0]);
  EXPECT_LT(nz, 0);
  EXPECT_EQ(f.vertex_flags[t[0]] & TriangleMesh::kHasNormal, 0); // and it was flat
}

TEST(MeshWriter, ManyPatchesWithJoiners) {
  const TriangleMesh m = grid(256, true); // 66049 vertices
  ASSERT_GT(m.positions.size(), 65536u);
  MeshWriteInfo info;
  MeshWriteOptions keep;
  keep.obj2mesh_normals = false;
  const TriangleMesh r = round_trip(m, &info, keep);
  EXPECT_GT(info.patches, 256u);
  EXPECT_EQ(r.positions.size(), m.positions.size());
  EXPECT_EQ(r.triangles.size(), m.triangles.size());
  expect_same_triangles(m, r, info, 4.0 * 3.00002 / 4294967296.0);
  // Every input triangle is there once.
  std::vector<int> seen(m.triangles.size(), 0);
  for (auto s : info.source_triangle)
    ++seen[s];
  for (int c : seen)
    ASSERT_EQ(c, 1);
}

// ---------------------------------------------------------------- the octree section

struct Layout {
  V3 org{};
  double size = 0;
  std::vector<std::pair<std::array<double, 4>, std::vector<std::int32_t>>> leaves; // cube, set
  std::map<std::int32_t, std::size_t> id_to_read_index;
};

// Decodes what Radiance's readmesh() uses of the file: cube, tree, and the triangle IDs
// (patch << 10 | 0x200 joiner | 0x100 double | index) in read order.
Layout decode_layout(const std::string& bytes) {
  ByteReader in(bytes, "mesh");
  EXPECT_TRUE(read_info_header(in).has_value());
  EXPECT_EQ(in.getint(2), 323);
  Layout L;
  for (auto& c : L.org)
    c = std::atof(in.getstr().c_str());
  L.size = std::atof(in.getstr().c_str());
  for (int i = 0; i < 4; ++i)
    in.getflt();
  std::function<void(V3, double)> tree = [&](V3 o, double s) {
    const int t = in.get();
    if (t == 2) {
      for (int i = 0; i < 8; ++i) {
        V3 k = o;
        for (int j = 0; j < 3; ++j)
          if (i & (1 << j)) k[j] += s / 2;
        tree(k, s / 2);
      }
    } else if (t == 1) {
      std::vector<std::int32_t> set(static_cast<std::size_t>(in.getint(4)));
      for (auto& id : set)
        id = static_cast<std::int32_t>(in.getint(4));
      EXPECT_TRUE(std::is_sorted(set.begin(), set.end()));
      L.leaves.push_back({{o[0], o[1], o[2], s}, set});
    } else {
      EXPECT_EQ(t, 0);
    }
  };
  tree(L.org, L.size);
  SceneDescription mats;
  EXPECT_TRUE(read_binary_scene(in, 4, mats));
  const auto npatches = in.getint(4);
  std::size_t next = 0;
  for (std::int32_t p = 0; p < npatches; ++p) {
    const int flags = static_cast<int>(in.getint(1));
    const auto nv = in.getint(2);
    for (std::int64_t i = 0; i < nv * (3 + (flags & 2 ? 1 : 0) + (flags & 4 ? 2 : 0)); ++i)
      in.getint(4);
    const auto nt = in.getint(2);
    for (std::int64_t i = 0; i < nt * 3; ++i)
      in.get();
    const auto nm = in.getint(2);
    for (std::int64_t i = 0; i < (nm > 1 ? nm : 1); ++i)
      in.getint(2);
    for (std::int32_t i = 0; i < nt; ++i)
      L.id_to_read_index[p << 10 | i] = next++;
    const auto n1 = in.getint(2);
    for (std::int32_t i = 0; i < n1; ++i) {
      in.getint(4), in.getint(1), in.getint(1), in.getint(2);
      L.id_to_read_index[p << 10 | 0x200 | i] = next++;
    }
    const auto n2 = in.getint(2);
    for (std::int32_t i = 0; i < n2; ++i) {
      in.getint(4), in.getint(4), in.getint(1), in.getint(2);
      L.id_to_read_index[p << 10 | 0x300 | i] = next++;
    }
  }
  EXPECT_TRUE(in.at_end());
  return L;
}

TEST(MeshWriter, OctreeHoldsEveryTriangleWhereRadianceLooks) {
  const TriangleMesh m = grid(40, false);
  std::string bytes;
  const MeshWriteInfo info = encode_mesh(m, bytes);
  const Layout L = decode_layout(bytes);
  EXPECT_EQ(L.leaves.size(), info.octree_leaves);
  EXPECT_GT(L.leaves.size(), 100u); // subdivided: at most 9 triangles a leaf above the limit
  std::vector<int> in_leaves(m.triangles.size(), 0);
  for (const auto& [cube, set] : L.leaves) {
    for (std::int32_t id : set) {
      auto it = L.id_to_read_index.find(id);
      ASSERT_NE(it, L.id_to_read_index.end()) << "bad triangle ID " << id;
      ++in_leaves[it->second];
    }
  }
  // Each triangle's centroid and corners lie in leaves that list it (Radiance looks up the
  // ray's cube), so it is found from every point of it.
  std::map<std::size_t, std::int32_t> read_to_id;
  for (const auto& [id, idx] : L.id_to_read_index)
    read_to_id[idx] = id;
  for (std::size_t t = 0; t < info.source_triangle.size(); ++t) {
    EXPECT_GT(in_leaves[t], 0);
    const auto& tri = m.triangles[info.source_triangle[t]];
    V3 c{0, 0, 0};
    for (auto v : tri)
      for (int j = 0; j < 3; ++j)
        c[j] += m.positions[v][j] / 3;
    bool found = false;
    for (const auto& [cube, set] : L.leaves) {
      bool inside = true;
      for (int j = 0; j < 3; ++j)
        inside &= c[j] >= cube[j] && c[j] < cube[j] + cube[3];
      if (inside) found |= std::binary_search(set.begin(), set.end(), read_to_id.at(t));
    }
    EXPECT_TRUE(found) << "triangle " << t << " missing at its centroid";
  }
}

TEST(MeshWriter, SkipsDegenerateTriangles) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 1, 3}, {2, 2, 1}};
  MeshWriteInfo info;
  const TriangleMesh r = round_trip(m, &info);
  EXPECT_EQ(info.skipped_degenerate, 2u);
  ASSERT_EQ(r.triangles.size(), 1u);
  EXPECT_TRUE(r.normals.empty());
  EXPECT_TRUE(r.uvs.empty());
}

TEST(MeshWriter, RefusesWhatObj2meshCannotWrite) {
  std::string out;
  TriangleMesh empty;
  EXPECT_THROW(encode_mesh(empty, out), FatalError);
  TriangleMesh m = grid(2, true);
  m.triangle_material[3] = kVoid;
  EXPECT_THROW(encode_mesh(m, out), FatalError); // void mixed with materials
  m = grid(2, true);
  m.objects.objects.resize(2);
  EXPECT_THROW(encode_mesh(m, out), FatalError); // material 3 undefined
  m = grid(2, true);
  m.objects.objects[0].type = RC_OBJ_SPHERE;
  EXPECT_THROW(encode_mesh(m, out), FatalError); // a surface among the materials
  m = grid(2, true);
  EXPECT_THROW(write_mesh(m, "/nonexistent-dir/x.rtm"), FatalError);
}

} // namespace
} // namespace radcl::scene
