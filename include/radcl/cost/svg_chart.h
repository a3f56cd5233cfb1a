// The error-against-time chart `radcl cost` writes: log-log, one circle per run (its settings
// in a tooltip), each renderer's Pareto front joined by a line, the error target dashed.
#pragma once

#include <string>
#include <vector>

namespace radcl::cost {

struct ChartPoint {
  double seconds = 0, error = 0; // error as a fraction (0.02 = 2%)
  std::string label;             // the run's settings
  bool pareto = false;
};

struct ChartSeries {
  std::string name;   // "radcl", "Radiance"
  std::string colour; // an SVG colour
  std::vector<ChartPoint> points;
};

struct Chart {
  std::string title, y_label;
  std::vector<ChartSeries> series;
  double target = 0;           // drawn where > 0
  int recommended_series = -1; // the recommended run, ringed
  std::size_t recommended_point = 0;
};

// A standalone SVG document (no scripts, no external files). Points with a time or an error
// of zero or less sit on the axis's lower edge.
std::string render_svg(const Chart& chart);

} // namespace radcl::cost
