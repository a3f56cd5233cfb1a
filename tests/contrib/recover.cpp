// -r: an interrupted run's files are checked, their complete records counted and the run goes
// on after them (recover_output()); with -c 0 the totals are read back instead (reload_output()).
#include "radcl/contrib/output.h"
#include "radcl/util/error.h"

#include "files.h"
#include "temp_dir.h"
#include "warnings.h"

#include <filesystem>
#include <functional>
#include <gtest/gtest.h>
#include <map>

using namespace radcl::contrib;
using radcl::test::read_file;
namespace fs = std::filesystem;

namespace {

struct Mod {
  std::optional<std::string> spec;
  std::string name;
  int nbins;
};

// Record k's values: k * 100 + i, exact in every binary format but RGBE.
std::vector<double> values(const std::vector<Mod>& mods, int k) {
  std::vector<double> v;
  for (const Mod& m : mods)
    for (int i = 0; i < 3 * m.nbins; ++i)
      v.push_back(k * 100 + static_cast<int>(v.size()));
  return v;
}

// Registers `mods`, recovers (with s.recover), then writes records `from` to `to` - 1.
long run(const OutputSettings& s, const std::vector<Mod>& mods, int from, int to) {
  Outputs out(s);
  for (const Mod& m : mods)
    out.add_modifier(m.spec, m.name, m.nbins);
  std::vector<double> reloaded;
  const long done = out.recover(reloaded);
  EXPECT_TRUE(reloaded.empty());
  if (out.output_complete()) return done;
  for (int k = from + static_cast<int>(done); k < to; ++k) {
    out.write_record(values(mods, k));
    out.end_record();
  }
  out.finish();
  return done;
}

// The header's length: up to its empty line, and the resolution string after it if any.
std::uintmax_t header_size(const fs::path& file) {
  const std::string text = read_file(file);
  if (text.compare(0, 2, "#?") != 0) return 0; // -h-
  std::size_t end = text.find("\n\n") + 2;
  if (text.compare(end, 2, "-Y") == 0) end = text.find('\n', end) + 1;
  return end;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const radcl::SystemError& e) {
    return std::string("system - ") + e.what();
  } catch (const radcl::FatalError& e) {
    return std::string("fatal - ") + e.what();
  }
  return "(no error)";
}

} // namespace

