// Helpers shared by the ambient tests: the reference cache file; whole-file I/O, scratch
// folders and captured warnings come from tests/support.
#pragma once

#include <string>

#include "files.h"
#include "temp_dir.h"
#include "test_env.h"
#include "warnings.h"

namespace radcl::test {

inline std::string office_amb() {
  return data("results/office_clear_default.amb");
}

} // namespace radcl::test
