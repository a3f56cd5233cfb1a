// Builds the Embree scene: leaf surfaces of the main scene in the top-level scene, every
// instanced octree and mesh as a prototype placed by an Embree instance. Nested instances are
// flattened (this Embree supports one instance level) by composing their transforms.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

#include "impl.h"
#include "radcl/scene/transform.h"
#include "radcl/util/error.h"

namespace radcl::geometry {
namespace {

constexpr int kMaxNesting = 64;

void embree_error(void* user, RTCError code, const char* str) {
  auto* msg = static_cast<std::string*>(user);
  if (msg->empty())
    *msg = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (str ? str : "");
}

// Packets of 8 rays where the CPU traverses them natively, else 16 or 4 (Embree's packet
// kernels share one node visit among the packet's rays: radcl's queries 1.1-1.3x the single-ray
// rate on office_clear's -aa 0 rays; 8 as fast as 16 there, without 512-bit registers);
// RADCL_RAY_PACKET=1, 4, 8 or 16 asks for one (1: single rays), taken if supported.
int native_packet(RTCDevice device) {
  const auto native = [device](int w) {
    if (w == 1) return true;
    const RTCDeviceProperty p = w == 4   ? RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED
                                : w == 8 ? RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED
                                         : RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED;
    return rtcGetDeviceProperty(device, p) != 0;
  };
  if (const char* e = std::getenv("RADCL_RAY_PACKET")) {
    const int w = std::atoi(e);
    if ((w == 1 || w == 4 || w == 8 || w == 16) && native(w)) return w;
  }
  for (int w : {8, 16, 4})
    if (native(w)) return w;
  return 1;
}

Affine affine_from(const scene::Transform& tr) {
  Affine a;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      a.l[i][k] = tr.m[i][k];
  a.t = {tr.m[3][0], tr.m[3][1], tr.m[3][2]};
  return a;
}

// LoadedScene keys files by the path found on RAYPATH; a primitive may name it relatively.
template <class Map>
const typename Map::mapped_type* find_file(const Map& m, const std::string& name) {
  if (auto it = m.find(name); it != m.end()) return &it->second;
  for (const auto& [key, value] : m)
    if (key.size() > name.size() && key.compare(key.size() - name.size(), name.size(), name) == 0 &&
        key[key.size() - name.size() - 1] == '/')
      return &value;
  return nullptr;
}

class Builder {
public:
  Builder(const scene::LoadedScene& scene, SceneGeometry::Impl& impl) : in_(scene), g_(impl) {}

  void build() {
    g_.prototypes.emplace_back(); // the main scene, built once the world centre is known
    Placement main;
    main.scene = &in_.main;
    g_.placements.push_back(main);
    g_.records.emplace_back();
    collect_sources();
    LeafSet leaves = collect_leaves(in_.main, false, g_.counts);
    place(in_.main, Affine{}, 1, false, -1, nullptr, -1, 0);
    world_bounds(leaves);
    g_.top = rtcNewScene(g_.device);
    rtcSetSceneFlags(g_.top, RTC_SCENE_FLAG_ROBUST);
    build_leaf_prototype(g_.device, g_.top, std::move(leaves), g_.centre, g_.prototypes[0]);
    g_.records[0].from_world = Affine::translation(scale(g_.centre, -1));
    attach_instances();
    rtcCommitScene(g_.top);
    g_.check_embree();
  }

private:
  void collect_sources() {
    const auto& objs = in_.main.objects;
    for (std::size_t i = 0; i < objs.size(); ++i) {
      const scene::Object& o = objs[i];
      if (o.type != RC_OBJ_SOURCE) continue;
      if (o.fargs.size() != 4) throw FatalError("bad # arguments for source \"" + o.name + "\"");
      if (!has_material(in_.main, static_cast<std::int32_t>(i))) {
        ++g_.counts.skipped_void;
        continue;
      }
      DistantSource s;
      s.object = static_cast<std::int32_t>(i);
      s.direction = normalized(Vec3{o.fargs[0], o.fargs[1], o.fargs[2]});
      if (length(s.direction) == 0)
        throw FatalError("zero direction for source \"" + o.name + "\"");
      s.angle = o.fargs[3];
      s.solid_angle = 2 * std::numbers::pi * (1 - std::cos(s.angle * (std::numbers::pi / 360)));
      g_.sources.push_back(s);
      ++g_.counts.sources;
    }
  }

