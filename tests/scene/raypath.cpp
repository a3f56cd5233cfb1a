// find_on_raypath: Radiance's getpath() rules, then radcl's own lib directory.
#include "radcl/scene/raypath.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::scene::find_on_raypath;

namespace {

// Sets an environment variable for one scope.
class EnvVar {
public:
  EnvVar(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    if (value)
      setenv(name, value, 1);
    else
      unsetenv(name);
  }
  ~EnvVar() {
    if (had_)
      setenv(name_, old_.c_str(), 1);
    else
      unsetenv(name_);
  }

private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

class RayPath : public ::testing::Test {
protected:
  void SetUp() override {
    old_ = fs::current_path();
    fs::create_directories(root_ / "a");
    fs::create_directories(root_ / "b");
    fs::create_directories(root_ / "cwd");
    touch("a/one.cal");
    touch("b/one.cal");
    touch("b/two.cal");
    touch("cwd/here.cal");
    fs::current_path(root_ / "cwd");
  }
  void TearDown() override { fs::current_path(old_); }
  void touch(const std::string& rel) { std::ofstream(root_ / rel) << "x\n"; }
  std::string dir(const std::string& rel) const { return (root_ / rel).string(); }

  fs::path old_;
  radcl::test::TempFolder root_{"raypath"};
};

} // namespace

TEST_F(RayPath, SearchesEntriesInOrder) {
  EnvVar rp("RAYPATH", (dir("a") + ":" + dir("b")).c_str());
  EnvVar lib("RADCL_LIB", "");
  EXPECT_EQ(find_on_raypath("one.cal"), dir("a") + "/one.cal");
  EXPECT_EQ(find_on_raypath("two.cal"), dir("b") + "/two.cal");
  EXPECT_EQ(find_on_raypath("none.cal"), "");
  EXPECT_EQ(find_on_raypath("here.cal"), ""); // no empty entry: cwd not searched
  EXPECT_EQ(find_on_raypath(""), "");
}

TEST_F(RayPath, EmptyEntryIsTheCurrentDirectory) {
  EnvVar lib("RADCL_LIB", "");
  {
    EnvVar rp("RAYPATH", (":" + dir("b") + "/").c_str()); // a trailing '/' is kept as is
    EXPECT_EQ(find_on_raypath("here.cal"), "here.cal");
    EXPECT_EQ(find_on_raypath("two.cal"), dir("b") + "/two.cal");
  }
  {
    EnvVar rp("RAYPATH", (dir("a") + "::" + dir("b")).c_str());
    EXPECT_EQ(find_on_raypath("here.cal"), "here.cal");
  }
  {
    // Radiance's loop never tries an empty entry after a trailing ':'.
    EnvVar rp("RAYPATH", (dir("a") + ":").c_str());
    EXPECT_EQ(find_on_raypath("here.cal"), "");
  }
  {
    EnvVar rp("RAYPATH", "");
    EXPECT_EQ(find_on_raypath("here.cal"), "here.cal");
  }
  {
    EnvVar rp("RAYPATH", nullptr); // default ":/usr/local/lib/ray"
    EXPECT_EQ(find_on_raypath("here.cal"), "here.cal");
  }
}

TEST_F(RayPath, AbsoluteDotAndTildeNamesAreNotSearched) {
  EnvVar rp("RAYPATH", dir("a").c_str());
  EnvVar lib("RADCL_LIB", "");
  EXPECT_EQ(find_on_raypath(dir("b") + "/two.cal"), dir("b") + "/two.cal");
  EXPECT_EQ(find_on_raypath(dir("b") + "/none.cal"), "");
  EXPECT_EQ(find_on_raypath("./here.cal"), "./here.cal");
  EXPECT_EQ(find_on_raypath("../a/one.cal"), "../a/one.cal");
  EXPECT_EQ(find_on_raypath("./one.cal"), ""); // not looked for in a/
  EnvVar home("HOME", dir("b").c_str());
  EXPECT_EQ(find_on_raypath("~/two.cal"), dir("b") + "/two.cal");
  EXPECT_EQ(find_on_raypath("~/here.cal"), "");
}

TEST_F(RayPath, RadclLibComesLast) {
  EnvVar rp("RAYPATH", dir("a").c_str());
  {
    EnvVar lib("RADCL_LIB", dir("b").c_str());
    EXPECT_EQ(find_on_raypath("one.cal"), dir("a") + "/one.cal"); // RAYPATH wins
    EXPECT_EQ(find_on_raypath("two.cal"), dir("b") + "/two.cal");
  }
  {
    // Without RADCL_LIB: the source tree's lib/ (compile-time default).
    EnvVar lib("RADCL_LIB", nullptr);
    fs::path src_lib = fs::path(radcl::test::source_dir()) / "lib";
    for (const auto& entry : fs::directory_iterator(src_lib)) {
      if (!entry.is_regular_file()) continue;
      std::string name = entry.path().filename().string();
      EXPECT_EQ(find_on_raypath(name), (src_lib / name).string());
      break;
    }
  }
}
