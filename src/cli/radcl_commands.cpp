#include "radcl_commands.h"

namespace radcl::cli {

std::span<const Command> commands() {
  static const Command kCommands[] = {
      {"ambient", "print a .amb irradiance cache as text (-d, -h), or text back to .amb (-r)",
       cmd_ambient},
      {"devices", "list OpenCL devices (RADCL_DEVICE selects one); --check tests each",
       cmd_devices},
      {"calc", "evaluate .cal expressions (-f file, -e statements, -r rayinit.cal, -c OpenCL C)",
       cmd_calc},
      {"cost", "what accuracy costs in time on your scene: a ladder of settings timed and scored",
       cmd_cost},
      {"scene", "summarise a scene (octree or .rad files); --list prints every object", cmd_scene},
  };
  return kCommands;
}

} // namespace radcl::cli
