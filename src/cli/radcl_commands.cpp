#include "radcl_commands.h"

namespace radcl::cli {

std::span<const Command> commands() {
  static const Command kCommands[] = {
      {"devices", "list OpenCL devices (RADCL_DEVICE selects one); --check tests each",
       cmd_devices},
  };
  return kCommands;
}

} // namespace radcl::cli
