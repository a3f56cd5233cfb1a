#include "radcl/render/compile/compiled_scene.h"

#include "radcl/render/compile/func_materials.h"
#include "radcl/render/compile/pattern_compiler.h"
#include <tuple>

#include <cmath>
#include <numbers>
#include <set>

#include "radcl/render/compile/material_traits.h"
#include "radcl/render/compile/mixture_chain.h"
#include "radcl/scene/material_chain.h"
#include "radcl/util/error.h"

namespace radcl::render {
namespace {

// Limits of the rays' antimatter state (rc_ray.clip and rc_ray.inside).
constexpr std::size_t kMaxClipped = 32;
constexpr std::size_t kMaxShadingAntimatter = 4;

// A modifier object: its scene (instances and meshes have their own) and number there.
using ModKey = std::pair<const scene::SceneDescription*, std::int32_t>;

class Compiler {
public:
  Compiler(const scene::LoadedScene& ls, const geometry::SceneGeometry& geom, bool shading,
           const ContribSpec* contrib)
      : ls_(ls), geom_(geom), shading_(shading), contrib_(contrib), patterns_(geom.centre()) {}

  CompiledScene run() {
    const auto& placements = geom_.placements();
    for (const geometry::Placement& pl : placements) {
      out_.placement_base.push_back(static_cast<std::uint32_t>(out_.surfaces.size()));
      out_.placement_mesh.push_back(pl.mesh);
      if (pl.mesh)
        add_mesh_surfaces(pl);
      else
        for (std::size_t i = 0; i < pl.scene->objects.size(); ++i)
          add_surface(pl, static_cast<std::int32_t>(i));
    }
    assign_clip_bits();
    if (out_.features.has(RC_OBJ_MIST)) { // room for the renderer's table of mist sources
      out_.mist_table = static_cast<std::uint32_t>(out_.args.size());
      out_.args.resize(out_.args.size() + kMaxMistSources + 1, 0.0f);
    }
    if (contrib_) compile_contrib(*contrib_, out_, patterns_, geom_.centre());
    if (!patterns_.empty()) {
      out_.features.define("RADCL_HAS_PATTERNS");
      if (patterns_.has_data()) out_.features.define("RADCL_HAS_PATTERN_DATA");
      if (patterns_.has_text()) out_.features.define("RADCL_HAS_TEXT");
      if (patterns_.has_brdf()) out_.features.define("RADCL_HAS_FUNC_MATERIALS");
      out_.features.add_code(patterns_.source());
    }
    // -i/-I: plastic (pi, pi, pi) without specular reflects radiance equal to irradiance.
    out_.irradiance_material = static_cast<std::uint32_t>(out_.materials.size());
    const float pi = std::numbers::pi_v<float>;
    push_material(RC_OBJ_PLASTIC, {pi, pi, pi, 0.0f, 0.0f}, RC_NONE);
    out_.features.add(RC_OBJ_PLASTIC);

    if (!shading_) return std::move(out_); // ray casting needs surfaces and names only
    out_.sources = compile_sources(ls_.main, geom_, [&](std::int32_t obj) {
      return out_.placement_base[0] + static_cast<std::uint32_t>(obj);
    });
    for (std::size_t s = 0; s < out_.sources.sources.size(); ++s) {
      std::uint32_t surf = out_.sources.sources[s].surface;
      if (surf < out_.surfaces.size()) out_.surfaces[surf].source = static_cast<std::uint32_t>(s);
    }
    if (contrib_) compile_contrib_sources(out_);
    return std::move(out_);
  }

private:
  const scene::LoadedScene& ls_;
  const geometry::SceneGeometry& geom_;
  bool shading_;
  const ContribSpec* contrib_;
  CompiledScene out_;
  std::map<std::pair<const scene::SceneDescription*, std::int32_t>, std::uint32_t> ids_;
  std::vector<ModKey> surface_mod_;          // direct modifier of each compiled surface
  std::map<ModKey, std::uint32_t> clip_bit_; // clipped modifiers and their bit in rc_ray.clip
  std::vector<std::uint32_t> slot_mask_;     // per crossing counter: its antimatter's list
  PatternCompiler patterns_;
  // Materials with patterns: (scene, material, the patterns' objects, the placement when it
  // places them: each instance of an octree has its own transform) -> compiled material.
  std::map<std::tuple<const scene::SceneDescription*, std::int32_t, std::vector<std::int32_t>,
                      const geometry::Placement*>,
           std::uint32_t>
      patterned_;
  // Mixtures: (scene, mixfunc, compiled sides, placement if it places them) -> compiled material.
  std::map<std::tuple<const scene::SceneDescription*, std::int32_t, std::uint32_t, std::uint32_t,
                      const geometry::Placement*>,
           std::uint32_t>
      mixtures_;
  // Illum and mirror materials with their alternate's patterns: (material, alternate) -> copy.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> alternates_;

