#include "radcl/cost/study.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <sstream>

#include "radcl/cost/pool.h"
#include "radcl/cost/renders.h"
#include "radcl/util/error.h"

namespace radcl::cost {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string percent(double f) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f%%", 100 * f);
  return b;
}

// The seconds left of the ladder, from the seconds per unit of cost_hint of the runs so far
// (per renderer and family; a family not yet run takes its renderer's overall rate).
class Estimate {
public:
  void done(const std::string& who, const Step& s, double seconds) {
    auto& f = rate_[who + "/" + s.family];
    auto& a = rate_[who];
    f.first += seconds;
    f.second += s.cost_hint;
    a.first += seconds;
    a.second += s.cost_hint;
  }
  double left(const std::vector<std::pair<std::string, const Step*>>& todo) const {
    double t = 0;
    for (const auto& [who, s] : todo) {
      auto f = rate_.find(who + "/" + s->family);
      if (f == rate_.end()) f = rate_.find(who);
      if (f == rate_.end()) f = rate_.find("radcl");
      if (f == rate_.end() || f->second.second <= 0) return -1;
      t += s->cost_hint * f->second.first / f->second.second;
    }
    return t;
  }

private:
  std::map<std::string, std::pair<double, double>> rate_; // seconds, cost units
};

// The converged reference from rtrace -aa 0 -oe runs, each with as many paths as all before
// it (the first with ref_ad), pooled by paths, until the 95th percentile of the sensors'
// relative standard errors meets ref_se.
std::vector<Rgb> sensor_reference(const StudyOptions& o, Reference& ref, const ProgressFn& pr) {
  PathPool pool;
  const auto start = Clock::now();
  double se = 0;
  for (int k = 0; k < o.ref_max_runs; ++k) {
    const int ad = static_cast<int>(std::min(65536.0, k == 0 ? o.ref_ad : pool.paths()));
    RenderJob job;
    job.settings = {"-u+", "-aa", "0",   "-ab", std::to_string(o.ref_ab), "-ad", std::to_string(ad),
                    "-as", "0",   "-lw", "1e-4"};
    job.seed = 1000003u + static_cast<std::uint32_t>(k);
    job.std_error = true;
    if (pr)
      pr("reference run " + std::to_string(k + 1) + " (-ad " + std::to_string(ad) +
             (k ? ", standard error " + percent(se) + ", aim " + percent(o.ref_se) : "") + ")",
         0, -1);
    RenderOutput out = render(o, job);
    pool.add(out.values, out.std_error, ad);
    const Score s = summarise(pool.relative_std_error());
    se = s.p95;
    ref.se_mean = s.mean;
    ref.se_p95 = s.p95;
    ref.se_rms = s.rms;
    if (se <= o.ref_se || (o.ref_seconds > 0 && since(start) > o.ref_seconds)) break;
  }
  ref.seconds = since(start);
  ref.std_error = pool.std_error();
  ref.how = std::to_string(pool.runs()) + " runs of radcl rtrace -aa 0 -ab " +
            std::to_string(o.ref_ab) + " -as 0 -lw 1e-4, " +
            std::to_string(static_cast<long long>(pool.paths())) + " paths per sensor in all";
  return pool.mean();
}

// The same for pictures: rpict -aa 0 -ps 1 renders of equal paths, their blocks' error from
// the renders' spread; the number of renders doubles until the blocks' rms relative standard
// error meets ref_se.
std::vector<Rgb> picture_reference(const StudyOptions& o, Reference& ref, const ProgressFn& pr) {
  RunPool pool;
  const auto start = Clock::now();
  double se = 0;
  for (int k = 0; k < o.ref_max_runs; ++k) {
    RenderJob job;
    job.settings = {"-u+",
                    "-ps",
                    "1",
                    "-aa",
                    "0",
                    "-ab",
                    std::to_string(o.ref_ab),
                    "-ad",
                    std::to_string(o.ref_ad),
                    "-as",
                    "0",
                    "-lw",
                    "1e-4"};
    job.seed = 1000003u + static_cast<std::uint32_t>(k);
    if (pr)
      pr("reference render " + std::to_string(k + 1) +
             (k > 1 ? " (standard error " + percent(se) + ", aim " + percent(o.ref_se) + ")" : ""),
         0, -1);
    pool.add(render(o, job).values);
    if (pool.runs() < 2) continue;
    const Score s = summarise(pool.relative_std_error());
    se = s.rms;
    ref.se_mean = s.mean;
    ref.se_p95 = s.p95;
    ref.se_rms = s.rms;
    // Whole doublings only: 2, 4, 8, ... renders.
    const bool power = (pool.runs() & (pool.runs() - 1)) == 0;
    if (power && (se <= o.ref_se || (o.ref_seconds > 0 && since(start) > o.ref_seconds))) break;
  }
  ref.seconds = since(start);
  ref.std_error = pool.std_error();
  ref.how = std::to_string(pool.runs()) + " renders of radcl rpict -aa 0 -ps 1 -ab " +
            std::to_string(o.ref_ab) + " -ad " + std::to_string(o.ref_ad) + " -as 0 -lw 1e-4";
  return pool.mean();
}

