// Radiance_tmesh files as obj2mesh writes them: header, magic (319 + objsize), cube, uv
// limits, a triangle octree (skipped: radcl builds its own), the binary scene section of the
// materials, then patches of up to 256 vertices whose triangles refer to local vertices or,
// for "joiner" triangles, to vertices of other patches by (patch << 8 | index).
#include "radcl/scene/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "radcl/scene/object_type.h"
#include "radcl/scene/octree_reader.h"
#include "radcl/scene/portable_io.h"
#include "radcl/util/error.h"

namespace radcl::scene {

namespace {

constexpr int kMeshMagic = 319; // 1 * MAXOBJSIZ + 311
constexpr int kMaxObjSize = 8;
constexpr std::int64_t kMaxSet = 511;
constexpr double kFtiny = 1e-6;
constexpr double kInv2to32 = 1.0 / 4294967296.0;

enum : int { kMtV = 1, kMtN = 2, kMtUV = 4 };

struct Patch {
  int flags = 0;
  std::vector<std::array<std::uint32_t, 3>> xyz;
  std::vector<std::int32_t> norm;
  std::vector<std::array<std::uint32_t, 2>> uv;
  std::vector<std::array<std::uint8_t, 3>> tri;
  std::vector<std::int16_t> trimat; // one entry (sole material) or one per local triangle
  struct Join1 {
    std::int32_t v1j;
    std::uint8_t v2, v3;
    std::int16_t mat;
  };
  struct Join2 {
    std::int32_t v1j, v2j;
    std::uint8_t v3;
    std::int16_t mat;
  };
  std::vector<Join1> j1;
  std::vector<Join2> j2;
};

void skip_tree(ByteReader& in, int objsize) {
  const std::string file_msg = in.truncation_message();
  in.set_truncation_message("truncated mesh octree");
  std::size_t pending = 1; // iterative: a damaged file could nest arbitrarily deep
  while (pending > 0) {
    --pending;
    switch (in.get()) {
    case 0:
      break;
    case 1: {
      const std::int64_t n = in.getint(objsize);
      if (n < 0 || n > kMaxSet) in.fail("bad set in getfullnode");
      for (std::int64_t i = 0; i < n; ++i)
        in.getint(objsize);
      break;
    }
    case 2:
      pending += 8;
      break;
    case -1:
      in.truncated();
    default:
      in.fail("damaged mesh octree");
    }
  }
  in.set_truncation_message(file_msg);
}

std::uint8_t get_u8(ByteReader& in) {
  return in.byte();
}

Patch read_patch(ByteReader& in) {
  Patch p;
  p.flags = static_cast<int>(in.getint(1));
  if (!(p.flags & kMtV) || (p.flags & ~(kMtV | kMtN | kMtUV))) in.fail("bad patch flags");
  const std::int64_t nv = in.getint(2);
  if (nv <= 0 || nv > 256) in.fail("bad number of patch vertices");
  p.xyz.resize(static_cast<std::size_t>(nv));
  for (auto& v : p.xyz)
    for (auto& c : v)
      c = static_cast<std::uint32_t>(in.getint(4));
  if (p.flags & kMtN) {
    p.norm.resize(p.xyz.size());
    for (auto& n : p.norm)
      n = static_cast<std::int32_t>(in.getint(4));
  }
  if (p.flags & kMtUV) {
    p.uv.resize(p.xyz.size());
    for (auto& v : p.uv)
      for (auto& c : v)
        c = static_cast<std::uint32_t>(in.getint(4));
  }
  const std::int64_t nt = in.getint(2);
  if (nt < 0 || nt > 512) in.fail("bad number of local triangles");
  p.tri.resize(static_cast<std::size_t>(nt));
  for (auto& t : p.tri)
    for (auto& v : t)
      v = get_u8(in);
  // A count above 1 introduces per-triangle materials; otherwise one sole material follows.
  if (in.getint(2) > 1) {
    p.trimat.resize(p.tri.size());
    for (auto& m : p.trimat)
      m = static_cast<std::int16_t>(in.getint(2));
  } else {
    p.trimat.assign(1, static_cast<std::int16_t>(in.getint(2)));
  }
  const std::int64_t nj1 = in.getint(2);
  if (nj1 < 0 || nj1 > 256) in.fail("bad number of joiner triangles");
  p.j1.resize(static_cast<std::size_t>(nj1));
  for (auto& j : p.j1) {
    j.v1j = static_cast<std::int32_t>(in.getint(4));
    j.v2 = get_u8(in);
    j.v3 = get_u8(in);
    j.mat = static_cast<std::int16_t>(in.getint(2));
  }
  const std::int64_t nj2 = in.getint(2);
  if (nj2 < 0 || nj2 > 256) in.fail("bad number of double joiner triangles");
  p.j2.resize(static_cast<std::size_t>(nj2));
  for (auto& j : p.j2) {
    j.v1j = static_cast<std::int32_t>(in.getint(4));
    j.v2j = static_cast<std::int32_t>(in.getint(4));
    j.v3 = get_u8(in);
    j.mat = static_cast<std::int16_t>(in.getint(2));
  }
  return p;
}

// Radiance's 4-byte direction code (dircode.c): the two smaller components are stored as
// 13-bit magnitudes, flags say which axes they are; the largest is recomputed.
std::array<float, 3> decode_direction(std::int32_t dc) {
  constexpr double kScale = 11584.5; // ((1 << 13) - .5) * sqrt(2)
  const auto u = static_cast<std::uint32_t>(dc);
  const double d1 = ((u >> 5) & 0x1fff) / kScale;
  const double d2 = ((u >> 18) & 0x1fff) / kScale;
  const double der = std::sqrt(std::max(0.0, 1.0 - d1 * d1 - d2 * d2));
  const bool first_is_x = u & 010, second_is_z = u & 020;
  double v[3];
  const int a = first_is_x ? 0 : 1;                     // axis of d1
  const int b = second_is_z ? 2 : (first_is_x ? 1 : 0); // axis of d2
  const int c = 3 - a - b;                              // the recomputed one
  v[a] = d1;
  v[b] = d2;
  v[c] = der;
  for (int i = 0; i < 3; ++i)
    if (u & (1u << i)) v[i] = -v[i];
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// The patches' vertices, in patch order (patch i's first is base[i]): positions at the centres
// of their quantised cells in the mesh's cube, normals and uv where they have them.
void add_vertices(TriangleMesh& mesh, const std::vector<Patch>& patches,
                  const std::vector<std::uint32_t>& base, std::uint32_t nverts,
                  const std::array<double, 3>& cube_org, double cube_size, const double uv_lo[2],
                  const double uv_hi[2], bool any_n, bool any_uv) {
  const double vres = cube_size * kInv2to32;
  mesh.positions.reserve(nverts);
  mesh.vertex_flags.assign(nverts, 0);
  if (any_n) mesh.normals.assign(nverts, {0, 0, 0});
  if (any_uv) mesh.uvs.assign(nverts, {0, 0});
  for (std::size_t pi = 0; pi < patches.size(); ++pi) {
    const Patch& p = patches[pi];
    for (std::size_t v = 0; v < p.xyz.size(); ++v) {
      const std::uint32_t g = base[pi] + static_cast<std::uint32_t>(v);
      std::array<double, 3> pos;
      for (int k = 0; k < 3; ++k) // cell centre of the quantised coordinate
        pos[k] = cube_org[k] + (p.xyz[v][k] + 0.5) * vres;
      mesh.positions.push_back(pos);
      if (!p.norm.empty() && p.norm[v] != 0) { // code 0 means "no normal"
        mesh.normals[g] = decode_direction(p.norm[v]);
        mesh.vertex_flags[g] |= TriangleMesh::kHasNormal;
      }
      if (!p.uv.empty() && p.uv[v][0] != 0) { // u code 0 is out of range: "no uv"
        for (int k = 0; k < 2; ++k)
          mesh.uvs[g][k] =
              static_cast<float>(uv_lo[k] + (uv_hi[k] - uv_lo[k]) * (p.uv[v][k] + 0.5) * kInv2to32);
        mesh.vertex_flags[g] |= TriangleMesh::kHasUV;
      }
    }
  }
  if (!mesh.positions.empty()) {
    mesh.bbox_min = mesh.bbox_max = mesh.positions[0];
    for (const auto& p : mesh.positions)
      for (int k = 0; k < 3; ++k) {
        mesh.bbox_min[k] = std::min(mesh.bbox_min[k], p[k]);
        mesh.bbox_max[k] = std::max(mesh.bbox_max[k], p[k]);
      }
  }
}

} // namespace

TriangleMesh read_mesh(const std::string& path) {
  return read_mesh_data(read_input_bytes(path, "mesh file"), path);
}

TriangleMesh read_mesh_data(std::string bytes, const std::string& path) {
  ByteReader in(std::move(bytes), path, "truncated mesh file");
  TriangleMesh mesh;

  auto header = read_info_header(in);
  if (!header || (!header->format.empty() && header->format != "Radiance_tmesh"))
    in.fail("not a mesh file");

  const std::int64_t objsize = in.getint(2) - kMeshMagic;
  if (objsize <= 0 || objsize > kMaxObjSize) in.fail("incompatible mesh format");
  const int osz = static_cast<int>(objsize);

  std::array<double, 3> cube_org;
  for (auto& c : cube_org)
    c = std::atof(in.getstr().c_str());
  const double cube_size = std::atof(in.getstr().c_str());
  double uv_lo[2], uv_hi[2];
  for (int i = 0; i < 2; ++i) {
    uv_lo[i] = in.getflt();
    uv_hi[i] = in.getflt();
  }

  skip_tree(in, osz);

  if (!read_binary_scene(in, osz, mesh.objects))
    in.truncated(); // patches must follow the materials
  for (const Object& o : mesh.objects.objects) {
    if (!is_modifier(o.type))
      in.fail("non-modifier in mesh (" + std::string(type_name(o.type)) + " \"" + o.name + "\")");
    mesh.materials.push_back(o.name);
  }
  const auto nmats = static_cast<std::int64_t>(mesh.materials.size());

  const std::int64_t npatches = in.getint(4);
  if (npatches < 0 || npatches > (std::int64_t{1} << 22)) in.fail("bad number of mesh patches");
  std::vector<Patch> patches;
  for (std::int64_t i = 0; i < npatches; ++i)
    patches.push_back(read_patch(in));

  // The checks of Radiance's checkmesh().
  if (cube_size <= kFtiny) in.fail("illegal octree bounds in mesh");
  const bool no_uv_bounds = uv_hi[0] - uv_lo[0] <= kFtiny || uv_hi[1] - uv_lo[1] <= kFtiny;
  if (patches.empty()) warning("(" + path + "): no patches in mesh");

  std::vector<std::uint32_t> base(patches.size());
  std::uint32_t nverts = 0;
  bool any_n = false, any_uv = false;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    base[i] = nverts;
    nverts += static_cast<std::uint32_t>(patches[i].xyz.size());
    any_n |= !patches[i].norm.empty();
    any_uv |= !patches[i].uv.empty();
    if (no_uv_bounds && !patches[i].uv.empty()) in.fail("unreferenced uv coordinates");
  }

