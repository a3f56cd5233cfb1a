// How far a run's values are from the reference: per sensor (or per block of a reduced
// picture) the relative luminance error, summarised as the mean, the 95th percentile, the
// worst and the root mean square.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace radcl::cost {

using Rgb = std::array<double, 3>;

struct Score {
  double mean = 0, p95 = 0, worst = 0, rms = 0;
  std::size_t counted = 0; // sensors or blocks scored
};

enum class Metric { Mean, P95, Worst, Rms };
// "mean", "p95", "max" or "rms"; throws FatalError otherwise.
Metric parse_metric(const std::string& name);
const char* metric_name(Metric m);
double pick(const Score& s, Metric m);

// |L(v) - L(ref)| / L(ref) per element, L the luminance weights' sum. Elements whose
// reference is darker than 1e-9 of the brightest are left out: a relative error means nothing
// there (a sensor in shadow of everything). Throws FatalError when the lengths differ.
std::vector<double> relative_errors(std::span<const Rgb> values, std::span<const Rgb> reference);

// The summary of `errors` (the 95th percentile by nearest rank).
Score summarise(std::vector<double> errors);

// Which points are on the Pareto front of (time, error): no other point is as fast and as
// accurate with one of the two strictly better.
std::vector<bool> pareto_front(std::span<const double> seconds, std::span<const double> error);

// The fastest point whose error is at most `target`; none if no point meets it.
std::optional<std::size_t> fastest_within(std::span<const double> seconds,
                                          std::span<const double> error, double target);

} // namespace radcl::cost
