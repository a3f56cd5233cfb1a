// The .rad reader on arbitrary text. !commands are refused through ReadPolicy (a fuzzer must
// never hand its input to /bin/sh), so a '!' line ends the parse with a FatalError instead.
#include <sstream>

#include "fuzz_target.h"
#include "radcl/scene/rad_reader.h"

RADCL_FUZZ_TARGET(rad_reader) {
  radcl::scene::ReadPolicy policy;
  policy.run_commands = false;
  policy.open_files = false;
  std::istringstream in{std::string(data)};
  radcl::scene::SceneDescription scene;
  radcl::scene::read_rad_stream(scene, in, "fuzz.rad", policy);
}