  // Vertices, in patch order.
  add_vertices(mesh, patches, base, nverts, cube_org, cube_size, uv_lo, uv_hi, any_n, any_uv);

  // Triangles in Radiance's triangle-ID order: per patch local, single-, double-joiners.
  auto material = [&](std::int64_t m, const char* what) -> std::int32_t {
    if (nmats == 0) return kVoid; // without stored materials every face takes the mesh's modifier
    if (m < 0 || m >= nmats) in.fail(std::string("bad ") + what + " triangle material");
    return static_cast<std::int32_t>(m);
  };
  auto joiner = [&](std::int32_t vid, const char* what) -> std::uint32_t {
    const std::int64_t pn = vid >> 8;
    const std::uint32_t local = static_cast<std::uint32_t>(vid) & 0xff;
    if (vid < 0 || pn >= static_cast<std::int64_t>(patches.size()) ||
        local >= patches[static_cast<std::size_t>(pn)].xyz.size())
      in.fail(std::string("bad ") + what + " triangle joiner");
    return base[static_cast<std::size_t>(pn)] + local;
  };
  for (std::size_t pi = 0; pi < patches.size(); ++pi) {
    const Patch& p = patches[pi];
    const auto nv = p.xyz.size();
    for (std::size_t t = 0; t < p.tri.size(); ++t) {
      const auto& tr = p.tri[t];
      if (tr[0] >= nv || tr[1] >= nv || tr[2] >= nv) in.fail("bad local triangle index");
      mesh.triangles.push_back({base[pi] + tr[0], base[pi] + tr[1], base[pi] + tr[2]});
      mesh.triangle_material.push_back(
          material(p.trimat.size() == 1 ? p.trimat[0] : p.trimat[t], "local"));
    }
    for (const auto& j : p.j1) {
      const std::uint32_t v1 = joiner(j.v1j, "j1");
      if (j.v2 >= nv || j.v3 >= nv) in.fail("bad j1 triangle local index");
      mesh.triangles.push_back({v1, base[pi] + j.v2, base[pi] + j.v3});
      mesh.triangle_material.push_back(material(j.mat, "j1"));
    }
    for (const auto& j : p.j2) {
      const std::uint32_t v1 = joiner(j.v1j, "j2");
      const std::uint32_t v2 = joiner(j.v2j, "j2");
      if (j.v3 >= nv) in.fail("bad j2 triangle local index");
      mesh.triangles.push_back({v1, v2, base[pi] + j.v3});
      mesh.triangle_material.push_back(material(j.mat, "j2"));
    }
  }
  return mesh;
}

} // namespace radcl::scene