  // Instances and meshes of `desc`, placed by `to_world`. `all`: an enclosing instance's
  // modifier shades everything, so surfaces without materials show too.
  void place(const scene::SceneDescription& desc, const Affine& to_world, double sca, bool all,
             std::int32_t outer, const scene::SceneDescription* shade_scene,
             std::int32_t shade_object, int depth) {
    if (depth > kMaxNesting) throw FatalError("instances nested too deeply");
    for (std::size_t i = 0; i < desc.objects.size(); ++i) {
      const scene::Object& o = desc.objects[i];
      if (o.type != RC_OBJ_INSTANCE && o.type != RC_OBJ_MESH) continue;
      const std::string what = std::string(scene::type_name(o.type)) + " \"" + o.name + "\"";
      if (o.sargs.empty() || !o.fargs.empty()) throw FatalError("bad # arguments for " + what);
      const scene::Transform tr = scene::parse_transform(o.sargs, 1);
      const Affine child = affine_from(tr).then(to_world);
      const double child_sca = sca * tr.scale;
      const auto index = static_cast<std::int32_t>(i);
      const std::int32_t top = depth == 0 ? index : outer;
      const bool overrides = !all && o.modifier != scene::kVoid;
      const auto* cs = overrides ? &desc : shade_scene;
      const std::int32_t co = overrides ? index : shade_object;
      const bool child_all = all || o.modifier != scene::kVoid;
      Placement pl;
      pl.path = o.sargs[0];
      pl.instance_object = top;
      pl.shade_scene = cs;
      pl.shade_object = co;
      pl.scale = child_sca;
      for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k)
          pl.to_world[r][k] = child.l[r][k];
        pl.to_world[r][3] = 0;
      }
      pl.to_world[3] = {child.t[0], child.t[1], child.t[2], 1};
      if (o.type == RC_OBJ_INSTANCE) {
        const auto* oct = find_file(in_.octrees, o.sargs[0]);
        if (oct == nullptr || !*oct)
          throw FatalError("cannot find octree \"" + o.sargs[0] + "\" for " + what);
        pl.scene = oct->get();
        g_.keep_alive.push_back(*oct);
        add_placement(pl, octree_prototype(o.sargs[0], **oct, child_all), child, -1);
        ++g_.counts.instances;
        place(**oct, child, child_sca, child_all, top, cs, co, depth + 1);
      } else {
        const auto* mesh = find_file(in_.meshes, o.sargs[0]);
        if (mesh == nullptr || !*mesh)
          throw FatalError("cannot find mesh \"" + o.sargs[0] + "\" for " + what);
        pl.scene = &desc;
        pl.mesh = mesh->get();
        g_.keep_alive.push_back(*mesh);
        add_placement(pl, mesh_prototype(o.sargs[0], **mesh, child_all), child, index);
        ++g_.counts.meshes;
      }
    }
  }

  void add_placement(const Placement& pl, int proto, const Affine& to_world,
                     std::int32_t mesh_object) {
    if (g_.prototypes[proto].empty) return;
    PlacementRecord rec;
    rec.prototype = proto;
    rec.to_world = to_world;
    rec.from_world =
        to_world.inverse().then(Affine::translation(scale(g_.prototypes[proto].centre, -1)));
    rec.mesh_object = mesh_object;
    g_.records.push_back(rec);
    g_.placements.push_back(pl);
  }

  int octree_prototype(const std::string& key, const scene::SceneDescription& desc, bool all) {
    const auto k = std::make_tuple(0, key, all);
    if (auto it = cache_.find(k); it != cache_.end()) return it->second;
    LeafSet leaves = collect_leaves(desc, all, g_.counts);
    const Vec3 centre = scale(add(leaves.bounds[0], leaves.bounds[1]), 0.5);
    Prototype& p = g_.prototypes.emplace_back();
    RTCScene s = rtcNewScene(g_.device);
    rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
    build_leaf_prototype(g_.device, s, std::move(leaves), centre, p);
    rtcCommitScene(s);
    g_.check_embree();
    return cache_[k] = static_cast<int>(g_.prototypes.size() - 1);
  }

  int mesh_prototype(const std::string& key, const scene::TriangleMesh& mesh, bool all) {
    const auto k = std::make_tuple(1, key, all);
    if (auto it = cache_.find(k); it != cache_.end()) return it->second;
    Prototype& p = g_.prototypes.emplace_back();
    RTCScene s = rtcNewScene(g_.device);
    rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
    build_mesh_prototype(g_.device, s, mesh, all, p, g_.counts);
    rtcCommitScene(s);
    g_.check_embree();
    return cache_[k] = static_cast<int>(g_.prototypes.size() - 1);
  }