  // Whether the pattern records of `sd` are placed by `pl` (inside its instance or mesh).
  static bool placed_by(const scene::SceneDescription& sd, const geometry::Placement& pl) {
    return &sd == pl.scene || (pl.mesh && &sd == &pl.mesh->objects);
  }

  // Where a modifier walk ends (Radiance's rayshade): the material reached, with the patterns
  // before it (`prefix`, then the walk's own) and its own modifiers' (raytexture); a mixture of
  // materials; or nothing (RC_NONE: the ray goes through). `in_mixture`: a side of a mixture,
  // which may not be antimatter.
  std::uint32_t chain_end(const scene::SceneDescription& sd, const ChainWalk& w,
                          const std::vector<std::int32_t>& prefix, const geometry::Placement& pl,
                          const std::string& surface, bool in_mixture) {
    std::vector<std::int32_t> prog = prefix;
    prog.insert(prog.end(), w.program.begin(), w.program.end());
    if (w.mixture != scene::kVoid) return mixture(sd, w.mixture, prog, pl, surface);
    if (w.material == scene::kVoid) return RC_NONE;
    const scene::Object& mo = sd.objects[w.material];
    if (in_mixture && mo.type == RC_OBJ_ANTIMATTER)
      throw FatalError("material type \"antimatter\" of \"" + mo.name +
                       "\" in a mixture is not supported yet");
    std::vector<std::int32_t> own = walk_texture(sd, w.texture_owner, surface);
    prog.insert(prog.end(), own.begin(), own.end());
    return with_alternate(sd, w.material, patterned(sd, w.material, prog, pl), pl);
  }

  // The alternate material named by illum or mirror `obj` (Radiance's lastmod() of its string
  // argument), or kVoid for none or `void`. Fatal: a name with no definition before it.
  static std::int32_t alternate_of(const scene::SceneDescription& sd, std::int32_t obj) {
    const scene::Object& o = sd.objects[obj];
    if ((o.type != RC_OBJ_ILLUM && o.type != RC_OBJ_MIRROR) || o.sargs.empty() ||
        o.sargs[0] == "void")
      return scene::kVoid;
    std::int32_t a = sd.last_modifier(obj, o.sargs[0]);
    if (a == scene::kVoid)
      throw FatalError("undefined alternate material \"" + o.sargs[0] + "\" for " +
                       std::string(scene::type_name(o.type)) + " \"" + o.name + "\"");
    return a;
  }

  // Compiled material `id` (of illum or mirror `m`) with its alternate shaded as Radiance's
  // rayshade() does from the alternate's name: the patterns of that walk apply, placed by `pl`.
  std::uint32_t with_alternate(const scene::SceneDescription& sd, std::int32_t m, std::uint32_t id,
                               const geometry::Placement& pl) {
    std::int32_t a = id == RC_NONE ? scene::kVoid : alternate_of(sd, m);
    if (a == scene::kVoid) return id;
    const std::string what =
        std::string(scene::type_name(sd.objects[m].type)) + " \"" + sd.objects[m].name + "\"";
    std::uint32_t alt = chain_end(sd, walk_chain(sd, a, what), {}, pl, what, true);
    if (alt != RC_NONE && out_.materials[alt].type == RC_OBJ_MIXFUNC)
      throw FatalError("alternate material \"" + sd.objects[a].name + "\" of " + what +
                       ": a mixture there is not supported yet");
    if (alt == out_.materials[id].alt) return id;
    auto key = std::make_pair(id, alt);
    if (auto it = alternates_.find(key); it != alternates_.end()) return it->second;
    rc_material copy = out_.materials[id];
    copy.alt = alt;
    out_.materials.push_back(copy);
    auto idx = static_cast<std::uint32_t>(out_.materials.size() - 1);
    alternates_[key] = idx;
    return idx;
  }

