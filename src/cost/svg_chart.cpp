#include "radcl/cost/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace radcl::cost {

namespace {

constexpr double kWidth = 720, kHeight = 480;
constexpr double kLeft = 80, kRight = 180, kTop = 40, kBottom = 60; // margins

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

std::string escape(std::string_view s) {
  std::string o;
  for (char c : s) {
    switch (c) {
    case '&':
      o += "&amp;";
      break;
    case '<':
      o += "&lt;";
      break;
    case '>':
      o += "&gt;";
      break;
    case '"':
      o += "&quot;";
      break;
    default:
      o += c;
    }
  }
  return o;
}

// A logarithmic axis over whole decades that hold every value.
struct LogAxis {
  double lo = 0, hi = 1; // decades: 10^lo .. 10^hi
  double from, to;       // pixels
  void fit(const std::vector<double>& v) {
    double mn = 1e300, mx = 0;
    for (double x : v)
      if (x > 0) {
        mn = std::min(mn, x);
        mx = std::max(mx, x);
      }
    if (mx <= 0) mn = mx = 1;
    lo = std::floor(std::log10(mn));
    hi = std::ceil(std::log10(mx));
    if (hi <= lo) hi = lo + 1;
  }
  double at(double x) const {
    const double d = x > 0 ? std::clamp(std::log10(x), lo, hi) : lo;
    return from + (to - from) * (d - lo) / (hi - lo);
  }
};

std::string tick_label(double v, bool percent) {
  char b[32];
  if (percent)
    std::snprintf(b, sizeof b, "%g%%", v * 100);
  else
    std::snprintf(b, sizeof b, "%g s", v);
  return b;
}

} // namespace

