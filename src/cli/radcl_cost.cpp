// radcl cost: what accuracy costs in time, for the user's own scene (docs/cost.md).
//   radcl cost [cost options] [rtrace options] OCTREE < sensors
//   radcl cost [cost options] -vf view -x X -y Y [rpict options] OCTREE
// Option parsing and the printed report live here; the study itself in src/cost/.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "cost_report.h"
#include "radcl/cost/study.h"
#include "radcl/util/error.h"
#include "radcl/util/program_folder.h"
#include "radcl_commands.h"

namespace radcl::cli {
namespace {

double parse_fraction(const std::string& opt, const std::string& s) {
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || (*end && std::string(end) != "%") || !(v > 0))
    throw FatalError("bad value \"" + s + "\" for " + opt + " (a percentage, as 2%)");
  return v / 100;
}

int parse_int(const std::string& opt, const std::string& s, int least) {
  char* end = nullptr;
  long v = std::strtol(s.c_str(), &end, 10);
  if (end == s.c_str() || *end || v < least || v > 1 << 24)
    throw FatalError("bad value \"" + s + "\" for " + opt);
  return static_cast<int>(v);
}

// The ambient options the ladder sets itself: the user's are dropped, with a warning.
bool ladder_sets(const std::string& a) {
  return a == "-aa" || a == "-ad" || a == "-as" || a == "-ar" || a == "-lw";
}

// A folder for the runs, removed with everything in it at the end.
struct WorkFolder {
  std::string path;
  WorkFolder() {
    const char* t = std::getenv("TMPDIR");
    std::string tmpl = std::string(t && *t ? t : "/tmp") + "/radcl-cost-XXXXXX";
    if (!::mkdtemp(tmpl.data())) throw FatalError("cannot make a temporary folder");
    path = tmpl;
  }
  ~WorkFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

} // namespace

int cmd_cost(int argc, char** argv) {
  cost::StudyOptions o;
  CostOutputs out;
  std::string ladder = "all";
  int ab = 5;
  bool ab_given = false, ref_ab_given = false, ref_se_given = false, metric_given = false;
  char in_format = 'a';
  o.nproc = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (const char* r = std::getenv("RADIANCE_BIN")) o.radiance_bin = r;
  std::vector<std::string> words(argv + 1, argv + argc);
  if (words.empty()) throw FatalError("missing octree argument (radcl cost [options] octree)");
  o.octree = words.back();
  words.pop_back();
  if (o.octree.empty() || o.octree[0] == '-')
    throw FatalError("missing octree argument (radcl cost [options] octree)");
  if (!std::filesystem::is_regular_file(o.octree))
    throw FatalError("cannot open octree \"" + o.octree + "\"");
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& a = words[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= words.size()) throw FatalError("missing value for " + a);
      return words[++i];
    };
    if (a == "-target") {
      o.target = parse_fraction(a, value());
    } else if (a == "-metric") {
      o.metric = cost::parse_metric(value());
      metric_given = true;
    } else if (a == "-ref") {
      o.ref_file = value();
    } else if (a == "-save-ref") {
      out.save_ref = value();
    } else if (a == "-ref-se") {
      o.ref_se = parse_fraction(a, value());
      ref_se_given = true;
    } else if (a == "-ref-ab") {
      o.ref_ab = parse_int(a, value(), 1);
      ref_ab_given = true;
    } else if (a == "-ref-ad") {
      o.ref_ad = parse_int(a, value(), 16);
    } else if (a == "-ref-time") {
      o.ref_seconds = parse_int(a, value(), 1);
    } else if (a == "-ladder") {
      ladder = value();
    } else if (a == "-svg") {
      out.svg = value();
    } else if (a == "-tsv") {
      out.tsv = value();
    } else if (a == "-block") {
      o.block = parse_int(a, value(), 1);
    } else if (a == "-seed") {
      o.seed = static_cast<std::uint32_t>(parse_int(a, value(), 0));
    } else if (a == "-n") {
      o.nproc = parse_int(a, value(), 1);
    } else if (a == "-radiance") {
      o.radiance_bin = value();
    } else if (a == "-ab") {
      ab = parse_int(a, value(), 1);
      ab_given = true;
    } else if (ladder_sets(a)) {
      warning(a + " " + value() + " ignored: the ladder sets it");
    } else if (a.rfind("-o", 0) == 0 && a != "-o") {
      throw FatalError(a + ": radcl cost chooses the outputs itself");
    } else if (a.size() >= 3 && a.size() <= 4 && a.rfind("-f", 0) == 0 &&
               std::string("afd").find(a[2]) != std::string::npos) {
      // rtrace's -f<in><out>: any input format, but the values are read back as text.
      if (a.size() == 4 && a[3] != 'a')
        throw FatalError(a + ": radcl cost reads the values as text (-f" + a[2] + "a)");
      in_format = a[2];
      o.pass.push_back(a);
    } else if (a.rfind("-v", 0) == 0 || a == "-x" || a == "-y" || a == "-pa" || a == "-pj") {
      // rpict's view and size: pictures. Their values follow (a -vX option takes 1 or 3).
      o.view.push_back(a);
      const int n = a == "-vp" || a == "-vd" || a == "-vu" ? 3
                    : a == "-vf" || a == "-vh" || a == "-vv" || a == "-vo" || a == "-va" ||
                            a == "-vs" || a == "-vl" || a == "-x" || a == "-y" || a == "-pa" ||
                            a == "-pj"
                        ? 1
                        : 0;
      for (int k = 0; k < n; ++k)
        o.view.push_back(value());
    } else {
      o.pass.push_back(a); // the renderer's own, with its values
    }
  }
  if (!ab_given) ab = 5;
  if (!ref_ab_given) o.ref_ab = ab + 3;
  if (!ref_se_given) o.ref_se = o.target / 5;
  if (!metric_given && o.pictures()) o.metric = cost::Metric::Rms;
  if (!out.save_ref.empty() && o.pictures())
    throw FatalError("-save-ref is for sensors (a picture's reference is kept in blocks only)");
  o.ladder = cost::make_ladder(ab, cost::parse_families(ladder));
  o.radcl_bin = program_folder();
  if (o.radcl_bin.empty()) throw FatalError("cannot find radcl's own folder");
  WorkFolder work;
  o.work = work.path;
  if (!o.pictures()) {
    if (::isatty(0)) throw FatalError("give the sensors on standard input (as for rtrace)");
    o.sensors = o.work + "/sensors";
    std::ofstream s(o.sensors, std::ios::binary);
    s << std::cin.rdbuf();
    if (!s.flush()) throw FatalError("cannot store the sensors");
    // The warm-up runs take the first 256 sensors: lines, or binary records of 6 numbers.
    std::ifstream all(o.sensors, std::ios::binary);
    std::string first;
    if (in_format == 'a') {
      std::string line;
      for (int k = 0; k < 256 && std::getline(all, line); ++k)
        first += line + "\n";
    } else {
      first.resize(256 * (in_format == 'f' ? 24 : 48));
      all.read(first.data(), static_cast<std::streamsize>(first.size()));
      first.resize(static_cast<std::size_t>(all.gcount()));
    }
    std::ofstream(o.work + "/first-sensors", std::ios::binary) << first;
  }
  CostProgress bar;
  const cost::StudyReport rep = cost::run_study(
      o, [&](const std::string& what, double done, double left) { bar.show(what, done, left); });
  bar.clear();
  write_report(o, rep, out);
  return 0;
}

} // namespace radcl::cli
