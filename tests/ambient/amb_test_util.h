// Helpers shared by the ambient tests: whole-file I/O, scratch folders and captured warnings.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "radcl/util/error.h"
#include "test_env.h"

namespace radcl::test {

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return std::move(ss).str();
}

inline void spit(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string office_amb() {
  return data("results/office_clear_default.amb");
}

// A fresh folder per test, removed at the end.
class ScratchDir {
public:
  explicit ScratchDir(const std::string& tag)
      : dir_(std::filesystem::temp_directory_path() /
             ("radcl-amb-" + tag + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~ScratchDir() { std::filesystem::remove_all(dir_); }
  std::string operator/(const std::string& name) const { return (dir_ / name).string(); }

private:
  std::filesystem::path dir_;
};

// Collects warning() messages while alive.
class WarningLog {
public:
  WarningLog() {
    messages().clear();
    set_warning_sink([](const std::string& m) { messages().push_back(m); });
  }
  ~WarningLog() { set_warning_sink(nullptr); }
  static std::vector<std::string>& messages() {
    static std::vector<std::string> m;
    return m;
  }
};

} // namespace radcl::test
