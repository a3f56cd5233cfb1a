// Malformed scene files (tests/data/scene/bad/): each must fail with a FatalError carrying
// Radiance's message, never crash or throw anything else.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "files.h"
#include "radcl/scene/rad_reader.h"
#include "radcl/util/error.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::FatalError;
using radcl::scene::SceneDescription;

namespace {

struct BadCase {
  const char* file;
  const char* message; // expected substring of the error
};

const BadCase kCases[] = {
    {"truncated_polygon.rad", "(truncated_polygon.rad line 6): bad arguments for polygon \"w1\""},
    {"polygon_4_reals.rad", "(polygon_4_reals.rad line 4): bad # arguments for polygon \"w1\""},
    {"polygon_not_multiple_of_3.rad", "line 2): bad # arguments for polygon \"w2\""},
    {"nonzero_int_count.rad", "(nonzero_int_count.rad line 1): bad arguments for plastic \"p\""},
    {"unknown_type.rad", "(unknown_type.rad line 1): unknown type \"plastik\""},
    {"undefined_modifier.rad", "(undefined_modifier.rad line 4): undefined modifier \"foo\""},
    {"bad_number_dots.rad", "line 1): bad arguments for plastic \"p\""},
    {"bad_number_nan.rad", "line 1): bad arguments for light \"l\""},
    {"bad_number_inf.rad", "line 1): bad arguments for light \"l\""},
    {"bad_number_hex.rad", "line 1): bad arguments for light \"l\""},
    {"bad_real_count.rad", "line 1): bad arguments for plastic \"p\""},
    {"negative_string_count.rad", "line 1): bad arguments for plastic \"p\""},
    {"failing_command.rad", "(!exit 3): command failed with exit status 3"},
    {"missing_include.rad",
     "(!cat no_such_include.rad 2>/dev/null): command failed with exit status 1"},
    {"inherit_misuse.rad", "line 2): inappropriate use of 'inherit' modifier for plastic \"copy\""},
    {"alias_bad_reference.rad", "line 2): bad reference \"wod\" for alias \"floor_wood\""},
    {"alias_of_surface.rad", "line 3): bad reference \"ball\" for alias \"ball2\""},
    {"alias_truncated.rad", "line 2): bad reference \"EOF\" for alias \"a\""},
    {"instance_bad_transform.rad", "line 1): bad transform for instance \"chair\""},
    {"instance_zero_scale.rad", "line 1): bad transform for instance \"chair\""},
    {"instance_no_file.rad", "line 1): bad # arguments for instance \"chair\""},
    {"function_bad_transform.rad", "line 1): bad transform for brightfunc \"sky\""},
    {"plastic_4_reals.rad", "line 1): bad # arguments for plastic \"p\""},
    {"plastic_with_string.rad", "line 1): bad # arguments for plastic \"p\""},
    {"sphere_3_reals.rad", "line 2): bad # arguments for sphere \"s\""},
    {"glass_5_reals.rad", "line 1): bad # arguments for glass \"g\""},
    {"surface_as_modifier.rad", "line 3): undefined modifier \"p\""},
    {"extra_real.rad", "(extra_real.rad line 1): undefined modifier \"0.25\""},
    {"only_modifier.rad", "(only_modifier.rad line 1): unknown type \"EOF\""},
    {"tab_in_identifier.rad", "line 1): illegal tab in identifier \"tab\there\""},
    {"bad_command_output.rad", " line 2): unknown type \"lite\""},
    {"antimatter_no_modifiers.rad", "line 1): bad # arguments for antimatter \"a\""},
    {"no_such_file.rad", "cannot open scene file \"no_such_file.rad\""}, // deliberately absent
};

// Runs `read` and returns the FatalError's message; any other outcome fails the test.
template <class F> std::string fatal_message(F read, const std::string& what) {
  try {
    read();
  } catch (const FatalError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": threw a non-fatal exception: " << e.what();
    return "";
  } catch (...) {
    ADD_FAILURE() << what << ": threw something that is not an exception";
    return "";
  }
  ADD_FAILURE() << what << ": no error";
  return "";
}

class BadRadInput : public ::testing::Test {
protected:
  void SetUp() override {
    old_ = fs::current_path();
    fs::current_path(radcl::test::data("scene/bad")); // messages then name files as given
    radcl::set_warning_sink([](const std::string&) {});
  }
  void TearDown() override {
    fs::current_path(old_);
    radcl::set_warning_sink(nullptr);
  }
  fs::path old_;
};

} // namespace

TEST_F(BadRadInput, EachFileFailsWithItsMessage) {
  for (const auto& c : kCases) {
    SceneDescription scene;
    std::string msg = fatal_message([&] { radcl::scene::read_rad_file(scene, c.file); }, c.file);
    EXPECT_NE(msg.find(c.message), std::string::npos)
        << c.file << "\n  got:      " << msg << "\n  expected: " << c.message;
  }
}

TEST_F(BadRadInput, StreamsGiveTheSameMessages) {
  for (const auto& c : kCases) {
    std::ifstream in(c.file, std::ios::binary);
    if (!in) continue; // the missing-file case
    SceneDescription scene;
    std::string msg =
        fatal_message([&] { radcl::scene::read_rad_stream(scene, in, c.file); }, c.file);
    EXPECT_NE(msg.find(c.message), std::string::npos) << c.file << ": " << msg;
  }
}

TEST_F(BadRadInput, CatalogueCoversEveryFile) {
  std::set<std::string> listed;
  for (const auto& c : kCases)
    listed.insert(c.file);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(".")) {
    if (e.path().extension() != ".rad") continue;
    ++files;
    EXPECT_TRUE(listed.count(e.path().filename().string())) << e.path() << " has no case";
  }
  EXPECT_GE(files, 18u);
  EXPECT_FALSE(fs::exists("no_such_file.rad"));
}

// Every prefix of a valid scene is either a valid scene or a FatalError, never a crash.
TEST_F(BadRadInput, TruncationsOfAValidSceneFailCleanly) {
  const std::string text = radcl::test::read_file(radcl::test::data("scenes/materials.rad"));
  for (std::size_t n = 0; n < text.size(); n += 7) {
    SceneDescription scene;
    std::istringstream part(text.substr(0, n));
    try {
      radcl::scene::read_rad_stream(scene, part, "part.rad");
    } catch (const FatalError&) {
    } catch (...) {
      ADD_FAILURE() << "prefix of " << n << " bytes: not a FatalError";
    }
  }
}