std::vector<Rgb> given_reference(const StudyOptions& o, Reference& ref) {
  ref.how = "read from " + o.ref_file;
  if (o.pictures()) return picture_blocks(o.ref_file, o.block);
  // Three numbers per line, or six (the last three their standard errors).
  std::ifstream probe(o.ref_file);
  std::string first;
  while (std::getline(probe, first) && first.find_first_not_of(" \t\r") == std::string::npos) {
  }
  std::istringstream w(first);
  int n = 0;
  for (double x; w >> x;)
    ++n;
  std::vector<Rgb> se;
  std::vector<Rgb> v = read_values(o.ref_file, n == 6 ? 6 : 3, n == 6 ? &se : nullptr);
  if (n == 6) {
    ref.std_error = se;
    PathPool p;
    p.add(v, se, 1);
    const Score s = summarise(p.relative_std_error());
    ref.se_mean = s.mean;
    ref.se_p95 = s.p95;
    ref.se_rms = s.rms;
  }
  return v;
}

} // namespace

StudyReport run_study(const StudyOptions& o, const ProgressFn& progress) {
  StudyReport rep;
  const std::vector<Rgb> reference = !o.ref_file.empty() ? given_reference(o, rep.reference)
                                     : o.pictures() ? picture_reference(o, rep.reference, progress)
                                                    : sensor_reference(o, rep.reference, progress);
  rep.reference.elements = reference.size();
  rep.reference.values = reference;
  if (summarise(relative_errors(reference, reference)).counted == 0)
    throw FatalError("the reference is black everywhere: nothing to measure errors against");

  std::vector<std::pair<std::string, const Step*>> todo;
  for (const Step& s : o.ladder) {
    todo.emplace_back("radcl", &s);
    if (!o.radiance_bin.empty()) todo.emplace_back("Radiance", &s);
  }
  // radcl compiles each scene's programs once per set of settings and keeps them (its program
  // cache; PoCL compiles again for each work-group size it meets): a first run of every step
  // on 256 sensors (a 32 x 32 picture), untimed, so the timed runs are what a user's second run
  // of those settings costs (with one sensor, PoCL's first timed run on 2 cores still took 1.4
  // s more than its second).
  if (progress) progress("compiling radcl's programs for each step", 0, -1);
  for (const Step& s : o.ladder) {
    RenderJob job;
    job.settings = s.options;
    job.warm_up = true;
    render(o, job);
  }
  Estimate eta;
  for (std::size_t k = 0; k < todo.size(); ++k) {
    const auto& [who, step] = todo[k];
    if (progress)
      progress(who + " " + step->label(), static_cast<double>(k) / todo.size(),
               eta.left({todo.begin() + static_cast<long>(k), todo.end()}));
    RenderJob job;
    job.radiance = who == "Radiance";
    job.settings = step->options;
    job.seed = o.seed;
    const RenderOutput out = render(o, job);
    eta.done(who, *step, out.seconds);
    rep.runs.push_back(
        Run{who, *step, out.seconds, summarise(relative_errors(out.values, reference))});
  }
  // Fronts and the recommendation, per renderer.
  for (const std::string who : {"radcl", "Radiance"}) {
    std::vector<std::size_t> idx;
    std::vector<double> t, e;
    for (std::size_t i = 0; i < rep.runs.size(); ++i)
      if (rep.runs[i].renderer == who) {
        idx.push_back(i);
        t.push_back(rep.runs[i].seconds);
        e.push_back(pick(rep.runs[i].score, o.metric));
      }
    const std::vector<bool> front = pareto_front(t, e);
    for (std::size_t j = 0; j < idx.size(); ++j)
      rep.runs[idx[j]].pareto = front[j];
    if (who != std::string("radcl")) continue;
    // The fastest settings within the target, confirmed with another seed; a candidate that
    // fails there gives way to the next fastest.
    while (auto best = fastest_within(t, e, o.target)) {
      const Run& cand = rep.runs[idx[*best]];
      if (progress) progress("confirming " + cand.step.label() + " with another seed", 1, -1);
      RenderJob job;
      job.settings = cand.step.options;
      job.settings.push_back("-u+");
      job.seed = o.seed + 1;
      const RenderOutput out = render(o, job);
      const Score s = summarise(relative_errors(out.values, reference));
      if (pick(s, o.metric) <= o.target) {
        rep.recommended = idx[*best];
        rep.confirmed = s;
        rep.confirmed_seconds = out.seconds;
        break;
      }
      rep.rejected.push_back(idx[*best]);
      e[*best] = 1e300; // out of the running
    }
  }
  return rep;
}

} // namespace radcl::cost
