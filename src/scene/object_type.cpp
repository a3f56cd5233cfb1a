#include "radcl/scene/object_type.h"

#include <array>

namespace radcl::scene {
namespace {

#define RADCL_NAME_ENTRY(id, name) name,
constexpr std::array<std::string_view, RC_OBJ_COUNT> kNames = {
    RADCL_OBJECT_TYPES(RADCL_NAME_ENTRY)};
#undef RADCL_NAME_ENTRY

} // namespace

std::string_view type_name(ObjectType t) {
  auto i = static_cast<std::size_t>(t);
  return i < kNames.size() ? kNames[i] : std::string_view("unknown");
}

std::optional<ObjectType> type_from_name(std::string_view name) {
  // Case-sensitive, as Radiance's otype() ("BSDF" and "aBSDF" differ only in case elsewhere).
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<ObjectType>(i);
  return std::nullopt;
}

bool is_surface(ObjectType t) {
  switch (t) {
  case RC_OBJ_POLYGON:
  case RC_OBJ_CONE:
  case RC_OBJ_SPHERE:
  case RC_OBJ_RING:
  case RC_OBJ_CYLINDER:
  case RC_OBJ_INSTANCE:
  case RC_OBJ_CUP:
  case RC_OBJ_BUBBLE:
  case RC_OBJ_TUBE:
  case RC_OBJ_MESH:
  case RC_OBJ_SOURCE:
    return true;
  default:
    return false;
  }
}

// Radiance: anything that is neither a surface nor a volume (instance, mesh), alias included.
bool is_modifier(ObjectType t) {
  return !is_surface(t) && t < RC_OBJ_COUNT;
}

bool is_light(ObjectType t) {
  return t == RC_OBJ_LIGHT || t == RC_OBJ_ILLUM || t == RC_OBJ_GLOW || t == RC_OBJ_SPOTLIGHT;
}

bool is_pattern(ObjectType t) {
  switch (t) {
  case RC_OBJ_BRIGHTFUNC:
  case RC_OBJ_BRIGHTDATA:
  case RC_OBJ_BRIGHTTEXT:
  case RC_OBJ_COLORPICT:
  case RC_OBJ_COLORFUNC:
  case RC_OBJ_COLORDATA:
  case RC_OBJ_COLORTEXT:
    return true;
  default:
    return false;
  }
}

bool is_texture(ObjectType t) {
  return t == RC_OBJ_TEXFUNC || t == RC_OBJ_TEXDATA;
}

bool is_mixture(ObjectType t) {
  return t == RC_OBJ_MIXFUNC || t == RC_OBJ_MIXDATA || t == RC_OBJ_MIXTEXT || t == RC_OBJ_MIXPICT;
}

// Every modifier that is not an alias, pattern, texture or mixture shades a surface.
bool is_material(ObjectType t) {
  return is_modifier(t) && t != RC_OBJ_ALIAS && !is_pattern(t) && !is_texture(t) && !is_mixture(t);
}

} // namespace radcl::scene
