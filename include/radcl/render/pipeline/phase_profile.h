// Wall time by phase of the renderer's work (RADCL_PROFILE=1 prints it when the renderer ends):
// where a run's time goes on a device we cannot attach a profiler to, such as the lent GPU.
// Device phases are measured from the host, so a blocking read counts the kernels before it.
// Phases nest: a phase's time includes the phases timed inside it. Each phase also counts the
// process's CPU time (all threads, PoCL's included), so cores = cpu / wall shows which phases
// leave cores idle, and the host's waits for the device in it (device::transfers().waits: on a
// GPU each is a round trip's latency, which small waves are made of).
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <time.h>

#include "radcl/device/buffer.h"
#include "radcl/render/pipeline/tuning.h"

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
  Slots,       // a wave's slot sizes counted (rc_shade counting a sample of its rays)
  Batch,       // a wave's own host work: primaries set up, queues moved, results summed
  Build,       // device programs built (from source, or loaded from the program cache)
  Tally,       // the -as tally tree fed a shaded slice, beside the next slice's shading
  kCount
};

class PhaseProfile {
public:
  explicit PhaseProfile(PipelineTuning::Profile mode = PipelineTuning::Profile::Off)
      : on_(mode != PipelineTuning::Profile::Off), waves_(mode == PipelineTuning::Profile::Waves),
        raw_(mode == PipelineTuning::Profile::Raw), t0_(std::chrono::steady_clock::now()) {}
  bool on() const { return on_; }
  // RADCL_PROFILE=waves: the shading kernel is waited for on its own, and its time and that of
  // the slot reads after it are summed by wave size (the extra wait costs a little).
  bool waves() const { return waves_; }
  void add_wave(std::size_t rays, double kernel, double reads) {
    int b = 0;
    for (std::size_t lim : kWaveBins)
      if (rays >= lim) ++b;
    ++wave_n_[b];
    wave_rays_[b] += rays;
    wave_kernel_[b] += kernel;
    wave_reads_[b] += reads;
  }
  // RADCL_PROFILE=raw: every traced chunk's rays also go through Embree's float traversal
  // alone (SceneGeometry::intersect_raw), untimed by the phases: how far the trace phase is from
  // the machine's limit on the very same rays (best read with RADCL_NO_OVERLAP=1).
  bool raw() const { return raw_; }
  void add_raw(std::size_t rays, double seconds) {
    raw_rays_ += rays;
    raw_sec_ += seconds;
  }
  // RADCL_PROFILE=waves: the host's steps of shading a slice (kStep names), summed.
  // The shadow steps' and the sums' parts are timed at their own waits (none added).
  enum Step {
    StepUpload,
    StepKernel,
    StepCounts,
    StepOffsets,
    StepPack,
    StepChildren,
    StepShadowSend, // a shadow step's hits, slots and states sent, its kernel enqueued
    StepShadowWait, // its wait for the device
    StepShadowHost, // the host's pass over its states (reached, blocked, going on)
    StepSumsWait,   // the sums' wait (rc_accumulate and the totals read back)
    StepSumsTally,  // the -as tally tree fed with the slice (or the plain sums)
    // Its parts (TallyTree::shaded_slice): the pass over each ray's children (their
    // hemispheres counted), the serial offsets, the hemispheres made, the sums and settling.
    StepTallyChildren,
    StepTallyOffsets,
    StepTallyHemis,
    StepTallySettle,
    kSteps
  };
  void add_step(Step s, double seconds) { step_[s] += seconds; }
  // Times consecutive parts of one piece of work under RADCL_PROFILE=waves: each mark() adds
  // the time since the last to its step.
  class StepClock {
  public:
    explicit StepClock(PhaseProfile& p) : p_(p.waves_ ? &p : nullptr) {
      if (p_) at_ = std::chrono::steady_clock::now();
    }
    void mark(Step s) {
      if (!p_) return;
      const auto now = std::chrono::steady_clock::now();
      p_->add_step(s, std::chrono::duration<double>(now - at_).count());
      at_ = now;
    }