  // A mixture with a material on a side, met after the pattern program `prefix` (Radiance's
  // raymixture): a material of type mixfunc whose sides are what each side's walk ends in
  // (each with the prefix), and whose coefficient is a pattern record.
  std::uint32_t mixture(const scene::SceneDescription& sd, std::int32_t mix,
                        const std::vector<std::int32_t>& prefix, const geometry::Placement& pl,
                        const std::string& surface) {
    std::array<std::int32_t, 2> names = mixture_sides(sd, mix);
    std::array<std::uint32_t, 2> side{RC_NONE, RC_NONE};
    for (int i = 0; i < 2; ++i)
      side[i] = chain_end(sd, walk_chain(sd, names[i], surface), prefix, pl, surface, true);
    bool placed = placed_by(sd, pl);
    auto key = std::make_tuple(&sd, mix, side[0], side[1], placed ? &pl : nullptr);
    if (auto it = mixtures_.find(key); it != mixtures_.end()) return it->second;
    rc_material mm{};
    mm.type = RC_OBJ_MIXFUNC;
    mm.args = static_cast<std::uint32_t>(out_.args.size());
    mm.alt = side[0];
    mm.back = side[1];
    mm.patterns = static_cast<std::uint32_t>(out_.patterns.size());
    out_.patterns.push_back(pattern_record(sd, mix, pl));
    out_.features.add(RC_OBJ_MIXFUNC);
    out_.materials.push_back(mm);
    auto idx = static_cast<std::uint32_t>(out_.materials.size() - 1);
    mixtures_[key] = idx;
    return idx;
  }

