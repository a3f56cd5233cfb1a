// Builds Radiance scenes by hand for the geometry tests (no reader involved).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "radcl/geometry/scene_geometry.h"

namespace radcl::geometry::test {

struct SceneMaker {
  scene::SceneDescription d;

  std::int32_t add(scene::ObjectType type, const std::string& name, std::vector<double> fargs,
                   std::int32_t modifier, std::vector<std::string> sargs = {}) {
    scene::Object o;
    o.type = type;
    o.name = name;
    o.modifier = modifier;
    o.fargs = std::move(fargs);
    o.sargs = std::move(sargs);
    d.objects.push_back(std::move(o));
    return static_cast<std::int32_t>(d.objects.size() - 1);
  }
  std::int32_t material(const std::string& name = "m") {
    return add(RC_OBJ_PLASTIC, name, {0.5, 0.5, 0.5, 0, 0}, scene::kVoid);
  }
  scene::LoadedScene loaded() const {
    scene::LoadedScene s;
    s.main = d;
    return s;
  }
};

inline Vec3d translate(const Vec3d& p, const Vec3d& by) {
  return {p[0] + by[0], p[1] + by[1], p[2] + by[2]};
}

} // namespace radcl::geometry::test
