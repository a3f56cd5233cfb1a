// radcl's bin function files (lib/tregenza.cal, reinhart.cal, reinhartb.cal, klems_full.cal,
// klems_half.cal, klems_quarter.cal, disk2square.cal) give every direction the bin Radiance's own
// files give it: tests/data/calc/bins/ holds directions (quasi-random ones and ones on and
// beside every patch edge) with the bins Radiance's rcalc computed from its files
// (tests/data/calc/make_bins.sh); here radcl's files are evaluated on the same directions by
// radcl's host evaluator. Radiance is not needed.
#include <cstdlib>
#include <gtest/gtest.h>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "radcl/calc/device_context.h"
#include "radcl/calc/evaluator.h"
#include "radcl/calc/program.h"
#include "test_env.h"
#include "warnings.h"

using radcl::calc::Evaluator;
using radcl::calc::Expression;
using radcl::calc::Program;

namespace {

// One reference file: how Radiance's file was set up, the bin expressions and, per direction,
// its text and Radiance's bins.
struct Reference {
  std::map<std::string, std::string> header; // file, before, after, bins, count
  struct Row {
    std::string text;
    double dir[3];
    std::vector<double> bins;
  };
  std::vector<Row> rows;
};

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  std::string w;
  while (in >> w)
    out.push_back(w);
  return out;
}

Reference read_reference(const std::string& name) {
  Reference ref;
  std::istringstream in(radcl::test::read_file(radcl::test::data("calc/bins/" + name + ".txt")));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] == '#') {
      std::size_t colon = line.find(':');
      if (colon == std::string::npos) continue;
      std::string key = line.substr(2, colon - 2);
      std::string value = colon + 2 <= line.size() ? line.substr(colon + 2) : "";
      ref.header[key] = value;
      continue;
    }
    std::vector<std::string> w = words(line);
    Reference::Row row;
    row.text = line;
    for (int i = 0; i < 3; ++i)
      row.dir[i] = std::strtod(w.at(i).c_str(), nullptr);
    for (std::size_t i = 3; i < w.size(); ++i)
      row.bins.push_back(std::strtod(w[i].c_str(), nullptr));
    ref.rows.push_back(std::move(row));
  }
  return ref;
}

std::string lib_file(const std::string& name) {
  return radcl::test::source_dir() + "/lib/" + name;
}

// Sets the evaluator's ray to direction d (the other ray variables 0).
void set_direction(Evaluator& ev, const double* d) {
  double slots[RC_CALC_NSLOTS] = {};
  slots[RC_CALC_DX] = d[0];
  slots[RC_CALC_DY] = d[1];
  slots[RC_CALC_DZ] = d[2];
  ev.set_ray(slots);
}

class AgainstRadiance : public ::testing::TestWithParam<const char*> {};

} // namespace

