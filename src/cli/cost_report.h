// What `radcl cost` prints and writes: the progress bar on a terminal, the table of runs, the
// recommendation, the TSV and the SVG chart.
#pragma once

#include <chrono>
#include <string>

#include "radcl/cost/study.h"

namespace radcl::cli {

struct CostOutputs {
  std::string svg, tsv; // files to write ("": none)
  std::string save_ref; // the reference's values and standard errors, for -ref next time
};

// A one-line bar on standard error, drawn only when it is a terminal.
class CostProgress {
public:
  CostProgress();
  void show(const std::string& what, double done, double seconds_left);
  void clear();

private:
  bool tty_;
  std::chrono::steady_clock::time_point start_;
};

void write_report(const cost::StudyOptions& o, const cost::StudyReport& r, const CostOutputs& out);

} // namespace radcl::cli
