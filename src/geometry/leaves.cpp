// From Radiance objects to leaf surfaces: polygons (Radiance's plane, triangulated) and
// quadrics, skipping surfaces that no material shades and counting what was kept.
#include <cmath>
#include <string>

#include "impl.h"
#include "radcl/util/error.h"

namespace radcl::geometry {
namespace {

constexpr double kTiny = 1e-6; // Radiance's FTINY

std::string about(const scene::Object& o) {
  return std::string(" for ") + std::string(scene::type_name(o.type)) + " \"" + o.name + "\"";
}

void add_polygon(const scene::Object& o, std::int32_t index, LeafSet& out, SurfaceCounts& counts) {
  const auto& f = o.fargs;
  if (f.size() < 9 || f.size() % 3 != 0) throw FatalError("bad # arguments" + about(o));
  std::vector<Vec3> v(f.size() / 3);
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
  // A closing vertex repeating the first is dropped, as Radiance does.
  if (v.size() > 3) {
    const Vec3 d = sub(v.front(), v.back());
    if (dot(d, d) <= kTiny * kTiny) v.pop_back();
  }
  const PolygonPlane pl = polygon_plane(v);
  if (pl.area == 0) {
    warning("zero area" + about(o));
    ++counts.skipped_degenerate;
    return;
  }
  // Radiance intersects the mean plane: put the vertices on it so triangles and the exact
  // plane distance agree.
  double worst = 0;
  for (auto& p : v) {
    const double off = dot(pl.normal, p) - pl.offset;
    worst = std::max(worst, std::abs(off));
    p = madd(p, pl.normal, -off);
  }
  if (v.size() > 3 && worst > 1e-5 * std::max(1.0, std::abs(pl.offset)))
    warning("non-planar vertex" + about(o));
  const std::vector<Tri> tris = triangulate_polygon(v, pl.normal);
  if (tris.empty()) {
    warning("zero area" + about(o));
    ++counts.skipped_degenerate;
    return;
  }
  PolygonRecord rec;
  rec.object = index;
  rec.normal = pl.normal;
  rec.offset = pl.offset;
  rec.first_triangle = static_cast<std::uint32_t>(out.triangles.size());
  const auto base = static_cast<std::uint32_t>(out.vertices.size());
  std::array<Vec3, 2> b{v[0], v[0]};
  for (const auto& p : v) {
    out.vertices.push_back(p);
    for (int k = 0; k < 3; ++k)
      b[0][k] = std::min(b[0][k], p[k]), b[1][k] = std::max(b[1][k], p[k]);
  }
  for (const auto& t : tris) {
    out.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    out.triangle_polygon.push_back(static_cast<std::uint32_t>(out.polygons.size()));
  }
  out.polygons.push_back(rec);
  out.grow(b);
  ++counts.polygons;
  counts.triangles += tris.size();
}

void count_quadric(scene::ObjectType t, SurfaceCounts& c) {
  switch (t) {
  case RC_OBJ_SPHERE:
    ++c.spheres;
    break;
  case RC_OBJ_BUBBLE:
    ++c.bubbles;
    break;
  case RC_OBJ_CONE:
    ++c.cones;
    break;
  case RC_OBJ_CUP:
    ++c.cups;
    break;
  case RC_OBJ_CYLINDER:
    ++c.cylinders;
    break;
  case RC_OBJ_TUBE:
    ++c.tubes;
    break;
  case RC_OBJ_RING:
    ++c.rings;
    break;
  default:
    break;
  }
}

} // namespace

void LeafSet::grow(const std::array<Vec3, 2>& b) {
  if (empty) {
    bounds = b;
    empty = false;
    return;
  }
  for (int k = 0; k < 3; ++k) {
    bounds[0][k] = std::min(bounds[0][k], b[0][k]);
    bounds[1][k] = std::max(bounds[1][k], b[1][k]);
  }
}

bool has_material(const scene::SceneDescription& desc, std::int32_t i) {
  std::int32_t m = desc.objects[i].modifier;
  for (std::size_t guard = 0; m != scene::kVoid; ++guard) {
    if (m < 0 || static_cast<std::size_t>(m) >= desc.objects.size() || guard > desc.objects.size())
      return true; // malformed chain: let the shading code report it
    const scene::ObjectType t = desc.objects[m].type;
    // Aliases and mixtures resolve to other modifiers at shading time; assume they shade.
    if (scene::is_material(t) || t == RC_OBJ_ALIAS || scene::is_mixture(t)) return true;
    m = desc.objects[m].modifier;
  }
  return false;
}

LeafSet collect_leaves(const scene::SceneDescription& desc, bool all, SurfaceCounts& counts) {
  LeafSet out;
  for (std::size_t i = 0; i < desc.objects.size(); ++i) {
    const scene::Object& o = desc.objects[i];
    const auto index = static_cast<std::int32_t>(i);
    switch (o.type) {
    case RC_OBJ_POLYGON:
    case RC_OBJ_SPHERE:
    case RC_OBJ_BUBBLE:
    case RC_OBJ_CONE:
    case RC_OBJ_CUP:
    case RC_OBJ_CYLINDER:
    case RC_OBJ_TUBE:
    case RC_OBJ_RING:
      break;
    default:
      continue;
    }
    if (!all && !has_material(desc, index)) {
      ++counts.skipped_void;
      continue;
    }
    if (o.type == RC_OBJ_POLYGON) {
      add_polygon(o, index, out, counts);
      continue;
    }
    auto s = make_analytic(o, index);
    if (!s) {
      ++counts.skipped_degenerate;
      continue;
    }
    count_quadric(s->type, counts);
    out.grow(analytic_bounds(*s));
    out.analytic.push_back(*s);
  }
  return out;
}

} // namespace radcl::geometry
