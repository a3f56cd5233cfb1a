// rpict's progress: Radiance's -t report lines on stderr, and on a terminal a live bar with
// rays per second and time left.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace radcl::cli {

class Progress {
public:
  // interval: -t seconds (0: no reports and no bar).
  Progress(std::string program, int interval);
  // Called as work advances: fraction done in [0,1], rays traced so far.
  void update(double fraction, std::uint64_t rays, bool force = false);
  void finish(std::uint64_t rays); // the 100% report, and clears the bar

private:
  std::string program_;
  int interval_;
  bool bar_;
  std::chrono::steady_clock::time_point start_, last_report_, last_bar_;
  void report(double fraction, std::uint64_t rays);
  void draw(double fraction, std::uint64_t rays);
};

} // namespace radcl::cli
