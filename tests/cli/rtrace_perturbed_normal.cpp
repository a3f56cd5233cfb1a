// rtrace -on is the perturbed normal (Radiance's oputn: raynormal() once the ray is shaded),
// -oN the unperturbed one: smoothed mesh normals, texfunc and texdata tilts, a mixture's sides'
// tilts blended by its coefficient, and the back of a textured pane (the tilt turns with it).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "run_program.h"
#include "temp_dir.h"
#include "test_env.h"

namespace {

// The scene: a light sphere above a floor whose plastic a texfunc tilts, a texdata metal ball,
// a wall mixing two textured plastics (.25 of the first), the reference octahedron mesh (its
// vertex normals smooth it) under a texfunc, and a textured glass pane.
const char* kScene = R"(void light lamp 0 0 3 100 100 100
lamp sphere bulb 0 0 4 0 0 6 0.5
void texfunc wave 4 .3*sin(2*Px) .2*cos(3*Py) 0 . 0 0
wave plastic wavy 0 0 5 .6 .6 .6 .05 0
wavy polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0
void texdata tdat 8 px py pz dx.dat dy.dat dz.dat tex.cal Px 0 0
tdat metal dmet 0 0 5 .8 .8 .8 .9 0
dmet sphere ball 0 0 4 3 0 1 0.8
void texfunc tA 4 .4 0 0 . 0 0
void texfunc tB 4 0 -.5 0 . 0 0
tA plastic pA 0 0 5 .5 .5 .5 0 0
tB plastic pB 0 0 5 .2 .2 .2 0 0
void mixfunc blend 4 pA pB .25 . 0 0
blend polygon wall 0 0 12 -3 -5 -1 -3 5 -1 -3 5 3 -3 -5 3
void texfunc tC 4 .1 .1 0 . 0 0
tC plastic octm 0 0 5 .5 .5 .5 0 0
octm mesh octo 7 octa.rtm -s .5 -t 0 3 1 0 0
void texfunc tG 4 0 .3 .1 . 0 0
tG glass tglass 0 0 3 .9 .9 .9
tglass polygon pane 0 0 12 2 -4 -0.5 4 -4 -0.5 4 -4 2 2 -4 2
)";

struct Ray {
  const char* ray;
  double n[3], N[3]; // Radiance's -on and -oN
};

// Radiance 5.4a: `rtrace -h -ab 0 -onN` on kScene (with the files TexturedScene writes and the
// reference set's octa.rtm), one ray per line; its output copied here.
const Ray kRays[] = {
    // floor (texfunc)
    {"0.3 0.2 2 0 0 -1", {1.648447e-01, 1.606352e-01, 9.731508e-01}, {0, 0, 1}},
    {"-1.2 0.7 2 0.1 0 -1", {-2.619333e-01, -9.695104e-02, 9.602039e-01}, {0, 0, 1}},
    {"1 -2 2 0 0.3 -1", {2.620034e-01, -9.417527e-02, 9.604609e-01}, {0, 0, 1}},
    // ball (texdata)
    {"3.1 0.2 3 0 0 -1",
     {6.599348e-01, -4.685928e-02, 7.498602e-01},
     {1.250000e-01, 2.500000e-01, 9.601432e-01}},
    {"2.5 0.5 1 1 0 0", {-9.868914e-01, -1.613855e-01, 0}, {7.806247e-01, 6.250000e-01, 0}},
    // wall (mixture: .25 x (.4 0 0) + .75 x (0 -.5 0))
    {"0 0 1 -1 0 0", {9.465102e-01, -3.226739e-01, 0}, {1, 0, 0}},
    {"0 1 2 -1 0.2 -0.1", {9.465102e-01, -3.226739e-01, 0}, {1, 0, 0}},
    // octahedron (smoothed mesh plus texfunc)
    {"0.1 3.1 3 0 0 -1",
     {3.759502e-01, 3.759502e-01, 8.469492e-01},
     {5.773503e-01, 5.773503e-01, 5.773503e-01}},
    {"0.05 2 1.1 0 1 0.1",
     {2.674678e-01, -7.879868e-01, 5.545609e-01},
     {5.773503e-01, -5.773503e-01, 5.773503e-01}},
    {"0.1 3.2 5 0 0 -1",
     {3.923216e-01, 6.941074e-01, 6.035716e-01},
     {5.773503e-01, 5.773503e-01, 5.773503e-01}},
    // floor from below: the tilted normal faces the ray
    {"0.3 0.2 -2 0 0 1", {-1.648447e-01, -1.606352e-01, -9.731508e-01}, {0, 0, 1}},
    // pane (texfunc on glass), from its back and its front
    {"3 -2 1 0 -1 0", {0, 9.899495e-01, -1.414214e-01}, {0, -1, 0}},
    {"3 -6 1 0 1 0.1", {0, -9.899495e-01, 1.414214e-01}, {0, -1, 0}},
};

class RtracePerturbedNormal : public radcl::test::TempDir {
protected:
  void SetUp() override {
    TempDir::SetUp();
    std::ofstream(dir / "scene.rad") << kScene;
    std::ofstream(dir / "tex.cal") << "px(a,b,c) = a;\npy(a,b,c) = b;\npz(a,b,c) = c;\n";
    std::ofstream(dir / "dx.dat") << "1\n-2 2 3\n-0.3 0.1 0.5\n";
    std::ofstream(dir / "dy.dat") << "1\n-2 2 3\n0.2 0 -0.2\n";
    std::ofstream(dir / "dz.dat") << "1\n-2 2 3\n0 0 0\n";
    std::filesystem::copy_file(radcl::test::data("scenes/octa.rtm"), dir / "octa.rtm");
  }

  std::vector<std::vector<double>> rtrace(const std::string& args, const std::string& rays) {
    const radcl::test::ProgramRun r = radcl::test::Program("rtrace")
                                          .input(rays)
                                          .in(dir.string())
                                          .merge_err()
                                          .run("-h " + args + " scene.rad");
    EXPECT_EQ(r.rc, 0) << r.out;
    std::vector<std::vector<double>> rows;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
      std::istringstream f(line);
      std::vector<double> v;
      for (double x; f >> x;)
        v.push_back(x);
      rows.push_back(v);
    }
    return rows;
  }
};

} // namespace

TEST_F(RtracePerturbedNormal, MatchesRadiance) {
  std::string rays;
  for (const Ray& r : kRays)
    rays += std::string(r.ray) + "\n";
  const auto rows = rtrace("-ab 0 -onN", rays);
  ASSERT_EQ(rows.size(), std::size(kRays));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 6u) << kRays[k].ray;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(rows[k][c], kRays[k].n[c], 2e-6) << kRays[k].ray << ": n[" << c << "]";
      EXPECT_NEAR(rows[k][3 + c], kRays[k].N[c], 2e-6) << kRays[k].ray << ": N[" << c << "]";
    }
  }
}

// -on is unit and on the ray's side however the tilts add.
TEST_F(RtracePerturbedNormal, UnitAndFacingTheRay) {
  std::string rays;
  for (const Ray& r : kRays)
    rays += std::string(r.ray) + "\n";
  const auto rows = rtrace("-ab 0 -odn", rays);
  ASSERT_EQ(rows.size(), std::size(kRays));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 6u) << kRays[k].ray;
    const double* d = rows[k].data();
    const double* n = d + 3;
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-6) << kRays[k].ray;
    EXPECT_LT(n[0] * d[0] + n[1] * d[1] + n[2] * d[2], 0.0) << kRays[k].ray;
  }
}
