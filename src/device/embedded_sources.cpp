#include "radcl/device/embedded_sources.h"

#include <string>

#include "radcl/util/error.h"

namespace radcl::device {

std::string_view embedded_source(std::string_view name) {
  for (const EmbeddedFile& f : embedded_files())
    if (name == f.name) return {f.data, f.size};
  throw FatalError("no embedded kernel source \"" + std::string(name) + "\"");
}

} // namespace radcl::device