  // The record of pattern (or mixture coefficient) `obj`, placed with `pl` when it is inside
  // the placed instance or mesh.
  rc_pattern pattern_record(const scene::SceneDescription& sd, std::int32_t obj,
                            const geometry::Placement& pl) {
    static const std::array<std::array<double, 4>, 4> id{
        {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    bool placed = placed_by(sd, pl);
    out_.features.add(static_cast<rc_object_type>(sd.objects[obj].type));
    return patterns_.compile(sd, obj, placed ? pl.to_world : id, placed ? pl.scale : 1.0,
                             out_.args);
  }

  // The compiled material of a surface with modifier `mod`, `m` its first material: the plain
  // material, a copy that carries its patterns, or a mixture. `surface` names it for messages.
  std::uint32_t shading_material(const scene::SceneDescription& sd, std::int32_t mod,
                                 std::int32_t m, const geometry::Placement& pl,
                                 const std::string& surface) {
    if (!shading_) return material(sd, m);
    return chain_end(sd, walk_chain(sd, mod, surface), {}, pl, surface, false);
  }

  // Material `m` of `sd` with the pattern program `prog` (placed by `pl`): patterns, and the
  // pattern-only mixtures between their markers (mixture_chain.h).
  std::uint32_t patterned(const scene::SceneDescription& sd, std::int32_t m,
                          const std::vector<std::int32_t>& prog, const geometry::Placement& pl) {
    std::uint32_t base = material(sd, m);
    if (base == RC_NONE) return base;
    // A pattern inside an instance or mesh is placed with it, and so is a BRDF material's
    // function record.
    bool placed = placed_by(sd, pl);
    static const std::array<std::array<double, 4>, 4> id{
        {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    bool func =
        out_.materials[base].func != RC_NONE && placed && (pl.to_world != id || pl.scale != 1.0);
    if (prog.empty() && !func) return base;
    auto key = std::make_tuple(&sd, m, prog, placed ? &pl : nullptr);
    if (auto it = patterned_.find(key); it != patterned_.end()) return it->second;
    rc_material copy = out_.materials[base];
    if (func) copy.func = func_record(sd, m, &pl);
    copy.patterns = static_cast<std::uint32_t>(out_.patterns.size());
    copy.npatterns = 0;
    for (std::size_t i = 0; i < prog.size(); ++i, ++copy.npatterns) {
      if (prog[i] == kMixBack || prog[i] == kMixEnd) {
        rc_pattern marker{};
        marker.type = prog[i] == kMixBack ? RC_PATTERN_MIX_BACK : RC_PATTERN_MIX_END;
        marker.object = RC_NONE;
        out_.patterns.push_back(marker);
        continue;
      }
      if (prog[i] == kMixBegin) ++i; // the mixture's coefficient record opens the blend
      out_.patterns.push_back(pattern_record(sd, prog[i], pl));
    }
    out_.materials.push_back(copy);
    auto idx = static_cast<std::uint32_t>(out_.materials.size() - 1);
    patterned_[key] = idx;
    return idx;
  }

  // The function record of BRDF material `m` (placed by `pl` if not null).
  std::uint32_t func_record(const scene::SceneDescription& sd, std::int32_t m,
                            const geometry::Placement* pl) {
    std::array<std::array<double, 4>, 4> id{
        {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    out_.patterns.push_back(
        patterns_.compile(sd, m, pl ? pl->to_world : id, pl ? pl->scale : 1.0, out_.args));
    return static_cast<std::uint32_t>(out_.patterns.size() - 1);
  }

  std::uint32_t clip_bit(const ModKey& key) {
    auto it = clip_bit_.find(key);
    if (it != clip_bit_.end()) return it->second;
    if (clip_bit_.size() == kMaxClipped)
      throw FatalError("antimatter: more than " + std::to_string(kMaxClipped) +
                       " clipped modifiers in the scene (radcl's limit)");
    std::uint32_t bit = static_cast<std::uint32_t>(clip_bit_.size());
    clip_bit_[key] = bit;
    return bit;
  }

  // antimatter: its list as a bit mask (Radiance's m_clip() modifier set, with its warnings),
  // mod1's material as the alternate and a crossing counter when mod1 shades.
  std::uint32_t antimatter(const scene::SceneDescription& sd, std::int32_t obj) {
    const scene::Object& o = sd.objects[obj];
    std::string what = " for antimatter \"" + o.name + "\"";
    if (o.sargs.empty()) throw FatalError("bad # arguments" + what);
    std::uint32_t mask = 0;
    for (const std::string& name : o.sargs) {
      if (name == "void") continue;
      std::int32_t mod = sd.last_modifier(obj, name);
      if (mod == scene::kVoid) {
        warning("unknown modifier \"" + name + "\"" + what);
        continue;
      }
      std::uint32_t bit = 1u << clip_bit({&sd, mod});
      if (mask & bit) {
        warning("duplicate modifier" + what);
        continue;
      }
      mask |= bit;
    }
    std::uint32_t alt = RC_NONE;
    float slot = -1;
    if (o.sargs[0] != "void") {
      std::int32_t mod1 = sd.last_modifier(obj, o.sargs[0]);
      if (mod1 != scene::kVoid) alt = material(sd, scene::first_material_from(sd, mod1));
    }
    if (alt != RC_NONE) {
      if (slot_mask_.size() == kMaxShadingAntimatter)
        throw FatalError("antimatter: more than " + std::to_string(kMaxShadingAntimatter) +
                         " antimatter materials with a shading modifier (radcl's limit)");
      slot = static_cast<float>(slot_mask_.size());
      slot_mask_.push_back(mask);
    }
    out_.features.add(RC_OBJ_ANTIMATTER);
    return push_material(RC_OBJ_ANTIMATTER,
                         {static_cast<float>(mask & 0xFFFFu), static_cast<float>(mask >> 16), slot},
                         alt);
  }

  // Every surface learns the bit of its direct modifier (if an antimatter lists it) and the
  // crossing counters that count it, now that all antimatters are known.
  void assign_clip_bits() {
    for (std::size_t i = 0; i < out_.surfaces.size(); ++i) {
      auto it = clip_bit_.find(surface_mod_[i]);
      if (it == clip_bit_.end()) continue;
      rc_surface& s = out_.surfaces[i];
      s.clip = 1u << it->second;
      for (std::size_t k = 0; k < slot_mask_.size(); ++k)
        if (slot_mask_[k] & s.clip) s.slots |= 1u << k;
    }
  }

  std::uint32_t push_material(rc_object_type type, const std::vector<float>& args,
                              std::uint32_t alt) {
    rc_material m{};
    m.type = type;
    m.args = static_cast<std::uint32_t>(out_.args.size());
    m.nargs = static_cast<std::uint32_t>(args.size());
    m.alt = alt;
    m.func = RC_NONE;
    out_.args.insert(out_.args.end(), args.begin(), args.end());
    out_.materials.push_back(m);
    return static_cast<std::uint32_t>(out_.materials.size() - 1);
  }

  // The compiled material for object `obj` of `sd` (a material, aliases resolved by caller).
  std::uint32_t material(const scene::SceneDescription& sd, std::int32_t obj) {
    if (obj == scene::kVoid) return RC_NONE;
    auto key = std::make_pair(&sd, obj);
    if (auto it = ids_.find(key); it != ids_.end()) return it->second;
    const scene::Object& o = sd.objects[obj];
    if (shading_ && !material_traits(o.type).shaded)
      throw FatalError("material type \"" + std::string(scene::type_name(o.type)) + "\" of \"" +
                       o.name + "\" is not supported yet");
    if (shading_ && o.type == RC_OBJ_ANTIMATTER) {
      std::uint32_t id = antimatter(sd, obj);
      ids_[key] = id;
      return id;
    }
    if (!real_count_ok(o.type, o.fargs.size()))
      throw FatalError("bad number of real arguments for " + std::string(scene::type_name(o.type)) +
                       " \"" + o.name + "\"");
    // Ward's anisotropic lobe divides by both roughnesses (Radiance refuses them at a hit).
    if ((o.type == RC_OBJ_PLASTIC2 || o.type == RC_OBJ_METAL2 || o.type == RC_OBJ_TRANS2) &&
        (o.fargs[4] <= 1e-6 || o.fargs[5] <= 1e-6))
      throw FatalError(std::string(scene::type_name(o.type)) + " \"" + o.name +
                       "\": roughness too small");
    // illum and mirror name an alternate material for rays other than their own purpose
    // (its patterns are added where a surface's walk places it: with_alternate()).
    std::uint32_t alt = RC_NONE;
    if (std::int32_t a = alternate_of(sd, obj); a != scene::kVoid)
      alt = material(sd, scene::first_material_from(sd, a));
    else if (o.type == RC_OBJ_MIRROR && !o.sargs.empty()) // `void`: the mirror disappears
      alt = RC_ALT_VOID;
    out_.features.add(o.type);
    std::uint32_t id =
        o.type == RC_OBJ_MIST
            ? push_material(o.type, mist_arguments(o, out_.mist_sources), alt)
            : push_material(o.type, std::vector<float>(o.fargs.begin(), o.fargs.end()), alt);
    if (shading_ && has_func_record(static_cast<rc_object_type>(o.type))) {
      std::uint32_t rec = func_record(sd, obj, nullptr);
      out_.materials[id].func = rec;
    }
    ids_[key] = id;
    return id;
  }

  static rc_surface new_surface(std::uint32_t type, std::uint32_t object) {
    rc_surface s{};
    s.material = RC_NONE;
    s.type = type;
    s.source = RC_NONE;
    s.object = object;
    return s;
  }

  void push_surface(rc_surface s, std::string name, std::string mod, std::string mat,
                    ModKey direct = {nullptr, scene::kVoid}) {
    out_.surfaces.push_back(s);
    surface_mod_.push_back(direct);
    out_.surface_names.push_back(std::move(name));
    out_.modifier_names.push_back(std::move(mod));
    out_.material_names.push_back(std::move(mat));
  }

  void add_surface(const geometry::Placement& pl, std::int32_t obj) {
    const scene::SceneDescription& sd = *pl.scene;
    const scene::Object& o = sd.objects[obj];
    rc_surface s = new_surface(static_cast<std::uint32_t>(o.type), static_cast<std::uint32_t>(obj));
    if (!scene::is_surface(o.type)) {
      push_surface(s, o.name, "", "");
      return;
    }
    // An instance with a modifier shades everything inside it with that modifier and is
    // reported as the surface hit.
    const scene::SceneDescription* msd = &sd;
    std::int32_t surf = obj;
    if (pl.shade_object >= 0) {
      msd = pl.shade_scene;
      surf = pl.shade_object;
    }
    std::int32_t m = scene::first_material(*msd, surf);
    const scene::Object& so = msd->objects[surf];
    s.material = shading_material(*msd, so.modifier, m, pl,
                                  std::string(scene::type_name(so.type)) + " \"" + so.name + "\"");
    out_.features.add(o.type);
    std::int32_t mod = msd->objects[surf].modifier;
    push_surface(s, msd->objects[surf].name, mod == scene::kVoid ? "void" : msd->objects[mod].name,
                 reported_material(*msd, mod), {msd, mod});
  }

  // One slot per modifier a mesh's faces may name (slot 0: faces without one).
  void add_mesh_surfaces(const geometry::Placement& pl) {
    const scene::TriangleMesh& mesh = *pl.mesh;
    const scene::Object& prim = ls_.main.objects[pl.instance_object];
    out_.features.add(RC_OBJ_MESH);
    for (std::int32_t i = -1; i < static_cast<std::int32_t>(mesh.materials.size()); ++i) {
      rc_surface s = new_surface(RC_OBJ_MESH, static_cast<std::uint32_t>(pl.instance_object));
      std::string mod = "void", mat = "void";
      ModKey direct{nullptr, scene::kVoid};
      if (pl.shade_object >= 0) { // the mesh primitive's own modifier overrides its faces'
        std::int32_t m = scene::first_material(*pl.shade_scene, pl.shade_object);
        s.material =
            shading_material(*pl.shade_scene, pl.shade_scene->objects[pl.shade_object].modifier, m,
                             pl, "mesh \"" + prim.name + "\"");
        std::int32_t mo = pl.shade_scene->objects[pl.shade_object].modifier;
        direct = {pl.shade_scene, mo};
        if (mo != scene::kVoid) mod = pl.shade_scene->objects[mo].name;
        mat = reported_material(*pl.shade_scene, mo);
      } else if (i >= 0) {
        std::int32_t m = scene::first_material_from(mesh.objects, i);
        s.material = shading_material(mesh.objects, i, m, pl, "mesh \"" + prim.name + "\"");
        mod = mesh.materials[i];
        direct = {&mesh.objects, i};
        mat = reported_material(mesh.objects, i);
      }
      push_surface(s, prim.name, mod, mat, direct);
    }
  }
};

} // namespace

std::uint32_t CompiledScene::surface_of(const geometry::Hit& hit) const {
  std::uint32_t base = placement_base[hit.placement];
  if (const scene::TriangleMesh* mesh = placement_mesh[hit.placement]) {
    std::int32_t m =
        hit.prim < mesh->triangle_material.size() ? mesh->triangle_material[hit.prim] : -1;
    return base + static_cast<std::uint32_t>(m + 1);
  }
  return base + static_cast<std::uint32_t>(hit.object);
}

std::uint32_t distant_surface(const CompiledScene& cs, const geometry::SceneGeometry& geom,
                              const std::array<double, 3>& dir) {
  double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  if (len <= 0) return RC_NONE;
  std::uint32_t found = RC_NONE;
  double best = 1e300;
  for (const geometry::DistantSource& s : geom.distant_sources()) {
    double c = (dir[0] * s.direction[0] + dir[1] * s.direction[1] + dir[2] * s.direction[2]) / len;
    if (2 * std::numbers::pi * (1 - c) > s.solid_angle || s.solid_angle >= best) continue;
    std::uint32_t surf = cs.placement_base[0] + static_cast<std::uint32_t>(s.object);
    if (cs.surfaces[surf].material == RC_NONE) continue;
    best = s.solid_angle;
    found = surf;
  }
  return found;
}

void mark_ambient_list(CompiledScene& cs, bool include, const std::vector<std::string>& names) {
  std::set<std::string> set(names.begin(), names.end());
  for (std::size_t i = 0; i < cs.surfaces.size(); ++i) {
    const std::string& mod = cs.modifier_names[i];
    // "void" names no object, so Radiance's set never holds it.
    bool in = !mod.empty() && mod != "void" && set.count(mod) > 0;
    if (in != include)
      cs.surfaces[i].flags |= RC_SURFF_NO_AMBIENT;
    else
      cs.surfaces[i].flags &= ~RC_SURFF_NO_AMBIENT;
  }
}

CompiledScene compile_scene(const scene::LoadedScene& scene, const geometry::SceneGeometry& geom,
                            bool shading, const ContribSpec* contrib) {
  return Compiler(scene, geom, shading, contrib).run();
}

} // namespace radcl::render
