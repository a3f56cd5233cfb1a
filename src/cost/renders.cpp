#include "radcl/cost/renders.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "radcl/image/picture.h"
#include "radcl/util/error.h"

namespace radcl::cost {

RenderOutput render(const StudyOptions& o, const RenderJob& job) {
  const std::string& bin = job.radiance ? o.radiance_bin : o.radcl_bin;
  TimedRun r;
  r.env = {{"RADCL_SEED", std::to_string(job.seed)}};
  r.out = o.work + (o.pictures() ? "/run.hdr" : "/run.txt");
  if (o.pictures()) {
    r.argv = {bin + "/rpict"};
    r.argv.insert(r.argv.end(), o.pass.begin(), o.pass.end());
    r.argv.insert(r.argv.end(), o.view.begin(), o.view.end());
    if (job.warm_up) r.argv.insert(r.argv.end(), {"-x", "32", "-y", "32"}); // the last wins
  } else {
    r.argv = {bin + "/rtrace", "-h"};
    r.argv.insert(r.argv.end(), o.pass.begin(), o.pass.end());
    r.in = job.warm_up ? o.work + "/first-sensors" : o.sensors;
  }
  r.argv.insert(r.argv.end(), job.settings.begin(), job.settings.end());
  if (!o.pictures()) {
    r.argv.insert(r.argv.end(), {"-n", std::to_string(o.nproc)});
    if (job.std_error) r.argv.push_back("-ove");
  }
  r.argv.push_back(o.octree);
  RenderOutput out;
  out.seconds = run_or_fail(r);
  if (job.warm_up) return out;
  if (o.pictures())
    out.values = picture_blocks(r.out, o.block);
  else
    out.values =
        read_values(r.out, job.std_error ? 6 : 3, job.std_error ? &out.std_error : nullptr);
  return out;
}

std::vector<Rgb> read_values(const std::string& path, int columns, std::vector<Rgb>* second) {
  std::ifstream in(path);
  if (!in) throw FatalError("cannot open \"" + path + "\"");
  std::vector<Rgb> v;
  if (second) second->clear();
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    std::istringstream words(line);
    double x[6];
    int n = 0;
    while (n < 6 && words >> x[n])
      ++n;
    std::string rest;
    if (n != columns || (words >> rest))
      throw FatalError("\"" + path + "\" line " + std::to_string(lineno) + ": expected " +
                       std::to_string(columns) + " numbers");
    v.push_back({x[0], x[1], x[2]});
    if (second && columns == 6) second->push_back({x[3], x[4], x[5]});
  }
  return v;
}

std::vector<Rgb> picture_blocks(const std::string& path, int block) {
  const image::Picture p = image::read_picture(path);
  const double ex = p.header.exposure() > 0 ? p.header.exposure() : 1.0;
  const std::vector<image::Color> c = p.colors();
  const int bw = (p.width + block - 1) / block, bh = (p.height + block - 1) / block;
  std::vector<Rgb> out(std::size_t(bw) * bh, Rgb{});
  std::vector<int> count(out.size(), 0);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const std::size_t b = std::size_t(y / block) * bw + x / block;
      const image::Color& px = c[std::size_t(y) * p.width + x];
      for (int k = 0; k < 3; ++k)
        out[b][k] += px[k];
      ++count[b];
    }
  for (std::size_t b = 0; b < out.size(); ++b)
    for (int k = 0; k < 3; ++k)
      out[b][k] /= count[b] * ex;
  return out;
}

} // namespace radcl::cost
