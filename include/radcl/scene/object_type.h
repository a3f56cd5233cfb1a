// Radiance primitive types: names, and which role each plays (surface, material, pattern...).
#pragma once

#include <optional>
#include <string_view>

#include "radcl/device_types.h"

namespace radcl::scene {

using ObjectType = rc_object_type;

std::string_view type_name(ObjectType t);
std::optional<ObjectType> type_from_name(std::string_view name);

bool is_surface(ObjectType t);  // geometry, including instance, mesh and source
bool is_modifier(ObjectType t); // anything that may be named as a modifier
bool is_material(ObjectType t); // shades a surface (incl. light, glow, illum, mirror, antimatter)
bool is_light(ObjectType t);    // light, illum, glow, spotlight
bool is_pattern(ObjectType t);  // modifies colour: *func, *data, *pict, *text colour/bright types
bool is_texture(ObjectType t);  // perturbs the normal: texfunc, texdata
bool is_mixture(ObjectType t);  // mixfunc, mixdata, mixpict, mixtext

} // namespace radcl::scene