class Recover : public radcl::test::TempDir {
protected:
  OutputSettings settings(char format) const {
    OutputSettings s;
    s.format = format;
    s.octree_header = {"#?RADIANCE", "oconv scene.rad"};
    s.command = {"rcontrib", "-r", "-m", "sky"};
    s.software = "radcl 1.2.3";
    s.time = 1700000000;
    return s;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  // A full run into full/ and an interrupted one into cut/ with each file cut to `keep`
  // bytes past its header; then -r on cut/ must give full/'s files and return `expected`.
  void check_recovery(OutputSettings s, const std::vector<std::string>& specs,
                      const std::vector<std::pair<std::string, int>>& mods, int records,
                      const std::map<std::string, std::uintmax_t>& keep, long expected) {
    fs::create_directories(dir / "full");
    fs::create_directories(dir / "cut");
    auto modlist = [&](const std::string& sub) {
      std::vector<Mod> v;
      for (std::size_t k = 0; k < mods.size(); ++k)
        v.push_back({path(sub + "/" + specs[k]), mods[k].first, mods[k].second});
      return v;
    };
    run(s, modlist("full"), 0, records);
    run(s, modlist("cut"), 0, records);
    for (const auto& [file, bytes] : keep)
      fs::resize_file(dir / "cut" / file, header_size(dir / "cut" / file) + bytes);
    s.recover = true;
    EXPECT_EQ(run(s, modlist("cut"), 0, records), expected);
    for (const auto& [file, bytes] : keep)
      EXPECT_EQ(read_file(dir / "cut" / file), read_file(dir / "full" / file)) << file;
  }
  radcl::test::CapturedWarnings warnings;
};

TEST_F(Recover, FloatFilePerModifier) {
  OutputSettings s = settings('f');
  s.yres = 8;
  const int sky = 2 * 12, sun = 12; // bytes per record
  check_recovery(s, {"%s.dat", "%s.dat"}, {{"sky", 2}, {"sun", 1}}, 8,
                 {{"sky.dat", 3 * sky + 12}, {"sun.dat", 4 * sun}}, 3);
  EXPECT_TRUE(warnings.list().empty());
}

TEST_F(Recover, SharedDoubleFile) {
  const int rec = 3 * 24;
  check_recovery(settings('d'), {"all.dat", "all.dat"}, {{"sky", 2}, {"sun", 1}}, 6,
                 {{"all.dat", 2 * rec + 30}}, 2);
}

TEST_F(Recover, PicturePerBin) {
  OutputSettings s = settings('c');
  s.xres = 2;
  s.yres = 2;
  check_recovery(s, {"p%d.hdr"}, {{"sky", 2}}, 4, {{"p0.hdr", 6}, {"p1.hdr", 8}}, 1);
}

TEST_F(Recover, WithoutHeader) {
  OutputSettings s = settings('d');
  s.header = false;
  check_recovery(s, {"sky.dat"}, {{"sky", 1}}, 5, {{"sky.dat", 2 * 24 + 1}}, 2);
}

// -c 2: a record is two rays, so the caller skips twice the count.
TEST_F(Recover, Accumulated) {
  OutputSettings s = settings('f');
  s.accumulate = 2;
  check_recovery(s, {"%s_%d.dat"}, {{"sky", 2}}, 5, {{"sky_0.dat", 36}, {"sky_1.dat", 24}}, 2);
}

TEST_F(Recover, OutputAppearsComplete) {
  OutputSettings s = settings('f');
  s.xres = 2;
  s.yres = 2;
  const std::vector<Mod> mods{{path("%s.dat"), "sky", 2}};
  run(s, mods, 0, 4);
  const std::string before = read_file(dir / "sky.dat");
  s.recover = true;
  {
    Outputs out(s);
    out.add_modifier(mods[0].spec, "sky", 2);
    std::vector<double> reloaded;
    EXPECT_EQ(out.recover(reloaded), 4);
    EXPECT_TRUE(out.output_complete());
  }
  EXPECT_EQ(warnings.list(), std::vector<std::string>{"output appears to be complete"});
  EXPECT_EQ(read_file(dir / "sky.dat"), before);
}

// Nothing to go on from: the run starts again, with fresh files.
TEST_F(Recover, NoPreviousData) {
  OutputSettings s = settings('d');
  const std::vector<Mod> mods{{path("sky.dat"), "sky", 1}};
  run(s, mods, 0, 3);
  const std::string full = read_file(dir / "sky.dat");
  fs::resize_file(dir / "sky.dat", header_size(dir / "sky.dat"));
  s.recover = true;
  EXPECT_EQ(run(s, mods, 0, 3), 0);
  EXPECT_EQ(read_file(dir / "sky.dat"), full);
  radcl::test::write_file(dir / "sky.dat", "");
  EXPECT_EQ(run(s, mods, 0, 3), 0);
  EXPECT_EQ(read_file(dir / "sky.dat"), full);
  EXPECT_EQ(warnings.list(), (std::vector<std::string>{"no previous data to recover",
                                                       "no previous data to recover"}));
}

TEST_F(Recover, MissingFile) {
  OutputSettings s = settings('f');
  radcl::test::write_file(dir / "sky.dat", format_header(s, "") + std::string(12, 'x'));
  s.recover = true;
  const std::vector<Mod> mods{{path("%s.dat"), "sky", 1}, {path("%s.dat"), "sun", 1}};
  EXPECT_EQ(run(s, mods, 0, 2), 0);
  EXPECT_EQ(warnings.list(),
            (std::vector<std::string>{"missing recover file '" + path("sun.dat") + "'",
                                      "no previous data to recover"}));
  EXPECT_EQ(fs::file_size(dir / "sun.dat"), header_size(dir / "sun.dat") + 2 * 12);
}

TEST_F(Recover, NoOutputFiles) {
  OutputSettings s = settings('f');
  s.recover = true;
  EXPECT_EQ(run(s, {}, 0, 0), 0);
  EXPECT_EQ(warnings.list(), std::vector<std::string>{"no output files to recover"});
}

TEST_F(Recover, OnlyWithR) {
  OutputSettings s = settings('f');
  s.force_open = true;
  radcl::test::write_file(dir / "sky.dat", format_header(s, "") + std::string(24, 'x'));
  Outputs out(s);
  out.add_modifier(path("sky.dat"), "sky", 1);
  std::vector<double> reloaded{1, 2, 3};
  EXPECT_EQ(out.recover(reloaded), 0);
  EXPECT_TRUE(reloaded.empty());
  EXPECT_TRUE(warnings.list().empty());
}

TEST_F(Recover, Errors) {
  auto recover_with = [&](char format, const std::optional<std::string>& spec, int xres = 0,
                          int yres = 0) {
    return error_of([&] {
      OutputSettings s = settings(format);
      s.recover = true;
      s.xres = xres;
      s.yres = yres;
      Outputs out(s);
      out.add_modifier(spec, "sky", 1);
      std::vector<double> reloaded;
      out.recover(reloaded);
    });
  };
  EXPECT_EQ(recover_with('a', path("sky.txt")), "fatal - cannot recover ASCII output");
  EXPECT_EQ(recover_with('f', std::nullopt), "fatal - cannot recover from stdout");
  EXPECT_EQ(recover_with('f', "!cat > " + path("x")), "fatal - cannot recover from command");

  OutputSettings s = settings('d');
  s.xres = 2;
  s.yres = 2;
  run(s, {{path("sky.dat"), "sky", 1}}, 0, 2);
  EXPECT_EQ(recover_with('f', path("sky.dat"), 2, 2),
            "fatal - format mismatch for '" + path("sky.dat") + "'");
  EXPECT_EQ(recover_with('d', path("sky.dat"), 2, 3),
            "fatal - resolution mismatch for '" + path("sky.dat") + "'");
  EXPECT_EQ(recover_with('d', path("sky.dat"), 2, 2), "(no error)");
  radcl::test::write_file(dir / "sky.dat", "#?RADIANCE\nFORMAT=double\n"); // no end of header
  EXPECT_EQ(recover_with('d', path("sky.dat")),
            "fatal - format mismatch for '" + path("sky.dat") + "'");
}

class Reload : public Recover {
protected:
  // A -c 0 run of one record, `first`; then -r reads it back and adds `more`.
  std::vector<double> reload(OutputSettings s, const std::vector<Mod>& mods) {
    s.accumulate = 0;
    s.recover = true;
    Outputs out(s);
    for (const Mod& m : mods)
      out.add_modifier(m.spec, m.name, m.nbins);
    std::vector<double> reloaded;
    EXPECT_EQ(out.recover(reloaded), 0);
    return reloaded;
  }
  void write_once(OutputSettings s, const std::vector<Mod>& mods, std::vector<double> v) {
    s.accumulate = 0;
    s.force_open = true;
    Outputs out(s);
    for (const Mod& m : mods)
      out.add_modifier(m.spec, m.name, m.nbins);
    out.write_record(v);
    out.end_record();
    out.finish();
  }
};

TEST_F(Reload, AsciiTotalsAreReadBackAndRewritten) {
  const OutputSettings s = settings('a');
  const std::vector<Mod> mods{{path("%s.txt"), "sky", 2}, {path("%s.txt"), "sun", 1}};
  write_once(s, mods, {1, 2, 3, 4, 5, 6, 0.5, 0.25, 0.125});
  std::vector<double> totals = reload(s, mods);
  EXPECT_EQ(totals, (std::vector<double>{1, 2, 3, 4, 5, 6, 0.5, 0.25, 0.125}));
  for (double& v : totals)
    v *= 2;
  write_once(s, mods, totals);
  EXPECT_EQ(read_file(dir / "sun.txt"), format_header(s, "MODIFIER=sun\nNCOLS=1\n") +
                                            "1.000000e+00\t5.000000e-01\t2.500000e-01\t\n");
  EXPECT_TRUE(warnings.list().empty());
}

TEST_F(Reload, SharedFloatFile) {
  const OutputSettings s = settings('f');
  const std::vector<Mod> mods{{path("all.dat"), "sky", 2}, {path("all.dat"), "sun", 1}};
  write_once(s, mods, {1, 2, 3, 4, 5, 6, 7, 8, 9});
  EXPECT_EQ(reload(s, mods), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

// RGBE reads back as the centre of each value's interval.
TEST_F(Reload, Pictures) {
  const OutputSettings s = settings('c');
  const std::vector<Mod> mods{{path("%s.hdr"), "sky", 1}};
  write_once(s, mods, {1, 2, 3});
  EXPECT_EQ(reload(s, mods), (std::vector<double>{64.5 / 64, 128.5 / 64, 192.5 / 64}));
}

TEST_F(Reload, MissingAndEmptyFiles) {
  const OutputSettings s = settings('d');
  const std::vector<Mod> mods{{path("%s_%d.dat"), "sky", 2}, {path("%s_%d.dat"), "sun", 1}};
  write_once(s, mods, {1, 2, 3, 4, 5, 6, 7, 8, 9});
  fs::remove(dir / "sky_1.dat"); // the rest of sky is skipped with a warning
  fs::resize_file(dir / "sun_0.dat", header_size(dir / "sun_0.dat")); // ignored
  EXPECT_EQ(reload(s, mods), (std::vector<double>{1, 2, 3, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(warnings.list(),
            std::vector<std::string>{"missing reload file '" + path("sky_1.dat") + "'"});
}

TEST_F(Reload, Errors) {
  auto reload_error = [&](char format, const std::vector<Mod>& mods) {
    return error_of([&] { reload(settings(format), mods); });
  };
  EXPECT_EQ(reload_error('d', {{std::nullopt, "sky", 1}}), "fatal - cannot reload from stdout");
  EXPECT_EQ(reload_error('d', {{"!cat", "sky", 1}}), "fatal - cannot reload from command");
  const std::vector<Mod> mods{{path("b%d.dat"), "sky", 2}};
  write_once(settings('d'), mods, {1, 2, 3, 4, 5, 6});
  EXPECT_EQ(reload_error('f', mods), "fatal - format mismatch for '" + path("b0.dat") + "'");
  fs::resize_file(dir / "b1.dat", header_size(dir / "b1.dat"));
  EXPECT_EQ(reload_error('d', mods), "fatal - missing data in '" + path("b1.dat") + "'");
}
