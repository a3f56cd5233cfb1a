#include "radcl_commands.h"

namespace radcl::cli {

std::span<const Command> commands() {
  static const Command kCommands[] = {
      {"devices", "list OpenCL devices (RADCL_DEVICE selects one); --check tests each",
       cmd_devices},
      {"scene", "summarise a scene (octree or .rad files); --list prints every object", cmd_scene},
  };
  return kCommands;
}

} // namespace radcl::cli
