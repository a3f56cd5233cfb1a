#include "radcl/scene/scene.h"

namespace radcl::scene {

std::int32_t SceneDescription::find_modifier(const std::string& name) const {
  if (name == "void") return kVoid;
  auto it = modifier_index.find(name);
  return it == modifier_index.end() ? kVoid : it->second;
}

std::int32_t SceneDescription::last_modifier(std::int32_t before, const std::string& name) const {
  auto it = modifier_index.find(name);
  if (it == modifier_index.end()) return kVoid; // never defined: no search, as Radiance
  if (before == kVoid || it->second < before) return it->second;
  // The index holds a later definition: look back for the most recent one before `before`.
  for (std::int32_t i = before; i-- > 0;) {
    const Object& o = objects[i];
    if (is_modifier(o.type) && o.name == name) return i;
  }
  return kVoid;
}

} // namespace radcl::scene
