// Auxiliary-file search (../shared/docs/radiance/scene-format.md §1.4,
// ../shared/docs/radiance/octree-format.md §6.1): the one rule of util/library_path.h.
#include "radcl/scene/raypath.h"

#include "radcl/util/library_path.h"

namespace radcl::scene {

std::string find_on_raypath(const std::string& name) {
  return find_library_file(name);
}

} // namespace radcl::scene
