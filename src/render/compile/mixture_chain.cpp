#include "radcl/render/compile/mixture_chain.h"

#include "radcl/render/compile/pattern_compiler.h"
#include "radcl/scene/material_chain.h"
#include "radcl/scene/object_type.h"
#include "radcl/util/error.h"

namespace radcl::render {
namespace {

std::string where(const scene::Object& o) {
  return std::string(scene::type_name(o.type)) + " \"" + o.name + "\"";
}

void append(std::vector<std::int32_t>& to, const std::vector<std::int32_t>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

ChainWalk walk(const scene::SceneDescription& sd, std::int32_t mod, const std::string& surface,
               int depth) {
  ChainWalk out;
  // Modifiers name earlier objects, so a longer chain than the object count must loop.
  for (std::size_t steps = 0; mod != scene::kVoid && steps <= sd.objects.size(); ++steps) {
    const scene::Object& a = sd.objects[mod];
    if (a.type == RC_OBJ_ALIAS && a.sargs.empty()) { // pass-through: as if not in the chain
      mod = a.modifier;
      continue;
    }
    // A named alias is a copy of its target with the alias's own modifier (m_alias).
    std::int32_t t = scene::alias_target(sd, mod);
    if (t == scene::kVoid) break;
    const scene::Object& o = sd.objects[t];
    const auto type = static_cast<rc_object_type>(o.type);
    if (scene::is_material(type)) {
      out.material = t;
      out.texture_owner = mod;
      return out;
    }
    if (!PatternCompiler::supported(type)) throw FatalError(where(o) + " is not supported yet");
    if (scene::is_mixture(type)) {
      if (depth >= RC_MIX_MAX_DEPTH)
        throw FatalError(where(o) + ": mixtures nested more than " +
                         std::to_string(RC_MIX_MAX_DEPTH) + " deep (radcl's limit)");
      std::array<std::int32_t, 2> side = mixture_sides(sd, t);
      ChainWalk fore = walk(sd, side[0], surface, depth + 1);
      ChainWalk back = walk(sd, side[1], surface, depth + 1);
      bool shades = fore.material != scene::kVoid || fore.mixture != scene::kVoid ||
                    back.material != scene::kVoid || back.mixture != scene::kVoid;
      if (shades) { // the de facto material: raymixture() returns 1
        if (a.modifier != scene::kVoid) throw FatalError(where(o) + ": inappropriate modifier");
        out.mixture = t;
        return out;
      }
      // Only patterns on either side: blended, and rayshade() goes on to its modifier.
      out.program.push_back(kMixBegin);
      out.program.push_back(t);
      append(out.program, fore.program);
      out.program.push_back(kMixBack);
      append(out.program, back.program);
      out.program.push_back(kMixEnd);
    } else {
      out.program.push_back(t);
    }
    mod = sd.objects[mod].modifier; // a named alias's own modifier continues the chain
  }
  if (mod != scene::kVoid && scene::alias_target(sd, mod) != scene::kVoid)
    throw FatalError("modifier loop at \"" + sd.objects[mod].name + "\"");
  return out;
}

} // namespace

std::array<std::int32_t, 2> mixture_sides(const scene::SceneDescription& sd, std::int32_t mix) {
  const scene::Object& o = sd.objects[mix];
  // Radiance's minimum string counts: sides, coefficient (or function, data, function file and
  // coordinates).
  std::size_t need = o.type == RC_OBJ_MIXDATA ? 6 : o.type == RC_OBJ_MIXPICT ? 7 : 4;
  if (o.sargs.size() < need) throw FatalError("bad # arguments for " + where(o));
  std::array<std::int32_t, 2> side{scene::kVoid, scene::kVoid};
  for (int i = 0; i < 2; ++i) {
    if (o.sargs[i] == "void") continue;
    side[i] = sd.last_modifier(mix, o.sargs[i]);
    if (side[i] == scene::kVoid)
      throw FatalError(where(o) + ": undefined modifier \"" + o.sargs[i] + "\"");
  }
  return side;
}

ChainWalk walk_chain(const scene::SceneDescription& sd, std::int32_t mod,
                     const std::string& surface) {
  return walk(sd, mod, surface, 0);
}

std::vector<std::int32_t> walk_texture(const scene::SceneDescription& sd, std::int32_t owner,
                                       const std::string& surface) {
  ChainWalk w = walk(sd, sd.objects[owner].modifier, surface, 0);
  std::int32_t conflict = w.material != scene::kVoid ? w.material : w.mixture;
  if (conflict != scene::kVoid)
    throw FatalError(surface + ": conflicting material \"" + sd.objects[conflict].name + "\"");
  return w.program;
}

std::string reported_material(const scene::SceneDescription& sd, std::int32_t mod) {
  for (std::size_t steps = 0; mod != scene::kVoid && steps <= sd.objects.size(); ++steps) {
    std::int32_t t = scene::alias_target(sd, mod);
    if (t == scene::kVoid) break;
    const scene::Object& o = sd.objects[t];
    if (scene::is_material(o.type)) return o.name;
    if (o.modifier == scene::kVoid && scene::is_mixture(o.type)) return o.name;
    mod = sd.objects[mod].modifier;
  }
  return "void";
}

} // namespace radcl::render
