// Fresh temporary folders, removed afterwards, so tests neither collide (ctest runs them side
// by side) nor leave files behind: TempFolder for a helper or a test body, TempDir as a fixture.
#pragma once

#include <atomic>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

namespace radcl::test {

// A folder of its own under the system's temporary folder, named for `tag`, the process and a
// count (unique within the process too), removed with everything in it when this goes.
class TempFolder {
public:
  explicit TempFolder(const std::string& tag = "tmp") {
    static std::atomic<int> count{0};
    path_ = std::filesystem::temp_directory_path() /
            ("radcl_" + tag + "_" + std::to_string(::getpid()) + "_" + std::to_string(count++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string str() const { return path_.string(); }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
  std::filesystem::path path_;
};

// A fixture that gives each test a fresh folder of its own (named for the suite, the test and
// the process), removed afterwards.
class TempDir : public ::testing::Test {
protected:
  std::filesystem::path dir;

  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::temp_directory_path() /
          ("radcl_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
           std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
};

} // namespace radcl::test
