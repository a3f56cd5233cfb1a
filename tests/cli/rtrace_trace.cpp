// rtrace's trace modes (-ot, -oT): every ray of each primary's tree, children before their
// parent, indented by their ancestors; letters before t/T once per primary.
#include <cmath>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "run_program.h"

namespace {

struct Line {
  int depth = 0;
  std::vector<std::string> f;
  double num(std::size_t i) const { return std::stod(f.at(i)); }
};

// Runs rtrace in the scene folder on `rays` (ascii, one per line).
std::vector<Line> rtrace(const std::string& args, const std::string& scene, const std::string& rays,
                         std::string* raw = nullptr) {
  const radcl::test::ProgramRun r =
      radcl::test::Program("rtrace").input(rays).merge_err().run("-h -w -u- " + args + " " + scene);
  const std::string& out = r.out;
  EXPECT_EQ(r.rc, 0) << out;
  if (raw) *raw = out;
  std::vector<Line> lines;
  std::istringstream in(out);
  std::string s;
  while (std::getline(in, s)) {
    Line l;
    std::size_t p = 0;
    while (p < s.size() && s[p] == '\t')
      ++l.depth, ++p;
    std::size_t q;
    while ((q = s.find('\t', p)) != std::string::npos) {
      l.f.push_back(s.substr(p, q - p));
      p = q + 1;
    }
    lines.push_back(l);
  }
  return lines;
}

const std::string kLum = "2 2 0.5 0 0 1\n1 3 0.8 0 0 1\n";

} // namespace

// -ab 0: the primary's value is its emission plus the contributions of its shadow rays; each
// traced ray's V is its value times its coefficient W.
TEST(RtraceTrace, ShadowRaysAddUpToThePrimary) {
  auto lines = rtrace("-ab 0 -dt 0 -ds 0 -ovtTVvW", "luminaires.rad", kLum);
  ASSERT_FALSE(lines.empty());
  int primaries = 0;
  double sum[3] = {0, 0, 0};
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Line& l = lines[i];
    if (l.depth == 0 && l.f.size() == 3) { // the primary's own line (letters before T)
      ++primaries;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(l.num(c), sum[c], 1e-5 * std::max(1.0, sum[c])) << "line " << i;
      sum[0] = sum[1] = sum[2] = 0;
      continue;
    }
    ASSERT_EQ(l.f.size(), 9u) << "line " << i;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(l.num(c), l.num(3 + c) * l.num(6 + c), 1e-5 * std::max(1e-3, l.num(c)));
    if (l.depth == 1)
      for (int c = 0; c < 3; ++c)
        sum[c] += l.num(c);
  }
  EXPECT_EQ(primaries, 2);
}

// Post-order: every ray is followed by its parent (one level up) before anything shallower,
// and the primary comes last; -ot leaves the shadow rays out.
TEST(RtraceTrace, PostOrderAndShadowRaysOnlyWithCapitalT) {
  auto with =
      rtrace("-ab 1 -ad 16 -as 0 -aa 0 -otTLsw", "materials_plain.oct", "0 -3 1.5 0.1 1 -0.2\n");
  auto without =
      rtrace("-ab 1 -ad 16 -as 0 -aa 0 -otLsw", "materials_plain.oct", "0 -3 1.5 0.1 1 -0.2\n");
  for (const auto* ls : {&with, &without}) {
    ASSERT_GE(ls->size(), 2u);
    EXPECT_EQ(ls->back().depth, 0);
    for (std::size_t i = 0; i + 1 < ls->size(); ++i) {
      EXPECT_GE((*ls)[i].depth, 1) << "only the last line is the primary";
      for (std::size_t j = i + 1; j < ls->size(); ++j)
        if ((*ls)[j].depth < (*ls)[i].depth) {
          EXPECT_EQ((*ls)[j].depth, (*ls)[i].depth - 1) << "line " << i;
          break;
        }
    }
  }
  // Shadow rays are the extra lines; each ends at a source (the sun here) or is blocked.
  EXPECT_GT(with.size(), without.size());
}

// -ti keeps only rays that hit a surface with a listed modifier; -te drops them.
TEST(RtraceTrace, IncludeAndExcludeLists) {
  const std::string ray = "0 -3 1.5 0.1 1 -0.2\n";
  auto all = rtrace("-ab 1 -ad 16 -as 0 -aa 0 -otm", "materials_plain.oct", ray);
  auto inc = rtrace("-ab 1 -ad 16 -as 0 -aa 0 -ti sky_glow -otm", "materials_plain.oct", ray);
  auto exc = rtrace("-ab 1 -ad 16 -as 0 -aa 0 -te sky_glow -otm", "materials_plain.oct", ray);
  std::size_t skies = 0;
  for (const Line& l : all)
    skies += l.f.at(0) == "sky_glow";
  ASSERT_GT(skies, 0u);
  EXPECT_EQ(inc.size(), skies);
  for (const Line& l : inc)
    EXPECT_EQ(l.f.at(0), "sky_glow");
  EXPECT_EQ(exc.size(), all.size() - skies);
}

// Binary output keeps the indentation TABs (as Radiance's tabin), no newlines.
TEST(RtraceTrace, BinaryOutputIsIndented) {
  std::string raw;
  rtrace("-ab 0 -faf -otTw", "luminaires.rad", "2 2 0.5 0 0 1\n", &raw);
  ASSERT_FALSE(raw.empty());
  EXPECT_EQ(raw.find('\n'), std::string::npos);
  EXPECT_EQ(raw[0], '\t');
  EXPECT_EQ(raw.size() % 1, 0u);
}