  void world_bounds(const LeafSet& leaves) {
    bool any = !leaves.empty;
    std::array<Vec3, 2> b = leaves.bounds;
    for (std::size_t i = 1; i < g_.records.size(); ++i) {
      const PlacementRecord& r = g_.records[i];
      const auto& pb = g_.prototypes[r.prototype].bounds;
      for (int c = 0; c < 8; ++c) {
        const Vec3 corner{pb[c & 1][0], pb[(c >> 1) & 1][1], pb[(c >> 2) & 1][2]};
        const Vec3 w = r.to_world.point(corner);
        for (int k = 0; k < 3; ++k) {
          b[0][k] = any ? std::min(b[0][k], w[k]) : w[k];
          b[1][k] = any ? std::max(b[1][k], w[k]) : w[k];
        }
        any = true;
      }
    }
    if (!any) b = {};
    g_.world_bounds = b;
    g_.centre = scale(add(b[0], b[1]), 0.5);
    const double diag = length(sub(b[1], b[0]));
    if (g_.eps <= 0) { // Radiance's FTINY, relative in small models, widened far from the centre
      g_.eps = std::max(1e-30, std::min(1e-6, 1e-7 * diag));
      g_.eps_rel = 1e-7;
    }
    g_.margin = 1e-5 * diag + 1e-30;
    g_.radius = 0.5 * diag + g_.margin;
    g_.far = std::min(1e4 * g_.radius + 1.0, 1e15);
  }

  void attach_instances() {
    const double diag = length(sub(g_.world_bounds[1], g_.world_bounds[0]));
    for (std::size_t i = 1; i < g_.records.size(); ++i) {
      const PlacementRecord& r = g_.records[i];
      const Prototype& p = g_.prototypes[r.prototype];
      // Embree carries a ray into an instance in float, divided by its scale: past about 1e18
      // (1.8e18 is its limit) the ray is invalid and Embree's assertion ends the program. An
      // instance so small against the scene cannot be traced at all (Radiance, in double, would
      // trace it): a clear error instead.
      const Placement& pl = g_.placements[i];
      if (diag / pl.scale > 1e16) {
        const scene::Object& o = in_.main.objects[pl.instance_object];
        char size[64];
        std::snprintf(size, sizeof size, "%g in a scene %g across", pl.scale, diag);
        throw FatalError("bad transform for " + std::string(scene::type_name(o.type)) + " \"" +
                         o.name + "\": a scale of " + size + " is too small to trace");
      }
      // Prototype-centred -> world-centred, as Embree's column-major 3x4 (columns are the
      // images of the axes: the rows of the row-vector matrix).
      const Affine m = Affine::translation(p.centre)
                           .then(r.to_world)
                           .then(Affine::translation(scale(g_.centre, -1)));
      float xfm[12];
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
          xfm[3 * c + k] = static_cast<float>(m.l[c][k]);
      for (int k = 0; k < 3; ++k)
        xfm[9 + k] = static_cast<float>(m.t[k]);
      RTCGeometry g = rtcNewGeometry(g_.device, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(g, p.scene);
      rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
      rtcCommitGeometry(g);
      const unsigned id = rtcAttachGeometry(g_.top, g);
      rtcReleaseGeometry(g);
      if (id >= g_.top_geom_placement.size()) g_.top_geom_placement.resize(id + 1, 0);
      g_.top_geom_placement[id] = static_cast<int>(i);
    }
  }

  const scene::LoadedScene& in_;
  SceneGeometry::Impl& g_;
  std::map<std::tuple<int, std::string, bool>, int> cache_;
};

} // namespace

SceneGeometry::Impl::~Impl() {
  for (auto& p : prototypes)
    if (p.scene != nullptr && p.scene != top) rtcReleaseScene(p.scene);
  if (top != nullptr) rtcReleaseScene(top);
  if (device != nullptr) rtcReleaseDevice(device);
}

void SceneGeometry::Impl::check_embree() const {
  if (!embree_error.empty()) throw FatalError(embree_error);
  if (device != nullptr) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) throw FatalError("Embree error " + std::to_string(int(e)));
  }
}

SceneGeometry::SceneGeometry(const scene::LoadedScene& scene, const GeometryOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (impl_->device == nullptr)
    throw FatalError("cannot create Embree device (error " +
                     std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(impl_->device, embree_error, &impl_->embree_error);
  impl_->eps = options.epsilon;
  impl_->packet = native_packet(impl_->device);
  Builder(scene, *impl_).build();
}

SceneGeometry::~SceneGeometry() = default;
SceneGeometry::SceneGeometry(SceneGeometry&&) noexcept = default;
SceneGeometry& SceneGeometry::operator=(SceneGeometry&&) noexcept = default;

std::array<Vec3d, 2> SceneGeometry::bounds() const {
  return impl_->world_bounds;
}
Vec3d SceneGeometry::centre() const {
  return impl_->centre;
}
double SceneGeometry::epsilon() const {
  return impl_->eps;
}
const SurfaceCounts& SceneGeometry::counts() const {
  return impl_->counts;
}
const std::vector<DistantSource>& SceneGeometry::distant_sources() const {
  return impl_->sources;
}
const std::vector<Placement>& SceneGeometry::placements() const {
  return impl_->placements;
}

} // namespace radcl::geometry
