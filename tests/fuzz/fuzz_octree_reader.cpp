// The octree reader on arbitrary bytes, in memory. The scene files an unfrozen octree names
// are not opened (nor run, for '!' names): ReadPolicy makes that a FatalError, so only frozen
// octrees reach the tree and object checks.
#include "fuzz_target.h"
#include "radcl/scene/octree_reader.h"

RADCL_FUZZ_TARGET(octree_reader) {
  radcl::scene::ReadPolicy policy;
  policy.run_commands = false;
  policy.open_files = false;
  radcl::scene::read_octree_data(std::string(data), "fuzz.oct", policy);
}