std::string render_svg(const Chart& chart) {
  std::vector<double> xs, ys;
  for (const ChartSeries& s : chart.series)
    for (const ChartPoint& p : s.points) {
      xs.push_back(p.seconds);
      ys.push_back(p.error);
    }
  if (chart.target > 0) ys.push_back(chart.target);
  LogAxis x{.from = kLeft, .to = kWidth - kRight}, y{.from = kHeight - kBottom, .to = kTop};
  x.fit(xs);
  y.fit(ys);
  std::string o;
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(kWidth) + "\" height=\"" +
       num(kHeight) + "\" viewBox=\"0 0 " + num(kWidth) + " " + num(kHeight) +
       "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o += "<text x=\"" + num(kWidth / 2) + "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" +
       escape(chart.title) + "</text>\n";
  // Grid lines and labels at 1, 2 and 5 of every decade.
  o += "<g class=\"grid\" stroke=\"#ddd\">\n";
  std::string labels;
  for (double d = x.lo; d <= x.hi; ++d)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, d);
      if (std::log10(v) > x.hi + 1e-9) break;
      const double px = x.at(v);
      o += "<line x1=\"" + num(px) + "\" y1=\"" + num(y.from) + "\" x2=\"" + num(px) + "\" y2=\"" +
           num(y.to) + "\"/>\n";
      labels += "<text x=\"" + num(px) + "\" y=\"" + num(y.from + 16) +
                "\" text-anchor=\"middle\">" + tick_label(v, false) + "</text>\n";
    }
  for (double d = y.lo; d <= y.hi; ++d)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, d);
      if (std::log10(v) > y.hi + 1e-9) break;
      const double py = y.at(v);
      o += "<line x1=\"" + num(x.from) + "\" y1=\"" + num(py) + "\" x2=\"" + num(x.to) +
           "\" y2=\"" + num(py) + "\"/>\n";
      labels += "<text x=\"" + num(x.from - 6) + "\" y=\"" + num(py + 4) +
                "\" text-anchor=\"end\">" + tick_label(v, true) + "</text>\n";
    }
  o += "</g>\n<g class=\"labels\">\n" + labels + "</g>\n";
  o += "<rect x=\"" + num(x.from) + "\" y=\"" + num(y.to) + "\" width=\"" + num(x.to - x.from) +
       "\" height=\"" + num(y.from - y.to) + "\" fill=\"none\" stroke=\"#444\"/>\n";
  o += "<text x=\"" + num((x.from + x.to) / 2) + "\" y=\"" + num(kHeight - 18) +
       "\" text-anchor=\"middle\">time per run (wall clock)</text>\n";
  o += "<text transform=\"translate(20 " + num((y.from + y.to) / 2) +
       ") rotate(-90)\" text-anchor=\"middle\">" + escape(chart.y_label) + "</text>\n";
  if (chart.target > 0) {
    const double py = y.at(chart.target);
    o += "<line class=\"target\" x1=\"" + num(x.from) + "\" y1=\"" + num(py) + "\" x2=\"" +
         num(x.to) + "\" y2=\"" + num(py) + "\" stroke=\"#c00\" stroke-dasharray=\"6 4\"/>\n";
    o += "<text x=\"" + num(x.to + 6) + "\" y=\"" + num(py + 4) + "\" fill=\"#c00\">target " +
         tick_label(chart.target, true) + "</text>\n";
  }
  double legend_y = kTop + 10;
  for (std::size_t si = 0; si < chart.series.size(); ++si) {
    const ChartSeries& s = chart.series[si];
    std::vector<const ChartPoint*> front;
    for (const ChartPoint& p : s.points)
      if (p.pareto) front.push_back(&p);
    std::sort(front.begin(), front.end(),
              [](const ChartPoint* a, const ChartPoint* b) { return a->seconds < b->seconds; });
    o += "<g class=\"series\" data-name=\"" + escape(s.name) + "\">\n";
    if (front.size() > 1) {
      o += "<polyline class=\"pareto\" fill=\"none\" stroke=\"" + escape(s.colour) +
           "\" stroke-width=\"1.5\" points=\"";
      for (const ChartPoint* p : front)
        o += num(x.at(p->seconds)) + "," + num(y.at(p->error)) + " ";
      o += "\"/>\n";
    }
    for (std::size_t pi = 0; pi < s.points.size(); ++pi) {
      const ChartPoint& p = s.points[pi];
      char tip[64];
      std::snprintf(tip, sizeof tip, ": %.3g s, %.3g%%", p.seconds, p.error * 100);
      o += "<circle class=\"run\" cx=\"" + num(x.at(p.seconds)) + "\" cy=\"" + num(y.at(p.error)) +
           "\" r=\"" + (p.pareto ? "5" : "3.5") + "\" fill=\"" +
           (p.pareto ? escape(s.colour) : "white") + "\" stroke=\"" + escape(s.colour) +
           "\"><title>" + escape(s.name + " " + p.label) + tip + "</title></circle>\n";
      if (static_cast<int>(si) == chart.recommended_series && pi == chart.recommended_point)
        o += "<circle class=\"recommended\" cx=\"" + num(x.at(p.seconds)) + "\" cy=\"" +
             num(y.at(p.error)) +
             "\" r=\"10\" fill=\"none\" stroke=\"#c00\" stroke-width=\"2\"/>\n";
    }
    o += "</g>\n";
    o += "<circle cx=\"" + num(x.to + 16) + "\" cy=\"" + num(legend_y) + "\" r=\"5\" fill=\"" +
         escape(s.colour) + "\"/><text x=\"" + num(x.to + 28) + "\" y=\"" + num(legend_y + 4) +
         "\">" + escape(s.name) + "</text>\n";
    legend_y += 20;
  }
  o += "<text x=\"" + num(x.to + 10) + "\" y=\"" + num(legend_y + 4) +
       "\" font-size=\"10\" fill=\"#555\">filled: Pareto front</text>\n";
  if (chart.recommended_series >= 0)
    o += "<text x=\"" + num(x.to + 10) + "\" y=\"" + num(legend_y + 20) +
         "\" font-size=\"10\" fill=\"#c00\">ringed: recommended</text>\n";
  o += "</svg>\n";
  return o;
}

} // namespace radcl::cost
