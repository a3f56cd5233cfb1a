// Kernel sources and shared headers embedded at build time (cmake/embed_files.cmake).
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace radcl::device {

struct EmbeddedFile {
  const char* name; // "layout.cl", "radcl/device_types.h", ... (as kernels #include them)
  const char* data;
  std::size_t size;
};

std::span<const EmbeddedFile> embedded_files();

// The embedded file of that name; throws FatalError if there is none.
std::string_view embedded_source(std::string_view name);

} // namespace radcl::device
