// The scene as Radiance understands it: every primitive in Radiance's object order, with its
// modifier, identifier and arguments exactly as read. Later stages (geometry, materials,
// patterns, lights) take all their data from here.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "radcl/scene/object_type.h"

namespace radcl::scene {

constexpr std::int32_t kVoid = -1; // Radiance's OVOID: no modifier

struct Object {
  ObjectType type{};
  std::int32_t modifier = kVoid; // object number of the modifier, or kVoid
  std::string name;
  std::vector<std::string> sargs;
  std::vector<double> fargs;
  std::int32_t file = -1; // index into SceneDescription::files (-1: unknown, e.g. frozen)
  std::int32_t line = 0;  // line where the primitive starts (0 if unknown)
};

// A scene read from .rad files or an octree. Object numbers are indices into `objects` and
// equal Radiance's object numbers for the same input.
struct SceneDescription {
  std::vector<Object> objects;
  std::vector<std::string> files;                               // input names, for messages
  std::unordered_map<std::string, std::int32_t> modifier_index; // most recent definition

  // Set when loaded from an octree.
  std::vector<std::string> header; // header lines (without FORMAT=), as rtrace echoes them
  std::array<double, 3> cube_origin{0, 0, 0};
  double cube_size = 0;
  bool frozen = false;

  // Resolves a modifier name as Radiance does at this point of reading (kVoid for "void"; also
  // kVoid for a name never defined, as Radiance's modifier()).
  std::int32_t find_modifier(const std::string& name) const;

  // Radiance's lastmod(): the most recent modifier called `name` defined before object
  // `before` (any definition if `before` is kVoid). Used for references held in string
  // arguments (alias, illum/mirror alternates, mixture inputs), which resolve this way.
  std::int32_t last_modifier(std::int32_t before, const std::string& name) const;
};

} // namespace radcl::scene
