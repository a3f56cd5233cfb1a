// Auxiliary-file search along RAYPATH (function files, data, pictures, fonts, octrees, meshes).
#pragma once

#include <string>

namespace radcl::scene {

// Radiance's getpath(): names starting with '/', '.' or '~' are used as given; otherwise each
// RAYPATH entry is tried in order (empty entry = current directory; default ":/usr/local/lib/ray"),
// then radcl's own library (util/library_path.h). Returns "" when not found.
std::string find_on_raypath(const std::string& name);

} // namespace radcl::scene
