// Wall time by phase of the renderer's work (RADCL_PROFILE=1 prints it when the renderer ends):
// where a run's time goes on a device we cannot attach a profiler to, such as the lent GPU.
// Device phases are measured from the host, so a blocking read counts the kernels before it.
// Phases nest: a phase's time includes the phases timed inside it.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>

namespace radcl::render {

enum class Phase {
  Trace,       // Embree over a wave's rays, and their hits made device records
  Leaks,       // the cache's leak test on the host
  Shade,       // rc_shade and its slots' transfers
  ShadowTrace, // Embree over shadow-ray steps
  ShadowStep,  // rc_shadow_step and its transfers
  Accumulate,  // rc_accumulate and its transfers
  Choose,      // picking well-spread misses to become records
  Sample,      // a record's hemisphere rays, host side (nested renders excluded)
  Records,     // the record kernel
  Upload,      // the cache's trees rebuilt and uploaded
  Super,       // the -as pass's second shading of a wave's rays (the tally tree's requests)
  Bookkeeping, // a cache-build round's own work: copies of the rays that missed, their slots
  Slots,       // a wave's slot sizes counted (rc_count over a sample of its rays)
  Batch,       // a wave's own host work: primaries set up, queues moved, results summed
  kCount
};

class PhaseProfile {
public:
  PhaseProfile()
      : on_(std::getenv("RADCL_PROFILE") != nullptr), t0_(std::chrono::steady_clock::now()) {}
  bool on() const { return on_; }
  void add(Phase p, double seconds) {
    sec_[static_cast<int>(p)] += seconds;
    ++calls_[static_cast<int>(p)];
  }
  // The phases, then the profile's lifetime and what no phase timed (phases timed inside
  // another are counted twice there, so keep them apart).
  void print(std::FILE* f) const {
    static const char* names[] = {"trace", "leaks",       "shade",  "shadow-trace", "shadow-step",
                                  "accum", "choose",      "sample", "records",      "upload",
                                  "super", "bookkeeping", "slots",  "batch"};
    static_assert(std::size(names) == static_cast<std::size_t>(Phase::kCount));
    for (int i = 0; i < static_cast<int>(Phase::kCount); ++i)
      if (calls_[i])
        std::fprintf(f, "profile: %-12s %9.3f s %8llu calls\n", names[i], sec_[i],
                     static_cast<unsigned long long>(calls_[i]));
    double timed = 0;
    for (double s : sec_)
      timed += s;
    const double life =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    std::fprintf(f, "profile: %-12s %9.3f s\nprofile: %-12s %9.3f s\n", "lifetime", life, "untimed",
                 life - timed);
  }

  // Times one phase for the scope it lives in (nothing when profiling is off).
  class Scope {
  public:
    Scope(PhaseProfile& p, Phase ph) : p_(p.on_ ? &p : nullptr), ph_(ph) {
      if (p_) t0_ = std::chrono::steady_clock::now();
    }
    ~Scope() {
      if (p_)
        p_->add(ph_, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count());
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

  private:
    PhaseProfile* p_;
    Phase ph_;
    std::chrono::steady_clock::time_point t0_{};
  };

private:
  bool on_;
  std::chrono::steady_clock::time_point t0_;
  std::array<double, static_cast<int>(Phase::kCount)> sec_{};
  std::array<std::uint64_t, static_cast<int>(Phase::kCount)> calls_{};
};

} // namespace radcl::render
