#include "radcl/cost/pool.h"

#include <algorithm>
#include <cmath>

#include "radcl/luminance.h"
#include "radcl/util/error.h"

namespace radcl::cost {

namespace {

void check_size(std::size_t have, std::size_t add) {
  if (have != 0 && have != add)
    throw FatalError("a reference run gave " + std::to_string(add) + " values for " +
                     std::to_string(have));
}

// The relative error of each element's luminance, in the elements relative_errors() keeps.
std::vector<double> relative(const std::vector<Rgb>& mean, const std::vector<Rgb>& se) {
  double brightest = 0;
  for (const Rgb& m : mean)
    brightest = std::max(brightest, bright(m));
  std::vector<double> out;
  for (std::size_t i = 0; i < mean.size(); ++i) {
    const double b = bright(mean[i]);
    if (!(b > 1e-9 * brightest)) continue;
    // The channels' errors move together (one path carries all three), so their weighted sum
    // is taken: the most the luminance's error can be.
    out.push_back(bright(se[i]) / b);
  }
  return out;
}

} // namespace

void PathPool::add(std::span<const Rgb> values, std::span<const Rgb> std_error, double paths) {
  check_size(sum_.size(), values.size());
  if (std_error.size() != values.size()) throw FatalError("standard errors missing from a run");
  sum_.resize(values.size(), Rgb{});
  var_.resize(values.size(), Rgb{});
  for (std::size_t i = 0; i < values.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      sum_[i][c] += paths * values[i][c];
      var_[i][c] += paths * paths * std_error[i][c] * std_error[i][c];
    }
  weight_ += paths;
  ++runs_;
}

std::vector<Rgb> PathPool::mean() const {
  std::vector<Rgb> m(sum_.size());
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int c = 0; c < 3; ++c)
      m[i][c] = sum_[i][c] / weight_;
  return m;
}

std::vector<Rgb> PathPool::std_error() const {
  std::vector<Rgb> s(var_.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int c = 0; c < 3; ++c)
      s[i][c] = std::sqrt(var_[i][c]) / weight_;
  return s;
}

std::vector<double> PathPool::relative_std_error() const {
  return relative(mean(), std_error());
}

void RunPool::add(std::span<const Rgb> values) {
  check_size(sum_.size(), values.size());
  sum_.resize(values.size(), Rgb{});
  sq_.resize(values.size(), Rgb{});
  for (std::size_t i = 0; i < values.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      sum_[i][c] += values[i][c];
      sq_[i][c] += values[i][c] * values[i][c];
    }
  ++runs_;
}

std::vector<Rgb> RunPool::mean() const {
  std::vector<Rgb> m(sum_.size());
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int c = 0; c < 3; ++c)
      m[i][c] = sum_[i][c] / runs_;
  return m;
}

std::vector<Rgb> RunPool::std_error() const {
  std::vector<Rgb> s(sum_.size(), Rgb{});
  if (runs_ < 2) return s;
  const double n = runs_;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double m = sum_[i][c] / n;
      const double var = std::max(0.0, (sq_[i][c] - n * m * m) / (n - 1));
      s[i][c] = std::sqrt(var / n);
    }
  return s;
}

std::vector<double> RunPool::relative_std_error() const {
  return relative(mean(), std_error());
}

} // namespace radcl::cost
