// A relocatable install: `cmake --install` into one prefix, the tree moved elsewhere, and the
// moved rtrace and rpict render every reference scene (and rcontrib bins a sky) with an empty environment (no RAYPATH,
// RADCL_LIB or PATH; only the caches are pointed at the build's, to spare compiling). They find
// rayinit.cal and radcl's other function files, and the sky generators, relative to themselves;
// an installed program never reads the source tree.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::run_command;

TEST(InstallRelocation, MovedInstallRendersEveryReferenceScene) {
  const fs::path build = fs::absolute(radcl::test::bin_dir()).parent_path();
  const radcl::test::TempFolder folder("install");
  const fs::path& tmp = folder.path();
  std::string out;
  ASSERT_EQ(
      run_command("cmake --install " + build.string() + " --prefix " + (tmp / "P").string(), &out),
      0)
      << out;
  fs::rename(tmp / "P", tmp / "Q");
  const fs::path bin = tmp / "Q" / "bin";
  ASSERT_TRUE(fs::exists(bin / "rtrace"));
  ASSERT_TRUE(fs::exists(tmp / "Q" / "lib" / "radcl" / "rayinit.cal"));
  const std::string env = "env -i HOME=" + tmp.string() +
                          " POCL_CACHE_DIR=" + (build / "pocl-cache").string() +
                          " RADCL_CACHE_DIR=" + (build / "radcl-cache").string() + " ";
  const std::string scenes = fs::absolute(radcl::test::data("scenes")).string();
  for (const char* oct :
       {"chair", "cornell", "furnished", "luminaires", "materials", "materials_plain",
        "office_clear", "office_clear_frozen", "office_overcast", "sphere"}) {
    // A ray from the middle of the scene's box, down, at -ab 1 without the cache.
    std::string cmd = "cd " + scenes + " && echo '0.5 0.5 0.5 0.1 0.2 -1' | " + env +
                      (bin / "rtrace").string() + " -h -ab 1 -aa 0 -ad 16 -ov " + oct + ".oct";
    out.clear();
    ASSERT_EQ(run_command(cmd, &out), 0) << oct << ": " << out;
    std::istringstream in(out);
    double r = -1, g = -1, b = -1;
    in >> r >> g >> b;
    EXPECT_TRUE(r >= 0 && g >= 0 && b >= 0) << oct << ": " << out;
  }
  // rpict, with a sky scene (gensky beside the program, skybright.cal in its library).
  const std::string pic = (tmp / "office.hdr").string();
  out.clear();
  ASSERT_EQ(run_command("cd " + scenes + " && " + env + (bin / "rpict").string() +
                            " -vf office.vf -x 24 -y 24 -ab 0 office_clear.oct > " + pic,
                        &out),
            0)
      << out;
  std::ifstream p(pic);
  std::string line;
  while (std::getline(p, line) && !line.empty()) {
  }
  std::getline(p, line);
  EXPECT_EQ(line, "-Y 18 +X 24"); // office.vf's aspect
  // rcontrib with a bin function file from its library (reinhart.cal): 146 bins of a sky dome.
  out.clear();
  ASSERT_EQ(run_command("cd " + scenes + " && echo '2 2 0.8 0 0 1' | " + env +
                            (bin / "rcontrib").string() +
                            " -h -I -ab 1 -ad 64 -e MF:1 -f reinhart.cal -b rbin -bn Nrbins "
                            "-m skyglow office_dome.oct",
                        &out),
            0)
      << out;
  std::istringstream bins(out);
  int nbins = 0;
  for (double v; bins >> v;)
    ++nbins;
  EXPECT_EQ(nbins, 146 * 3) << out.substr(0, 300);
  // Without its library the moved program stops (a scene with patterns needs rayinit.cal): it
  // never falls back to the source tree.
  fs::remove(tmp / "Q" / "lib" / "radcl" / "rayinit.cal");
  out.clear();
  EXPECT_EQ(run_command("cd " + scenes + " && echo '2 2 1 0 0 1' | " + env +
                            (bin / "rtrace").string() + " -h office_clear.oct",
                        &out),
            1);
  EXPECT_NE(out.find("rtrace: fatal - cannot find function file \"rayinit.cal\""),
            std::string::npos)
      << out;
}
