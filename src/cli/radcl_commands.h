// The radcl subcommands. Each is defined in src/cli/radcl_<name>.cpp.
#pragma once

#include <span>

namespace radcl::cli {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv); // argv[0] is the command name
};

std::span<const Command> commands();

int cmd_ambient(int argc, char** argv);
int cmd_calc(int argc, char** argv);
int cmd_cost(int argc, char** argv);
int cmd_devices(int argc, char** argv);
int cmd_scene(int argc, char** argv);

} // namespace radcl::cli
