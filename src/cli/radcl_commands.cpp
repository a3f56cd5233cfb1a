#include "radcl_commands.h"

namespace radcl::cli {

std::span<const Command> commands() {
  static const Command kCommands[] = {
      {"devices", "list OpenCL platforms and devices (RADCL_DEVICE selects one)", cmd_devices},
  };
  return kCommands;
}

} // namespace radcl::cli
