// `radcl cost`: what accuracy costs in time on the user's own scene. A converged reference is
// made (or read), then every step of the ladder is run by radcl's rtrace (or rpict) and, when
// Radiance's programs are named, by Radiance's, each timed and scored against the reference;
// the fastest radcl settings that meet the error target are run again with another seed to
// confirm them.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "radcl/cost/ladder.h"
#include "radcl/cost/score.h"

namespace radcl::cost {

struct StudyOptions {
  std::string octree;
  std::vector<std::string> pass; // the user's other renderer options, given to every run
  std::string sensors;           // rtrace's input (a file), for sensors
  std::vector<std::string> view; // rpict's view and size options: pictures instead of sensors
  int block = 8;                 // pictures are scored in blocks of block x block pixels
  int ref_ab = 8;                // the converged reference's -ab
  int ref_ad = 4096;             // its first run's -ad (later runs double the paths)
  double ref_se = 0.004;         // its aim: standard error (p95 of the sensors; rms of blocks)
  double ref_seconds = 0;        // stop refining it after this long (0: no limit)
  int ref_max_runs = 64;
  std::string ref_file; // a reference the user gives instead (text rgb, or a picture)
  std::vector<Step> ladder;
  double target = 0.02;
  Metric metric = Metric::P95;
  std::uint32_t seed = 1;   // RADCL_SEED of the ladder's runs (confirmation: seed + 1)
  int nproc = 1;            // rtrace -n for radcl and Radiance
  std::string radcl_bin;    // the folder with radcl's rtrace and rpict
  std::string radiance_bin; // Radiance's, or empty
  std::string work;         // a folder for the runs' files
  bool pictures() const { return !view.empty(); }
};

struct Run {
  std::string renderer; // "radcl" or "Radiance"
  Step step;
  double seconds = 0;
  Score score;
  bool pareto = false; // on its renderer's front
};

struct Reference {
  std::string how;                            // a line saying how it was made
  std::size_t elements = 0;                   // sensors, or blocks
  double seconds = 0;                         // time spent making it
  double se_mean = 0, se_p95 = 0, se_rms = 0; // its relative standard errors (0: unknown)
  std::vector<Rgb> values, std_error;         // per sensor or block (std_error may be empty)
};

struct StudyReport {
  Reference reference;
  std::vector<Run> runs;
  std::optional<std::size_t> recommended; // index into runs
  Score confirmed;                        // the recommended settings, another seed
  double confirmed_seconds = 0;
  std::vector<std::size_t> rejected; // recommended first, failed on the second seed
};

// What the study is doing: a line, the fraction of the ladder done and an estimate of the
// seconds left (negative: unknown).
using ProgressFn = std::function<void(const std::string& what, double done, double left)>;

StudyReport run_study(const StudyOptions& o, const ProgressFn& progress);

} // namespace radcl::cost
