// Radiance_tmesh output following obj2mesh's steps: accept triangles (cvtri), bound them
// (cvmeshbounds), insert them into an octree (addface/add2full, then combine), turn the
// octree's triangles into patch vertices and triangle IDs while walking it (cvmeshoct),
// and write header, cube, uv limits, tree, materials and patches. Every rule that decides a
// byte (walk order, vertex sharing, patch and joiner placement, rounding) matters: the file
// then equals obj2mesh's for the same triangles, and Radiance ray-traces its octree.
#include "radcl/scene/mesh_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unordered_map>

#include "radcl/scene/object_type.h"
#include "radcl/scene/portable_io.h"
#include "radcl/util/error.h"
#include "tmesh_geometry.h"

namespace radcl::scene {
namespace {

using namespace tmesh;
constexpr double kOmargin = 10 * kFtiny; // margin around the cube
constexpr double kCosTol = 0.999995;     // obj2mesh's flatness tolerance
constexpr double k2to32 = 4294967296.0;
constexpr std::size_t kMaxSet = 511;
constexpr int kMeshMagic = 319, kObjSize = 4;
enum : int { kMtV = 1, kMtN = 2, kMtUV = 4 };

constexpr std::int32_t kEmpty = -1;
struct Node {
  bool tree = false;
  std::array<std::int32_t, 8> kid{};
  std::vector<std::int32_t> set; // ascending, as Radiance keeps object sets
};

struct Patch {
  std::vector<std::array<std::uint32_t, 3>> xyz;
  std::vector<std::int32_t> norm;
  std::vector<std::array<std::uint32_t, 2>> uv;
  bool any_norm = false, any_uv = false;
  std::vector<std::array<std::uint8_t, 3>> tri;
  std::int16_t solemat = 0;
  std::vector<std::int16_t> trimat; // empty while every local triangle has solemat
  struct J1 {
    std::int32_t v1j;
    std::uint8_t v2, v3;
    std::int16_t mat;
  };
  struct J2 {
    std::int32_t v1j, v2j;
    std::uint8_t v3;
    std::int16_t mat;
  };
  std::vector<J1> j1;
  std::vector<J2> j2;
  std::vector<std::uint32_t> src_tri, src_j1, src_j2; // input triangle of each entry
};

struct VertexKey {
  int flags;
  std::array<std::uint32_t, 3> xyz;
  std::int32_t norm;
  std::array<std::uint32_t, 2> uv;
  bool operator==(const VertexKey&) const = default;
};
struct VertexHash {
  std::size_t operator()(const VertexKey& k) const {
    std::uint64_t h = k.flags;
    for (std::uint32_t w :
         {k.xyz[0], k.xyz[1], k.xyz[2], static_cast<std::uint32_t>(k.norm), k.uv[0], k.uv[1]})
      h = (h ^ w) * 0x100000001b3ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

class Writer {
public:
  Writer(const TriangleMesh& m, const MeshWriteOptions& o) : mesh_(m), opt_(o) {}

  MeshWriteInfo run(std::string& out) {
    accept_triangles();
    set_bounds();
    build_octree();
    root_ = combine(root_);
    root_ = convert(root_);
    check_materials();
    write(out);
    for (const Patch& p : patches_)
      for (const auto* src : {&p.src_tri, &p.src_j1, &p.src_j2})
        info_.source_triangle.insert(info_.source_triangle.end(), src->begin(), src->end());
    info_.patches = patches_.size();
    info_.cube_origin = org_;
    info_.cube_size = size_;
    return std::move(info_);
  }

private:
  const V3& pos(const Tri& t, int k) const { return mesh_.positions.at(t.vertex[k]); }
  bool has(std::uint32_t v, std::uint8_t flag, bool present) const {
    return present && v < mesh_.vertex_flags.size() && (mesh_.vertex_flags[v] & flag);
  }

  // cvtri: flags per triangle, flat triangles lose their normals, reversed ones turn over.
  void accept_triangles() {
    for (std::uint32_t ti = 0; ti < mesh_.triangles.size(); ++ti) {
      Tri t{};
      t.source = ti;
      t.vertex = mesh_.triangles[ti];
      for (std::uint32_t v : t.vertex)
        if (v >= mesh_.positions.size()) throw FatalError("mesh triangle vertex out of range");
      t.material = ti < mesh_.triangle_material.size() ? mesh_.triangle_material[ti] : kVoid;
      bool with_n = true, with_uv = true;
      for (int k = 0; k < 3; ++k) {
        with_n &= has(t.vertex[k], TriangleMesh::kHasNormal, !mesh_.normals.empty());
        with_uv &= has(t.vertex[k], TriangleMesh::kHasUV, !mesh_.uvs.empty());
        if (with_n) {
          const auto& n = mesh_.normals[t.vertex[k]];
          t.normal[k] = {n[0], n[1], n[2]};
          with_n = normalize(t.normal[k]);
        }
      }
      V3 fn = cross(sub(pos(t, 1), pos(t, 0)), sub(pos(t, 2), pos(t, 1)));
      if (!normalize(fn)) {
        ++info_.skipped_degenerate;
        continue;
      }
      t.flags = kMtV;
      if (with_n && opt_.obj2mesh_normals) {
        const double d[3] = {dot(fn, t.normal[0]), dot(fn, t.normal[1]), dot(fn, t.normal[2])};
        const bool reversed = d[0] < 0 && d[1] < 0 && d[2] < 0;
        const double tol = reversed ? -kCosTol : kCosTol;
        bool bent = false;
        for (double di : d)
          bent |= reversed ? di > tol : di < tol;
        if (bent) t.flags |= kMtN;
        if (reversed) {
          std::swap(t.vertex[0], t.vertex[2]);
          std::swap(t.normal[0], t.normal[2]);
          for (double& c : fn)
            c = -c;
        }
      } else if (with_n) {
        t.flags |= kMtN;
      }
      if (with_uv) t.flags |= kMtUV;
      t.unit_normal = fn;
      t.offset = dot(fn, pos(t, 0));
      tris_.push_back(t);
    }
    if (tris_.empty()) throw FatalError("no polygons in mesh");
  }

  // cvmeshbounds: a cube centred on the box grown by OMARGIN; uv limits grown so that code
  // 0 stays out of range ("no uv").
  void set_bounds() {
    V3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    double uvlo[2] = {HUGE_VAL, HUGE_VAL}, uvhi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (const Tri& t : tris_)
      for (int k = 0; k < 3; ++k) {
        for (int j = 0; j < 3; ++j) {
          lo[j] = std::min(lo[j], pos(t, k)[j]);
          hi[j] = std::max(hi[j], pos(t, k)[j]);
        }
        if (t.flags & kMtUV)
          for (int j = 0; j < 2; ++j) {
            uvlo[j] = std::min(uvlo[j], double{mesh_.uvs[t.vertex[k]][j]});
            uvhi[j] = std::max(uvhi[j], double{mesh_.uvs[t.vertex[k]][j]});
          }
      }
    for (int j = 0; j < 3; ++j) {
      lo[j] -= kOmargin;
      hi[j] += kOmargin;
      size_ = std::max(size_, hi[j] - lo[j]);
    }
    for (int j = 0; j < 3; ++j)
      org_[j] = (hi[j] + lo[j] - size_) * .5;
    if (uvlo[0] <= uvhi[0])
      for (int j = 0; j < 2; ++j) {
        const double marg = (2. / 65536) * (uvhi[j] - uvlo[j]) + kFtiny;
        uvlim_[0][j] = uvlo[j] - marg;
        uvlim_[1][j] = uvhi[j] + marg;
      }
  }

  // ---- octree (obj2mesh's addface/add2full) over indices into tris_

  std::array<V3, 3> corners(const Tri& t) const { return {pos(t, 0), pos(t, 1), pos(t, 2)}; }

  void build_octree() {
    min_size_ = size_ / opt_.resolution - kFtiny;
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(tris_.size()); ++i)
      root_ = add(root_, org_, size_, i);
  }

  static V3 kid_origin(const V3& org, double half, int i) {
    V3 o = org;
    for (int j = 0; j < 3; ++j)
      if (i & (1 << j)) o[j] += half;
    return o;
  }

  std::int32_t add(std::int32_t node, const V3& org, double size, std::int32_t obj) {
    const Tri& t = tris_[static_cast<std::size_t>(obj)];
    if (!touches_cube(corners(t), t, org, size)) return node;
    if (node == kEmpty) {
      nodes_.push_back({false, {}, {obj}});
      return static_cast<std::int32_t>(nodes_.size() - 1);
    }
    const double half = size * 0.5;
    if (nodes_[node].tree) {
      for (int i = 0; i < 8; ++i) {
        const std::int32_t k = add(nodes_[node].kid[i], kid_origin(org, half, i), half, obj);
        nodes_[node].kid[i] = k;
      }
      return node;
    }
    std::vector<std::int32_t>& set = nodes_[node].set;
    if (set.size() < static_cast<std::size_t>(opt_.objlim) ||
        half < (set.size() < kMaxSet ? min_size_ : min_size_ / 256.0)) {
      if (set.size() >= kMaxSet) throw FatalError("set overflow in mesh octree");
      set.insert(std::upper_bound(set.begin(), set.end(), obj), obj);
      return node;
    }
    // Split: each child gets the old members first, then the new triangle.
    const std::vector<std::int32_t> old = std::move(set);
    nodes_[node].tree = true;
    nodes_[node].set.clear();
    for (int i = 0; i < 8; ++i) {
      const V3 ko = kid_origin(org, half, i);
      std::int32_t k = kEmpty;
      for (std::int32_t o : old)
        k = add(k, ko, half, o);
      k = add(k, ko, half, obj);
      nodes_[node].kid[i] = k;
    }
    return node;
  }

  bool same_leaf(std::int32_t a, std::int32_t b) const {
    if (a == kEmpty || b == kEmpty) return a == b;
    return !nodes_[a].tree && !nodes_[b].tree && nodes_[a].set == nodes_[b].set;
  }

  // A tree whose eight children are equal leaves becomes that leaf.
  std::int32_t combine(std::int32_t node) {
    if (node == kEmpty || !nodes_[node].tree) return node;
    bool same = true;
    for (int i = 0; i < 8; ++i) {
      const std::int32_t k = combine(nodes_[node].kid[i]);
      nodes_[node].kid[i] = k;
      same &= same_leaf(k, nodes_[node].kid[0]) && (k == kEmpty || !nodes_[k].tree);
    }
    return same ? nodes_[node].kid[0] : node;
  }

  // ---- cvmeshoct: children 7..0, set members last to first, each triangle added once

  std::int32_t convert(std::int32_t node) {
    if (node == kEmpty) return kEmpty;
    if (nodes_[node].tree) {
      for (int i = 8; i--;) {
        const std::int32_t k = convert(nodes_[node].kid[i]);
        nodes_[node].kid[i] = k;
      }
      return node;
    }
    std::vector<std::int32_t> ids;
    const std::vector<std::int32_t>& set = nodes_[node].set;
    for (auto it = set.rbegin(); it != set.rend(); ++it)
      ids.push_back(triangle_id(*it));
    std::sort(ids.begin(), ids.end());
    std::int32_t leaf = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back({false, {}, std::move(ids)});
    ++info_.octree_leaves;
    return leaf;
  }

  // addmeshvert: the vertex's patch ID (patch << 8 | index), shared by equal encodings.
  std::int32_t vertex_id(const Tri& t, int k) {
    VertexKey key{t.flags, {}, 0, {0, 0}};
    const V3& p = pos(t, k);
    for (int j = 0; j < 3; ++j) {
      if (p[j] < org_[j] || p[j] >= org_[j] + size_)
        throw FatalError("mesh vertex outside its cube");
      key.xyz[j] = static_cast<std::uint32_t>(k2to32 * (p[j] - org_[j]) / size_);
    }
    if (t.flags & kMtN) key.norm = encode_direction(t.normal[k]);
    if (t.flags & kMtUV)
      for (int j = 0; j < 2; ++j) {
        const double u = mesh_.uvs[t.vertex[k]][j];
        key.uv[j] =
            static_cast<std::uint32_t>(k2to32 * (u - uvlim_[0][j]) / (uvlim_[1][j] - uvlim_[0][j]));
      }
    auto [it, fresh] = vertices_.try_emplace(key, 0);
    if (!fresh) return it->second;
    if (patches_.empty() || patches_.back().xyz.size() >= 256) {
      if (patches_.size() >= (std::size_t{1} << 22)) throw FatalError("too many mesh patches");
      patches_.emplace_back();
    }
    Patch& pp = patches_.back();
    pp.xyz.push_back(key.xyz);
    pp.norm.push_back(key.norm);
    pp.uv.push_back(key.uv);
    pp.any_norm |= (t.flags & kMtN) != 0;
    pp.any_uv |= (t.flags & kMtUV) != 0;
    ++info_.vertices;
    it->second = static_cast<std::int32_t>((patches_.size() - 1) << 8 | (pp.xyz.size() - 1));
    return it->second;
  }

  // addmeshtri: local to one patch while it has room, else a joiner kept by a patch that
  // holds two of the vertices, else a double joiner in the least loaded of the three.
  std::int32_t triangle_id(std::int32_t obj) {
    if (tri_ids_.empty()) tri_ids_.assign(tris_.size(), {0, false});
    auto& memo = tri_ids_[static_cast<std::size_t>(obj)];
    if (memo.second) return memo.first;
    const Tri& t = tris_[static_cast<std::size_t>(obj)];
    std::int32_t vid[3];
    int pn[3];
    for (int k = 0; k < 3; ++k) {
      vid[k] = vertex_id(t, k);
      pn[k] = vid[k] >> 8;
    }
    std::int16_t mo = -1;
    if (t.material != kVoid) {
      if (t.material < 0 || t.material > 32767) throw FatalError("bad mesh material index");
      mo = static_cast<std::int16_t>(t.material);
      nmats_ = std::max(nmats_, t.material + 1);
    }
    memo = {place(t.source, vid, pn, mo), true};
    return memo.first;
  }

  std::int32_t place(std::uint32_t src, std::int32_t vid[3], int pn[3], std::int16_t mo) {
    if (pn[0] == pn[1] && pn[1] == pn[2]) {
      Patch& pp = patches_[pn[0]];
      if (pp.tri.size() < 512) {
        pp.tri.push_back({static_cast<std::uint8_t>(vid[0] & 0xff),
                          static_cast<std::uint8_t>(vid[1] & 0xff),
                          static_cast<std::uint8_t>(vid[2] & 0xff)});
        if (pp.tri.size() == 1)
          pp.solemat = mo;
        else if (pp.trimat.empty() && mo != pp.solemat)
          pp.trimat.assign(pp.tri.size() - 1, pp.solemat);
        if (!pp.trimat.empty()) pp.trimat.push_back(mo);
        pp.src_tri.push_back(src);
        return pn[0] << 10 | static_cast<std::int32_t>(pp.tri.size() - 1);
      }
    } else if (pn[0] == pn[1]) { // rotate so that the odd vertex comes first
      std::rotate(vid, vid + 2, vid + 3);
      std::rotate(pn, pn + 2, pn + 3);
    } else if (pn[0] == pn[2]) {
      std::rotate(vid, vid + 1, vid + 3);
      std::rotate(pn, pn + 1, pn + 3);
    }
    if (pn[1] == pn[2] && patches_[pn[1]].j1.size() < 256) {
      Patch& pp = patches_[pn[1]];
      pp.j1.push_back({vid[0], static_cast<std::uint8_t>(vid[1] & 0xff),
                       static_cast<std::uint8_t>(vid[2] & 0xff), mo});
      pp.src_j1.push_back(src);
      return pn[1] << 10 | 0x200 | static_cast<std::int32_t>(pp.j1.size() - 1);
    }
    int i = 0;
    for (int k = 1; k < 3; ++k)
      if (patches_[pn[k]].j2.size() < patches_[pn[i]].j2.size()) i = k;
    Patch& pp = patches_[pn[i]];
    if (pp.j2.size() >= 256) throw FatalError("too many patch triangles in mesh");
    // The kept vertex is local (v3); the other two keep their cyclic order as v1j, v2j.
    const std::int32_t a = vid[(i + 1) % 3], b = vid[(i + 2) % 3];
    pp.j2.push_back({a, b, static_cast<std::uint8_t>(vid[i] & 0xff), mo});
    pp.src_j2.push_back(src);
    return pn[i] << 10 | 0x300 | static_cast<std::int32_t>(pp.j2.size() - 1);
  }

  // Radiance rejects a mesh whose materials are mixed with void faces, or not modifiers.
  void check_materials() {
    if (nmats_ == 0) return;
    if (static_cast<std::size_t>(nmats_) > mesh_.objects.objects.size())
      throw FatalError("mesh material " + std::to_string(nmats_ - 1) + " has no definition");
    for (std::int32_t i = 0; i < nmats_; ++i) {
      const Object& o = mesh_.objects.objects[static_cast<std::size_t>(i)];
      if (!is_modifier(o.type))
        throw FatalError("non-modifier in mesh (" + std::string(type_name(o.type)) + " \"" +
                         o.name + "\")");
    }
    auto is_void = [](std::int16_t m) { return m < 0; };
    for (const Patch& p : patches_) {
      bool bad = !p.tri.empty() &&
                 (p.trimat.empty() ? is_void(p.solemat)
                                   : std::any_of(p.trimat.begin(), p.trimat.end(), is_void));
      for (const auto& j : p.j1)
        bad |= is_void(j.mat);
      for (const auto& j : p.j2)
        bad |= is_void(j.mat);
      if (bad) throw FatalError("mesh mixes void and non-void triangle materials");
    }
  }

  // ---- output (writemesh)

  void write_tree(std::string& out, std::int32_t node) const {
    if (node == kEmpty) {
      out.push_back(0);
    } else if (nodes_[node].tree) {
      out.push_back(2);
      for (std::int32_t k : nodes_[node].kid)
        write_tree(out, k);
    } else {
      out.push_back(1);
      put_int(out, static_cast<std::int64_t>(nodes_[node].set.size()), kObjSize);
      for (std::int32_t id : nodes_[node].set)
        put_int(out, id, kObjSize);
    }
  }

  void write_materials(std::string& out) const {
    for (int t = 0; t < RC_OBJ_COUNT; ++t)
      put_str(out, type_name(static_cast<ObjectType>(t)));
    put_str(out, "");
    for (std::int32_t i = 0; i < nmats_; ++i) {
      const Object& o = mesh_.objects.objects[static_cast<std::size_t>(i)];
      put_int(out, static_cast<int>(o.type), 1);
      put_int(out, o.modifier, kObjSize);
      put_str(out, o.name);
      put_int(out, static_cast<std::int64_t>(o.sargs.size()), 2);
      for (const auto& s : o.sargs)
        put_str(out, s);
      put_int(out, static_cast<std::int64_t>(o.fargs.size()), 2);
      for (double f : o.fargs)
        put_flt(out, f);
    }
    put_int(out, -1, 1);
  }

  static void write_patch(std::string& out, const Patch& p) {
    put_int(out, kMtV | (p.any_norm ? kMtN : 0) | (p.any_uv ? kMtUV : 0), 1);
    put_int(out, static_cast<std::int64_t>(p.xyz.size()), 2);
    for (const auto& v : p.xyz)
      for (std::uint32_t c : v)
        put_int(out, c, 4);
    if (p.any_norm)
      for (std::int32_t n : p.norm)
        put_int(out, n, 4);
    if (p.any_uv)
      for (const auto& uv : p.uv)
        for (std::uint32_t c : uv)
          put_int(out, c, 4);
    put_int(out, static_cast<std::int64_t>(p.tri.size()), 2);
    for (const auto& t : p.tri)
      out.append(reinterpret_cast<const char*>(t.data()), 3);
    if (p.trimat.empty()) {
      put_int(out, 1, 2);
      put_int(out, p.solemat, 2);
    } else {
      put_int(out, static_cast<std::int64_t>(p.trimat.size()), 2);
      for (std::int16_t m : p.trimat)
        put_int(out, m, 2);
    }
    put_int(out, static_cast<std::int64_t>(p.j1.size()), 2);
    for (const auto& j : p.j1) {
      put_int(out, j.v1j, 4);
      put_int(out, j.v2, 1);
      put_int(out, j.v3, 1);
      put_int(out, j.mat, 2);
    }
    put_int(out, static_cast<std::int64_t>(p.j2.size()), 2);
    for (const auto& j : p.j2) {
      put_int(out, j.v1j, 4);
      put_int(out, j.v2j, 4);
      put_int(out, j.v3, 1);
      put_int(out, j.mat, 2);
    }
  }

  void write(std::string& out) const {
    out += "#?RADIANCE\n";
    for (const auto& line : opt_.header_lines)
      out += line + "\n";
    out += "FORMAT=Radiance_tmesh\n\n";
    put_int(out, kMeshMagic + kObjSize, 2);
    char buf[64];
    for (double c : {org_[0], org_[1], org_[2], size_}) {
      std::snprintf(buf, sizeof buf, "%.12g", c);
      put_str(out, buf);
    }
    for (int j = 0; j < 2; ++j) {
      put_flt(out, uvlim_[0][j]);
      put_flt(out, uvlim_[1][j]);
    }
    write_tree(out, root_);
    write_materials(out);
    put_int(out, static_cast<std::int64_t>(patches_.size()), 4);
    for (const Patch& p : patches_)
      write_patch(out, p);
  }

  const TriangleMesh& mesh_;
  const MeshWriteOptions& opt_;
  MeshWriteInfo info_;
  std::vector<Tri> tris_;
  V3 org_{0, 0, 0};
  double size_ = 0, min_size_ = 0;
  double uvlim_[2][2] = {{0, 0}, {0, 0}};
  std::vector<Node> nodes_;
  std::int32_t root_ = kEmpty;
  std::unordered_map<VertexKey, std::int32_t, VertexHash> vertices_;
  std::vector<std::pair<std::int32_t, bool>> tri_ids_; // memo of triangle_id()
  std::vector<Patch> patches_;
  std::int32_t nmats_ = 0;
};

} // namespace

MeshWriteInfo encode_mesh(const TriangleMesh& mesh, std::string& out,
                          const MeshWriteOptions& options) {
  if (options.objlim < 1 || options.resolution < 1) throw FatalError("bad mesh octree limits");
  return Writer(mesh, options).run(out);
}

MeshWriteInfo write_mesh(const TriangleMesh& mesh, const std::string& path,
                         const MeshWriteOptions& options) {
  std::string bytes;
  MeshWriteInfo info = encode_mesh(mesh, bytes, options);
  const std::string tmp = path + ".part";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw FatalError("cannot open mesh file \"" + path + "\" for writing");
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!f.flush()) throw FatalError("write error in mesh file \"" + path + "\"");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw FatalError("cannot write mesh file \"" + path + "\"");
  }
  return info;
}

} // namespace radcl::scene
