#include "radcl/device/program.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <utility>
#include <vector>

#include "radcl/device/buffer.h"
#include "radcl/device/cl.h"
#include "radcl/device/context.h"
#include "radcl/util/error.h"
#include "radcl/util/hash.h"

namespace fs = std::filesystem;

namespace radcl::device {
namespace {

std::string build_log(cl_program p, cl_device_id d) {
  size_t n = 0;
  clGetProgramBuildInfo(p, d, CL_PROGRAM_BUILD_LOG, 0, nullptr, &n);
  std::string log(n, '\0');
  if (n) clGetProgramBuildInfo(p, d, CL_PROGRAM_BUILD_LOG, n, log.data(), nullptr);
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n'))
    log.pop_back();
  return log;
}

std::vector<unsigned char> read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

// Write-then-rename so a concurrent reader never sees a partial binary.
void write_file_atomic(const fs::path& p, const unsigned char* data, size_t n) {
  fs::path tmp = p;
  tmp += ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(n));
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      return;
    }
  }
  std::error_code ec;
  fs::rename(tmp, p, ec);
  if (ec) fs::remove(tmp, ec);
}

// RADCL_DUMP_PROGRAMS=<dir>: every program's assembled source as <key>.cl, its first line a
// comment with the build options, for offline compilers (weighing what a kernel costs to build).
void dump_program(const std::string& key, const std::string& source, const std::string& options) {
  const char* d = std::getenv("RADCL_DUMP_PROGRAMS");
  if (!d || !*d) return;
  std::error_code ec;
  fs::create_directories(d, ec);
  const std::string text = "// options: " + options + "\n" + source;
  write_file_atomic(fs::path(d) / (key + ".cl"),
                    reinterpret_cast<const unsigned char*>(text.data()), text.size());
}

// RADCL_CL_OPTIONS: build options added to every program's (say, a vendor's optimisation
// level, to weigh compile time against speed); they are part of the cache key.
std::string with_user_options(std::string options) {
  if (const char* e = std::getenv("RADCL_CL_OPTIONS"); e && *e) options += std::string(" ") + e;
  return options;
}

} // namespace

std::string program_cache_dir() {
  const char* off = std::getenv("RADCL_PROGRAM_CACHE");
  if (off && std::string(off) == "0") return "";
  fs::path dir;
  if (const char* d = std::getenv("RADCL_CACHE_DIR"); d && *d)
    dir = d;
  else if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    dir = fs::path(x) / "radcl";
  else if (const char* h = std::getenv("HOME"); h && *h)
    dir = fs::path(h) / ".cache" / "radcl";
  else
    return "";
  dir /= "programs";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    static bool warned = false;
    if (!warned) warning("cannot use program cache folder " + dir.string() + ": " + ec.message());
    warned = true;
    return "";
  }
  return dir.string();
}

Program::Program(Context& ctx, const ProgramSource& src)
    : ctx_(&ctx), source_(src.assemble()), options_(with_user_options(src.options)) {
  const DeviceInfo& dev = ctx.info();
  cl_device_id id = static_cast<cl_device_id>(dev.id);
  key_ = Hasher()
             .add(source_)
             .add(options_)
             .add(dev.platform_name)
             .add(dev.platform_version)
             .add(dev.name)
             .add(dev.device_version)
             .add(dev.driver_version)
             .hex();
  dump_program(key_, source_, options_);
  std::string dir = program_cache_dir();
  fs::path cached = dir.empty() ? fs::path() : fs::path(dir) / (key_ + ".bin");

  if (!dir.empty()) {
    std::vector<unsigned char> bin = read_file(cached);
    if (!bin.empty()) {
      const unsigned char* data = bin.data();
      size_t size = bin.size();
      cl_int bin_status = CL_SUCCESS, st = CL_SUCCESS;
      cl_program p =
          clCreateProgramWithBinary(ctx.handle(), 1, &id, &size, &data, &bin_status, &st);
      if (st == CL_SUCCESS && bin_status == CL_SUCCESS &&
          clBuildProgram(p, 1, &id, options_.c_str(), nullptr, nullptr) == CL_SUCCESS) {
        program_ = p;
        from_cache_ = true;
        return;
      }
      if (p) clReleaseProgram(p);
      std::error_code ec;
      fs::remove(cached, ec); // stale or foreign binary: rebuild from source below
    }
  }

  const char* text = source_.c_str();
  size_t len = source_.size();
  RADCL_CL_CREATE(program_,
                  clCreateProgramWithSource(ctx.handle(), 1, &text, &len, &radcl_status_));
  cl_int st = clBuildProgram(program_, 1, &id, options_.c_str(), nullptr, nullptr);
  if (st != CL_SUCCESS) {
    std::string log = locate_log_lines(build_log(program_, id), source_);
    clReleaseProgram(program_);
    program_ = nullptr;
    throw FatalError("OpenCL program build failed on " + dev.name + " (" + cl_status_name(st) +
                     "), options \"" + options_ + "\":\n" + log);
  }
  if (!dir.empty()) {
    size_t size = 0;
    RADCL_CL(clGetProgramInfo(program_, CL_PROGRAM_BINARY_SIZES, sizeof size, &size, nullptr));
    if (size > 0) {
      std::vector<unsigned char> bin(size);
      unsigned char* ptr = bin.data();
      RADCL_CL(clGetProgramInfo(program_, CL_PROGRAM_BINARIES, sizeof ptr, &ptr, nullptr));
      write_file_atomic(cached, bin.data(), bin.size());
    }
  }
}

Program::~Program() {
  if (program_) clReleaseProgram(program_);
}

Kernel Program::kernel(const char* name) const {
  cl_kernel k = nullptr;
  RADCL_CL_CREATE(k, clCreateKernel(program_, name, &radcl_status_));
  Kernel out(k);
  RADCL_CL(clGetKernelWorkGroupInfo(k, static_cast<cl_device_id>(ctx_->info().id),
                                    CL_KERNEL_PREFERRED_WORK_GROUP_SIZE_MULTIPLE, sizeof out.group_,
                                    &out.group_, nullptr));
  // Several preferred multiples per group keep wide GPUs busy; cap at the device maximum.
  size_t max_group = 0;
  RADCL_CL(clGetKernelWorkGroupInfo(k, static_cast<cl_device_id>(ctx_->info().id),
                                    CL_KERNEL_WORK_GROUP_SIZE, sizeof max_group, &max_group,
                                    nullptr));
  if (out.group_ == 0) out.group_ = 1;
  size_t g = out.group_;
  while (g * 2 <= 128 && g * 2 <= max_group)
    g *= 2;
  out.group_ = g <= max_group ? g : max_group;
  return out;
}

Kernel::~Kernel() {
  if (kernel_) clReleaseKernel(kernel_);
}

Kernel::Kernel(Kernel&& o) noexcept
    : kernel_(std::exchange(o.kernel_, nullptr)), group_(o.group_) {}

Kernel& Kernel::operator=(Kernel&& o) noexcept {
  if (this != &o) {
    if (kernel_) clReleaseKernel(kernel_);
    kernel_ = std::exchange(o.kernel_, nullptr);
    group_ = o.group_;
  }
  return *this;
}

Kernel& Kernel::set_arg(unsigned index, std::size_t size, const void* value) {
  RADCL_CL(clSetKernelArg(kernel_, index, size, value));
  return *this;
}

Kernel& Kernel::arg(unsigned index, const Buffer& buffer) {
  cl_mem m = buffer.handle();
  return set_arg(index, sizeof m, &m);
}

} // namespace radcl::device
