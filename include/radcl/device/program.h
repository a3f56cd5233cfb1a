// Device programs: assembled from the embedded kernel sources plus generated code, built with
// options, cached on disk as binaries; and their kernels.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

struct _cl_program;
struct _cl_kernel;

namespace radcl::device {

class Context;
class Buffer;

// What a program is made of: root files (embedded names, e.g. "probe.cl") whose #include "..."
// lines are expanded from the embedded sources, a generated file that kernels include as
// "generated.cl", and the build options (-D defines).
struct ProgramSource {
  std::vector<std::string> roots;
  std::string generated;
  std::string options;

  // The single translation unit handed to the compiler; each file appears once.
  std::string assemble() const;
};

// Rewrites "<kernel>:N:" and "<source>:N:" positions in a compiler log (drivers that ignore
// #line file names, e.g. NVIDIA's) to "file:line:" of the embedded source they came from.
std::string locate_log_lines(const std::string& log, const std::string& assembled);

class Kernel {
public:
  Kernel() = default;
  Kernel(_cl_kernel* k) : kernel_(k) {}
  ~Kernel();
  Kernel(Kernel&& o) noexcept;
  Kernel& operator=(Kernel&& o) noexcept;
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;

  template <class T> Kernel& arg(unsigned index, const T& value) {
    return set_arg(index, sizeof(T), &value);
  }
  Kernel& arg(unsigned index, const Buffer& buffer);
  Kernel& set_arg(unsigned index, std::size_t size, const void* value);

  std::size_t preferred_group_size() const { return group_; }
  _cl_kernel* handle() const { return kernel_; }

private:
  friend class Program;
  _cl_kernel* kernel_ = nullptr;
  std::size_t group_ = 0;
};

class Program {
public:
  // Builds `src` for the context's device, or loads the binary a previous build left in the
  // program cache. A failed build is a FatalError carrying the compiler's log.
  Program(Context& ctx, const ProgramSource& src);
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  Kernel kernel(const char* name) const;

  const std::string& source() const { return source_; }
  const std::string& options() const { return options_; }
  const std::string& cache_key() const { return key_; }
  bool loaded_from_cache() const { return from_cache_; }

private:
  Context* ctx_;
  _cl_program* program_ = nullptr;
  std::string source_, options_, key_;
  bool from_cache_ = false;
};

// The program cache folder: RADCL_CACHE_DIR, else $XDG_CACHE_HOME/radcl, else
// ~/.cache/radcl; "" when caching is off (RADCL_PROGRAM_CACHE=0 or no usable folder).
std::string program_cache_dir();

} // namespace radcl::device