  private:
    PhaseProfile* p_;
    std::chrono::steady_clock::time_point at_{};
  };
  // The process's CPU time so far, every thread's.
  static double cpu_now() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }
  void add(Phase p, double seconds, double cpu = 0, std::size_t waits = 0) {
    sec_[static_cast<int>(p)] += seconds;
    cpu_[static_cast<int>(p)] += cpu;
    waits_[static_cast<int>(p)] += waits;
    ++calls_[static_cast<int>(p)];
  }
  // The phases, then the profile's lifetime and what no phase timed (phases timed inside
  // another are counted twice there, so keep them apart).
  void print(std::FILE* f) const {
    static const char* names[] = {
        "trace",   "leaks",  "shade", "shadow-trace", "shadow-step", "accum", "choose", "sample",
        "records", "upload", "super", "bookkeeping",  "slots",       "batch", "build",  "tally"};
    static_assert(std::size(names) == static_cast<std::size_t>(Phase::kCount));
    for (int i = 0; i < static_cast<int>(Phase::kCount); ++i)
      if (calls_[i])
        std::fprintf(
            f, "profile: %-12s %9.3f s %8llu calls  cpu %8.3f s (%.2f cores) %7llu waits\n",
            names[i], sec_[i], static_cast<unsigned long long>(calls_[i]), cpu_[i],
            sec_[i] > 0 ? cpu_[i] / sec_[i] : 0.0, static_cast<unsigned long long>(waits_[i]));
    double timed = 0;
    for (double s : sec_)
      timed += s;
    const double life =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const double cpu = cpu_now() - cpu0_;
    std::fprintf(f, "profile: %-12s %9.3f s %14s cpu %8.3f s (%.2f cores)\n", "lifetime", life, "",
                 cpu, life > 0 ? cpu / life : 0.0);
    std::fprintf(f, "profile: %-12s %9.3f s\n", "untimed", life - timed);
    if (raw_ && raw_sec_ > 0) {
      const double trace = sec_[static_cast<int>(Phase::Trace)];
      const double rays = static_cast<double>(raw_rays_);
      std::fprintf(f,
                   "profile: raw embree  %9.3f s for the %llu traced rays (%.1f M/s); the trace "
                   "phase %.1f M/s, %.2f of it\n",
                   raw_sec_, static_cast<unsigned long long>(raw_rays_), rays / raw_sec_ / 1e6,
                   trace > 0 ? rays / trace / 1e6 : 0.0, trace > 0 ? raw_sec_ / trace : 0.0);
    }
    static const char* steps[] = {
        "shade step upload", "shade step kernel",   "shade step counts", "shade step offsets",
        "shade step pack",   "shade step children", "shadow step send",  "shadow step wait",
        "shadow step host",  "accum wait",          "accum tally",       "  tally children",
        "  tally offsets",   "  tally hemispheres", "  tally settling"};
    static_assert(std::size(steps) == kSteps);
    if (waves_)
      for (int i = 0; i < kSteps; ++i)
        std::fprintf(f, "profile: %-20s %9.3f s\n", steps[i], step_[i]);
    for (std::size_t b = 0; b < wave_n_.size(); ++b)
      if (wave_n_[b])
        std::fprintf(
            f,
            "profile: waves from %6zu rays: %6llu, %9llu rays, kernel %.3f s, reads "
            "%.3f s\n",
            b ? kWaveBins[b - 1] : std::size_t{0}, static_cast<unsigned long long>(wave_n_[b]),
            static_cast<unsigned long long>(wave_rays_[b]), wave_kernel_[b], wave_reads_[b]);
  }

  // Times one phase for the scope it lives in (nothing when profiling is off); stop() ends it
  // early, start() goes on with another phase.
  class Scope {
  public:
    Scope(PhaseProfile& p, Phase ph) : p_(p.on_ ? &p : nullptr) { start(ph); }
    ~Scope() { stop(); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
    void start(Phase ph) {
      stop();
      ph_ = ph;
      running_ = p_ != nullptr;
      if (running_) {
        t0_ = std::chrono::steady_clock::now();
        c0_ = cpu_now();
        w0_ = device::transfers().waits;
      }
    }
    void stop() {
      if (running_)
        p_->add(ph_, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(),
                cpu_now() - c0_, device::transfers().waits - w0_);
      running_ = false;
    }

  private:
    PhaseProfile* p_;
    Phase ph_ = Phase::kCount;
    bool running_ = false;
    std::chrono::steady_clock::time_point t0_{};
    double c0_ = 0;
    std::size_t w0_ = 0;
  };

private:
  static constexpr std::array<std::size_t, 5> kWaveBins{64, 256, 1024, 8192, 65536};
  bool on_, waves_, raw_;
  std::uint64_t raw_rays_ = 0;
  double raw_sec_ = 0;
  std::array<std::uint64_t, 6> wave_n_{}, wave_rays_{};
  std::array<double, 6> wave_kernel_{}, wave_reads_{};
  std::array<double, kSteps> step_{};
  std::chrono::steady_clock::time_point t0_;
  double cpu0_ = cpu_now();
  std::array<double, static_cast<int>(Phase::kCount)> sec_{}, cpu_{};
  std::array<std::size_t, static_cast<int>(Phase::kCount)> waits_{};
  std::array<std::uint64_t, static_cast<int>(Phase::kCount)> calls_{};
};

} // namespace radcl::render
