// What a scene needs from the device program: the object types present (surfaces, materials,
// patterns, lights) and any further switches. It becomes -D options and a generated source file
// that includes only the kernel modules of those types, so a program carries no code for
// effects the scene lacks.
#pragma once

#include <bitset>
#include <map>
#include <string>
#include <vector>

#include "radcl/device/program.h"
#include "radcl/device_types.h"

namespace radcl::device {

class FeatureSet {
public:
  void add(rc_object_type t) { types_.set(t); }
  bool has(rc_object_type t) const { return types_.test(t); }
  // A further switch, e.g. define("RADCL_AMBIENT_CACHE") or define("RADCL_MAX_DEPTH", "8").
  void define(const std::string& name, const std::string& value = "1");
  // Code appended to the generated file (e.g. compiled .cal expressions).
  void add_code(const std::string& code) { code_ += code; }

  // -D options, one per present type (RADCL_HAS_<TYPE>) and per switch, in a fixed order.
  std::string options() const;
  // Includes "<category>/<type>.cl" for each present type that has such a module under
  // kernels/ (materials/, surfaces/, patterns/), then the added code.
  std::string generated_source() const;
  ProgramSource program(std::vector<std::string> roots) const;

private:
  std::bitset<RC_OBJ_COUNT> types_;
  std::map<std::string, std::string> defines_;
  std::string code_;
};

} // namespace radcl::device
