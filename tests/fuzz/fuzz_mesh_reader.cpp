// The Radiance_tmesh (.rtm) reader on arbitrary bytes, in memory.
#include "fuzz_target.h"
#include "radcl/scene/mesh.h"

RADCL_FUZZ_TARGET(mesh_reader) {
  radcl::scene::read_mesh_data(std::string(data), "fuzz.rtm");
}