TEST_P(AgainstRadiance, EveryDirectionInTheSameBin) {
  const Reference ref = read_reference(GetParam());
  ASSERT_FALSE(ref.rows.empty()) << "no data for " << GetParam();
  const std::vector<std::string> bins = words(ref.header.at("bins"));
  const std::vector<std::string> count = words(ref.header.at("count"));
  ASSERT_EQ(count.size(), 2u);

  radcl::test::CapturedWarnings warnings;
  Program prog;
  prog.load_rayinit(); // as the renderers do: the files must not clash with it
  if (!ref.header.at("before").empty()) prog.load_string(ref.header.at("before"), "-e");
  prog.load_file(lib_file(ref.header.at("file")));
  EXPECT_TRUE(warnings.list().empty())
      << "loading " << ref.header.at("file") << ": " << warnings.list().front();
  // rfluxmtx's -p settings come after the file and redefine its defaults ("redefined").
  if (!ref.header.at("after").empty()) prog.load_string(ref.header.at("after"), "-p");

  std::vector<Expression> exprs;
  for (const std::string& b : bins)
    exprs.push_back(prog.parse_expression(b));
  Evaluator ev(prog);
  int mismatches = 0;
  long checked = 0;
  for (const Reference::Row& row : ref.rows) {
    ASSERT_EQ(row.bins.size(), bins.size()) << row.text;
    set_direction(ev, row.dir);
    for (std::size_t i = 0; i < bins.size(); ++i) {
      const double got = ev.eval(exprs[i]);
      ++checked;
      if (got != row.bins[i] && ++mismatches <= 10)
        ADD_FAILURE() << bins[i] << " at " << row.text << ": radcl " << got;
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << checked << " bins";
  // radcl's files never need an error result (Radiance's disk2square.cal does, see that file).
  EXPECT_EQ(ev.errors(), 0);
  EXPECT_EQ(ev.eval(prog.parse_expression(count[0])), std::strtod(count[1].c_str(), nullptr))
      << count[0];
}

INSTANTIATE_TEST_SUITE_P(Bins, AgainstRadiance,
                         ::testing::Values("tregenza", "reinhart_mf1", "reinhart_mf2",
                                           "reinhart_mf4", "reinhartb_mf1", "reinhartb_mf2",
                                           "reinhartb_mf4", "klems_full", "klems_full_lh",
                                           "klems_half", "klems_quarter", "disk2square_sc4",
                                           "disk2square_sc7", "disk2square_sc16"));

// The bin counts rcontrib's -bn reads, for the subdivisions in common use.
TEST(BinFunctions, Counts) {
  radcl::test::CapturedWarnings warnings;
  auto count = [](const std::string& before, const std::string& file, const std::string& after,
                  const std::string& name) {
    Program prog;
    if (!before.empty()) prog.load_string(before, "-e");
    prog.load_file(lib_file(file));
    if (!after.empty()) prog.load_string(after, "-p");
    Evaluator ev(prog);
    return ev.eval(prog.parse_expression(name));
  };
  EXPECT_EQ(count("", "tregenza.cal", "", "Ntbins"), 146);
  EXPECT_EQ(count("MF:1", "reinhart.cal", "", "Nrbins"), 146);
  EXPECT_EQ(count("MF:2", "reinhart.cal", "", "Nrbins"), 578);
  EXPECT_EQ(count("MF:4", "reinhart.cal", "", "Nrbins"), 2306);
  EXPECT_EQ(count("", "reinhartb.cal", "", "Nrbins"), 145);
  EXPECT_EQ(count("", "reinhartb.cal", "MF=2", "Nrbins"), 577);
  EXPECT_EQ(count("", "reinhartb.cal", "MF=4", "Nrbins"), 2305);
  EXPECT_EQ(count("", "klems_full.cal", "", "Nkbins"), 145);
  EXPECT_EQ(count("", "klems_half.cal", "", "Nkhbins"), 73);
  EXPECT_EQ(count("", "klems_quarter.cal", "", "Nkqbins"), 41);
}

// Every bin from 0 to the count less one is some direction's: the stored directions reach them
// all. No bin lies outside that range, but for one quirk of the Shirley-Chiu bins that radcl's
// disk2square.cal keeps: a direction grazing the surface plane (within about 1e-8 of it) can land
// exactly on the square's right edge, column SCdim, bins SCdim*SCdim to SCdim*SCdim + SCdim - 1.
TEST(BinFunctions, BinsCoverTheirRange) {
  struct Case {
    const char* data;
    double count, limit;
  };
  for (const Case& c :
       {Case{"tregenza", 146, 146}, Case{"reinhart_mf1", 146, 146}, Case{"reinhart_mf2", 578, 578},
        Case{"reinhart_mf4", 2306, 2306}, Case{"reinhartb_mf1", 145, 145},
        Case{"reinhartb_mf2", 577, 577}, Case{"reinhartb_mf4", 2305, 2305},
        Case{"klems_full", 145, 145}, Case{"klems_full_lh", 145, 145}, Case{"klems_half", 73, 73},
        Case{"klems_quarter", 41, 41}, Case{"disk2square_sc4", 16, 20},
        Case{"disk2square_sc7", 49, 56}, Case{"disk2square_sc16", 256, 272}}) {
    SCOPED_TRACE(c.data);
    const Reference ref = read_reference(c.data);
    std::vector<bool> seen(static_cast<std::size_t>(c.limit), false);
    for (const Reference::Row& row : ref.rows)
      for (double b : row.bins) {
        if (b == -1) continue;
        ASSERT_GE(b, 0) << row.text;
        ASSERT_LT(b, c.limit) << row.text;
        ASSERT_EQ(b, static_cast<double>(static_cast<long>(b))) << row.text;
        seen[static_cast<std::size_t>(b)] = true;
      }
    for (std::size_t i = 0; i < static_cast<std::size_t>(c.count); ++i)
      EXPECT_TRUE(seen[i]) << "no direction in bin " << i;
  }
}

// disk2square.cal's two maps on their own, against Radiance's file at full precision.
TEST(BinFunctions, ShirleyChiuMaps) {
  radcl::test::CapturedWarnings warnings;
  std::istringstream in(
      radcl::test::read_file(radcl::test::data("calc/bins/disk2square_maps.txt")));
  Program prog;
  prog.load_file(lib_file("disk2square.cal"));
  // The inputs come in as channels $1 and $2; in_disk_x/y replace the file's own definitions.
  prog.load_string("in_square_x = $1; in_square_y = $2; in_disk_x = $1; in_disk_y = $2;", "-e");
  const Expression out[2][2] = {
      {prog.parse_expression("out_disk_x"), prog.parse_expression("out_disk_y")},
      {prog.parse_expression("out_square_x"), prog.parse_expression("out_square_y")}};
  Evaluator ev(prog);
  int section = -1, points[2] = {0, 0};
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# square:", 0) == 0) section = 0;
    if (line.rfind("# disk:", 0) == 0) section = 1;
    if (line.empty() || line[0] == '#') continue;
    ASSERT_GE(section, 0);
    const std::vector<std::string> w = words(line);
    ASSERT_EQ(w.size(), 4u) << line;
    double v[4];
    for (int i = 0; i < 4; ++i)
      v[i] = std::strtod(w[i].c_str(), nullptr);
    ev.set_ray(std::span<const double>(v, 2));
    EXPECT_EQ(ev.eval(out[section][0]), v[2]) << line;
    EXPECT_EQ(ev.eval(out[section][1]), v[3]) << line;
    ++points[section];
  }
  EXPECT_GT(points[0], 200);
  EXPECT_GT(points[1], 200);
  EXPECT_EQ(ev.errors(), 0);
}
