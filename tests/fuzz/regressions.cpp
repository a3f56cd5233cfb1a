// Every input the fuzzers ever crashed on, kept in tests/data/fuzz/<target>/, run through the
// same entry point without libFuzzer, so builds without it (gcc CI) keep checking them. An
// input passes when the target returns or throws FatalError; a crash or any other exception
// fails. The asan preset adds the sanitizers' checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "files.h"
#include "fuzz_target.h"
#include "test_env.h"

namespace radcl::fuzz {

namespace {
std::map<std::string, Body>& registry() {
  static std::map<std::string, Body> targets;
  return targets;
}
} // namespace

bool register_target(const char* name, Body body) {
  return registry().emplace(name, body).second;
}

namespace {

namespace fs = std::filesystem;

std::vector<std::string> target_names() {
  std::vector<std::string> names;
  for (const auto& [name, body] : registry())
    names.push_back(name);
  return names;
}

class FuzzRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzRegression, KeptInputsDoNotCrash) {
  const Body body = registry().at(GetParam());
  const fs::path dir = fs::path(test::data_dir()) / "fuzz" / GetParam();
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const std::string bytes = radcl::test::read_file(f);
    EXPECT_NO_THROW(run_one(body, bytes));
  }
  // The trivial inputs too: nothing at all, one NUL, one newline.
  for (const std::string& s : {std::string(), std::string(1, '\0'), std::string("\n")})
    EXPECT_NO_THROW(run_one(body, s));
  RecordProperty("inputs", static_cast<int>(files.size()));
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzRegression, ::testing::ValuesIn(target_names()),
                         [](const auto& info) { return info.param; });

TEST(FuzzRegression, EveryTargetIsRegistered) {
  for (const char* name : {"rad_reader", "octree_reader", "mesh_reader", "amb_reader",
                           "picture_reader", "options", "ray_input", "command_line"})
    EXPECT_EQ(registry().count(name), 1u) << name;
}

} // namespace
} // namespace radcl::fuzz
