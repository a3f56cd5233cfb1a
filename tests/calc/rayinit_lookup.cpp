// rayinit.cal is found as every function file is (util/library_path.h): on RAYPATH first, as
// Radiance finds it, else radcl's own library (here, from the build tree, the source's lib/).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

#include "radcl/calc/evaluator.h"
#include "radcl/calc/program.h"
#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::calc::Evaluator;
using radcl::calc::Program;

TEST(RayinitLookup, RaypathFirstThenOwnLibrary) {
  const radcl::test::TempFolder tmp("rayinit");
  const fs::path& dir = tmp.path();
  std::ofstream(dir / "rayinit.cal") << "marker = 42;\n";
  const char* old = std::getenv("RAYPATH");
  const std::string saved = old ? old : "";
  setenv("RAYPATH", dir.c_str(), 1);
  EXPECT_EQ(Program::rayinit_path(), (dir / "rayinit.cal").string());
  {
    Program p;
    p.load_rayinit();
    Evaluator ev{p};
    EXPECT_EQ(ev.eval(p.parse_expression("marker")), 42.0);
  }
  fs::remove(dir / "rayinit.cal");
  EXPECT_EQ(Program::rayinit_path(),
            (fs::path(radcl::test::source_dir()) / "lib" / "rayinit.cal").string());
  {
    Program p;
    p.load_rayinit();
    Evaluator ev{p};
    EXPECT_EQ(ev.eval(p.parse_expression("abs(-3)")), 3.0); // radcl's own definitions
  }
  if (old)
    setenv("RAYPATH", saved.c_str(), 1);
  else
    unsetenv("RAYPATH");
}
