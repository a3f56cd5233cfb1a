// The scene as the kernels see it: flat tables of surfaces, materials (with their real
// arguments) and light sources, plus the feature set that specialises the device program.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "radcl/device/feature_set.h"
#include "radcl/device_types.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/render/compile/contrib_tables.h"
#include "radcl/render/compile/mist_materials.h"
#include "radcl/render/lights/light_sources.h"
#include "radcl/scene/loader.h"

namespace radcl::render {

struct CompiledScene {
  std::vector<rc_surface> surfaces;
  std::vector<rc_material> materials;
  std::vector<float> args;          // material real arguments, rc_material::args indexes them
  std::vector<rc_pattern> patterns; // per material, a run of its patterns (rc_material::patterns)
  CompiledSources sources;
  device::FeatureSet features;

  // Host-side names for the output letters s, m and M, per compiled surface.
  std::vector<std::string> surface_names, modifier_names, material_names;

  // Built-in material of -i/-I: a diffuse surface of reflectance pi, so reflected radiance
  // equals irradiance.
  std::uint32_t irradiance_material = RC_NONE;

  // Compiled surface of a geometry hit.
  std::uint32_t surface_of(const geometry::Hit& hit) const;

  // mist: the source names the mists list (a bit of rc_ray.slights each) and the args offset
  // of the table of their source indices, which the renderer fills (RC_NONE: no mist).
  MistSources mist_sources;
  std::uint32_t mist_table = RC_NONE;

  // rcontrib (render/compile/contrib_tables.h): the tables' offset in args, or RC_NONE.
  std::uint32_t contrib_table = RC_NONE;

  std::vector<std::uint32_t> placement_base;              // first surface slot per placement
  std::vector<const scene::TriangleMesh*> placement_mesh; // mesh of a mesh placement
};

// The compiled surface of the distant `source` a ray leaving the scene in direction `dir`
// meets, or RC_NONE. Radiance picks the smallest source containing the direction, so the sun
// wins over the sky dome; sources without a material are invisible.
std::uint32_t distant_surface(const CompiledScene& cs, const geometry::SceneGeometry& geom,
                              const std::array<double, 3>& dir);

// -ae/-ai: flags every surface whose modifier (the object it names, as Radiance's r->ro->omod,
// before aliases and patterns are followed) is in `names` with an exclude list, or not in it
// with an include list, so its hits take -av instead of sampling the ambient.
void mark_ambient_list(CompiledScene& cs, bool include, const std::vector<std::string>& names);

// Throws FatalError naming the material for types the renderer does not handle yet. With
// `shading` false (ray casting only) every material is accepted, nothing is checked for
// shading and no light sources are compiled.
// `contrib`: rcontrib's tracked modifiers (contrib_tables.h), or none.
CompiledScene compile_scene(const scene::LoadedScene& scene, const geometry::SceneGeometry& geom,
                            bool shading = true, const ContribSpec* contrib = nullptr);

} // namespace radcl::render
