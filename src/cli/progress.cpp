#include "progress.h"

#include <cstdio>
#include <sys/resource.h>
#include <unistd.h>

namespace radcl::cli {

Progress::Progress(std::string program, int interval)
    : program_(std::move(program)), interval_(interval), bar_(interval > 0 && ::isatty(2)),
      start_(std::chrono::steady_clock::now()), last_report_(start_), last_bar_(start_) {}

// Radiance's report: user and system CPU time (children included) and real time, in hours.
void Progress::report(double fraction, std::uint64_t rays) {
  rusage self{}, kids{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &kids);
  auto secs = [](const timeval& a, const timeval& b) {
    return a.tv_sec + b.tv_sec + (a.tv_usec + b.tv_usec) * 1e-6;
  };
  double real = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char host[256] = "localhost";
  gethostname(host, sizeof host - 1);
  if (bar_) std::fputs("\r\033[K", stderr);
  std::fprintf(stderr, "%s: %lu rays, %4.2f%% after %.3fu %.3fs %.3fr hours on %s (PID %d)\n",
               program_.c_str(), static_cast<unsigned long>(rays), 100.0 * fraction,
               secs(self.ru_utime, kids.ru_utime) / 3600.0,
               secs(self.ru_stime, kids.ru_stime) / 3600.0, real / 3600.0, host,
               static_cast<int>(getpid()));
}

void Progress::draw(double fraction, std::uint64_t rays) {
  double real = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double rate = real > 0 ? rays / real : 0;
  double left = fraction > 0 ? real * (1 - fraction) / fraction : 0;
  const int width = 30;
  int filled = static_cast<int>(fraction * width + 0.5);
  std::string bar(filled, '#');
  bar.resize(width, '.');
  std::fprintf(stderr, "\r\033[K[%s] %5.1f%%  %.3g rays/s  %.0f s left", bar.c_str(),
               100 * fraction, rate, left);
  std::fflush(stderr);
}

void Progress::update(double fraction, std::uint64_t rays, bool force) {
  if (interval_ <= 0) return;
  auto now = std::chrono::steady_clock::now();
  if (force || now - last_report_ >= std::chrono::seconds(interval_)) {
    report(fraction, rays);
    last_report_ = now;
  }
  if (bar_ && now - last_bar_ >= std::chrono::milliseconds(200)) {
    draw(fraction, rays);
    last_bar_ = now;
  }
}

void Progress::finish(std::uint64_t rays) {
  if (interval_ <= 0) return;
  report(1.0, rays);
}

} // namespace radcl::cli
