#include "cost_report.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "radcl/cost/svg_chart.h"
#include "radcl/util/error.h"

namespace radcl::cli {

namespace {

std::string pct(double f) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f%%", 100 * f);
  return b;
}

std::string duration(double s) {
  char b[32];
  if (s < 90)
    std::snprintf(b, sizeof b, "%.0f s", s);
  else if (s < 5400)
    std::snprintf(b, sizeof b, "%.0f min", s / 60);
  else
    std::snprintf(b, sizeof b, "%.1f h", s / 3600);
  return b;
}

// Written whole to a temporary name, then renamed: never left half-written.
void write_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    if (!f.flush()) throw FatalError("cannot write \"" + path + "\"");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw FatalError("cannot write \"" + path + "\"");
  }
}

} // namespace

CostProgress::CostProgress() : tty_(::isatty(2)), start_(std::chrono::steady_clock::now()) {}

void CostProgress::show(const std::string& what, double done, double left) {
  if (!tty_) return;
  const int width = 24;
  const int filled = static_cast<int>(done * width + 0.5);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(width, '.');
  const double el =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string t = duration(el) + " so far";
  if (left >= 0) t += ", about " + duration(left) + " left";
  std::string line = "[" + bar + "] " + t + "  " + what;
  if (line.size() > 120) line.resize(120);
  std::fprintf(stderr, "\r\033[K%s", line.c_str());
  std::fflush(stderr);
}

void CostProgress::clear() {
  if (tty_) std::fputs("\r\033[K", stderr);
}

void write_report(const cost::StudyOptions& o, const cost::StudyReport& r, const CostOutputs& out) {
  const char* unit = o.pictures() ? "blocks" : "sensors";
  const std::string metric = cost::metric_name(o.metric);
  const std::string scene = std::filesystem::path(o.octree).filename().string();
  std::printf("# radcl cost: %s, %zu %s; error: relative luminance error per %s, judged by %s\n",
              scene.c_str(), r.reference.elements, unit, o.pictures() ? "block" : "sensor",
              metric.c_str());
  std::printf("# reference: %s", r.reference.how.c_str());
  if (r.reference.se_p95 > 0)
    std::printf("; its standard error %s mean, %s p95", pct(r.reference.se_mean).c_str(),
                pct(r.reference.se_p95).c_str());
  if (r.reference.seconds > 0) std::printf(" (%.1f s)", r.reference.seconds);
  std::printf("\n\n| renderer | settings | seconds | mean | p95 | max | rms | front |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|:-:|\n");
  std::string tsv = "renderer\tfamily\tsettings\tseconds\tmean\tp95\tmax\trms\tfront\n";
  for (const cost::Run& run : r.runs) {
    std::printf("| %s | %s | %.2f | %s | %s | %s | %s | %s |\n", run.renderer.c_str(),
                run.step.label().c_str(), run.seconds, pct(run.score.mean).c_str(),
                pct(run.score.p95).c_str(), pct(run.score.worst).c_str(),
                pct(run.score.rms).c_str(), run.pareto ? "*" : "");
    char row[512];
    std::snprintf(row, sizeof row, "%s\t%s\t%s\t%.4f\t%.6g\t%.6g\t%.6g\t%.6g\t%d\n",
                  run.renderer.c_str(), run.step.family.c_str(), run.step.label().c_str(),
                  run.seconds, run.score.mean, run.score.p95, run.score.worst, run.score.rms,
                  run.pareto ? 1 : 0);
    tsv += row;
  }
  std::printf("\n");
  for (std::size_t k : r.rejected)
    std::printf("not recommended: %s met %s <= %s but not with another seed\n",
                r.runs[k].step.label().c_str(), metric.c_str(), pct(o.target).c_str());
  if (r.recommended) {
    const cost::Run& best = r.runs[*r.recommended];
    std::printf("recommended for %s <= %s: %s (%.2f s; %s %s, another seed %s)\n", metric.c_str(),
                pct(o.target).c_str(), best.step.label().c_str(), best.seconds, metric.c_str(),
                pct(cost::pick(best.score, o.metric)).c_str(),
                pct(cost::pick(r.confirmed, o.metric)).c_str());
  } else {
    std::printf("no settings of the ladder met %s <= %s: raise -ad on the mc ladder, or relax "
                "-target\n",
                metric.c_str(), pct(o.target).c_str());
  }
  if (!out.tsv.empty()) write_file(out.tsv, tsv);
  if (!out.save_ref.empty()) {
    // Six numbers per sensor, as rtrace -ove prints them: -ref reads them back.
    std::string text;
    const auto& v = r.reference.values;
    const auto& se = r.reference.std_error;
    for (std::size_t i = 0; i < v.size(); ++i) {
      char row[160];
      const cost::Rgb e = i < se.size() ? se[i] : cost::Rgb{};
      std::snprintf(row, sizeof row, "%.6e\t%.6e\t%.6e\t%.6e\t%.6e\t%.6e\n", v[i][0], v[i][1],
                    v[i][2], e[0], e[1], e[2]);
      text += row;
    }
    write_file(out.save_ref, text);
  }
  if (!out.svg.empty()) {
    cost::Chart c;
    c.title = "What accuracy costs: " + scene;
    c.y_label = metric + " relative error per " + (o.pictures() ? "block" : "sensor");
    c.target = o.target;
    for (const char* who : {"radcl", "Radiance"}) {
      cost::ChartSeries s{who, std::string(who) == "radcl" ? "#1f77b4" : "#ff7f0e", {}};
      for (std::size_t i = 0; i < r.runs.size(); ++i) {
        const cost::Run& run = r.runs[i];
        if (run.renderer != who) continue;
        if (r.recommended && i == *r.recommended) {
          c.recommended_series = static_cast<int>(c.series.size());
          c.recommended_point = s.points.size();
        }
        s.points.push_back(
            {run.seconds, cost::pick(run.score, o.metric), run.step.label(), run.pareto});
      }
      if (!s.points.empty()) c.series.push_back(std::move(s));
    }
    write_file(out.svg, cost::render_svg(c));
  }
}

} // namespace radcl::cli
