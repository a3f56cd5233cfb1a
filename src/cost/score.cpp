#include "radcl/cost/score.h"

#include <algorithm>
#include <cmath>

#include "radcl/luminance.h"
#include "radcl/util/error.h"

namespace radcl::cost {

Metric parse_metric(const std::string& name) {
  if (name == "mean") return Metric::Mean;
  if (name == "p95") return Metric::P95;
  if (name == "max") return Metric::Worst;
  if (name == "rms") return Metric::Rms;
  throw FatalError("unknown error metric \"" + name + "\" (mean, p95, max or rms)");
}

const char* metric_name(Metric m) {
  switch (m) {
  case Metric::Mean:
    return "mean";
  case Metric::P95:
    return "p95";
  case Metric::Worst:
    return "max";
  case Metric::Rms:
    return "rms";
  }
  return "?";
}

double pick(const Score& s, Metric m) {
  switch (m) {
  case Metric::Mean:
    return s.mean;
  case Metric::P95:
    return s.p95;
  case Metric::Worst:
    return s.worst;
  case Metric::Rms:
    return s.rms;
  }
  return s.p95;
}

std::vector<double> relative_errors(std::span<const Rgb> values, std::span<const Rgb> reference) {
  if (values.size() != reference.size())
    throw FatalError("a run gave " + std::to_string(values.size()) + " values for " +
                     std::to_string(reference.size()) + " reference values");
  double brightest = 0;
  for (const Rgb& r : reference)
    brightest = std::max(brightest, bright(r));
  std::vector<double> e;
  e.reserve(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double b = bright(reference[i]);
    if (!(b > 1e-9 * brightest)) continue;
    e.push_back(std::fabs(bright(values[i]) - b) / b);
  }
  return e;
}

Score summarise(std::vector<double> errors) {
  Score s;
  s.counted = errors.size();
  if (errors.empty()) return s;
  double sum = 0, sq = 0;
  for (double e : errors) {
    sum += e;
    sq += e * e;
  }
  std::sort(errors.begin(), errors.end());
  s.mean = sum / errors.size();
  s.rms = std::sqrt(sq / errors.size());
  s.worst = errors.back();
  // Nearest rank: the smallest error at least 95% of the elements do not exceed.
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * errors.size()));
  s.p95 = errors[std::max<std::size_t>(rank, 1) - 1];
  return s;
}

std::vector<bool> pareto_front(std::span<const double> seconds, std::span<const double> error) {
  std::vector<bool> front(seconds.size(), true);
  for (std::size_t i = 0; i < seconds.size(); ++i)
    for (std::size_t j = 0; j < seconds.size() && front[i]; ++j)
      if (j != i && seconds[j] <= seconds[i] && error[j] <= error[i] &&
          (seconds[j] < seconds[i] || error[j] < error[i]))
        front[i] = false;
  return front;
}

std::optional<std::size_t> fastest_within(std::span<const double> seconds,
                                          std::span<const double> error, double target) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < seconds.size(); ++i)
    if (error[i] <= target && (!best || seconds[i] < seconds[*best])) best = i;
  return best;
}

} // namespace radcl::cost
