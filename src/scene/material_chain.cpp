#include "radcl/scene/material_chain.h"

#include <string>

#include "radcl/util/error.h"

namespace radcl::scene {

std::int32_t alias_target(const SceneDescription& scene, std::int32_t obj) {
  // A chain longer than the object count must loop.
  for (std::size_t steps = 0; obj != kVoid && steps <= scene.objects.size(); ++steps) {
    const Object& o = scene.objects[obj];
    if (o.type != RC_OBJ_ALIAS) return obj;
    // Pass-through form: the modifier is the referenced object; named form: the reference is
    // the most recent definition of that name before the alias.
    obj = o.sargs.empty() ? o.modifier : scene.last_modifier(obj, o.sargs[0]);
  }
  if (obj == kVoid) return kVoid;
  throw FatalError("alias loop at \"" + scene.objects[obj].name + "\"");
}

std::int32_t first_material(const SceneDescription& scene, std::int32_t surface) {
  return first_material_from(scene, scene.objects.at(surface).modifier);
}

std::int32_t first_material_from(const SceneDescription& scene, std::int32_t m) {
  const std::int32_t start = m;
  for (std::size_t steps = 0; m != kVoid && steps <= scene.objects.size(); ++steps) {
    std::int32_t t = alias_target(scene, m);
    if (t == kVoid) return kVoid;
    if (is_material(scene.objects[t].type)) return t;
    // A pattern/texture/mixture (or named alias of one): continue with the modifier of the
    // object in the chain, which for a named alias is the alias's own modifier.
    m = scene.objects[m].modifier;
  }
  if (m == kVoid) return kVoid;
  throw FatalError("modifier loop at \"" + scene.objects[start].name + "\"");
}

bool is_light_source(const SceneDescription& scene, std::int32_t surface) {
  std::int32_t m = first_material(scene, surface);
  if (m == kVoid) return false;
  const Object& mat = scene.objects[m];
  // Radiance ignores emitters too dim to matter (every channel <= 1e-6).
  if (mat.fargs.size() >= 3 && mat.fargs[0] <= 1e-6 && mat.fargs[1] <= 1e-6 && mat.fargs[2] <= 1e-6)
    return false;
  switch (mat.type) {
  case RC_OBJ_LIGHT:
  case RC_OBJ_ILLUM:
  case RC_OBJ_SPOTLIGHT:
    return true;
  case RC_OBJ_GLOW:
    return scene.objects[surface].type != RC_OBJ_SOURCE && mat.fargs.size() >= 4 &&
           mat.fargs[3] > 0;
  default:
    return false;
  }
}

} // namespace radcl::scene
