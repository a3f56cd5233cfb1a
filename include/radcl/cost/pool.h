// The converged reference, pooled from independent -aa 0 runs.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "radcl/cost/score.h"

namespace radcl::cost {

// Sensor runs, each with its own standard errors (rtrace -oe), weighed by their paths per
// sensor: the weights do not depend on the values, so the pooled mean stays unbiased (weighing
// by the inverse variance would pull it towards the darker draws, whose errors are smaller).
class PathPool {
public:
  // One run's values and standard errors, with its -ad as the weight.
  void add(std::span<const Rgb> values, std::span<const Rgb> std_error, double paths);
  std::vector<Rgb> mean() const;
  std::vector<Rgb> std_error() const;
  // The relative standard error of each sensor's luminance (left out where the mean is
  // darker than 1e-9 of the brightest, as relative_errors() does).
  std::vector<double> relative_std_error() const;
  double paths() const { return weight_; }
  int runs() const { return runs_; }

private:
  std::vector<Rgb> sum_, var_; // sum of w v and of w^2 se^2
  double weight_ = 0;
  int runs_ = 0;
};

// Picture runs of equal weight, without standard errors of their own: the error of their mean
// comes from their spread (at least two runs).
class RunPool {
public:
  void add(std::span<const Rgb> values);
  std::vector<Rgb> mean() const;
  std::vector<Rgb> std_error() const; // zero with fewer than two runs
  std::vector<double> relative_std_error() const;
  int runs() const { return runs_; }

private:
  std::vector<Rgb> sum_, sq_;
  int runs_ = 0;
};

} // namespace radcl::cost
