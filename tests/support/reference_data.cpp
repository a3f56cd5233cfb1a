#include "reference_data.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace radcl::test {

std::vector<std::vector<double>> parse_table(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::vector<double> row;
    double v;
    while (ls >> v)
      row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

std::vector<std::vector<double>> read_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_table(text.str());
}

std::vector<std::array<double, 6>> read_rays(const std::string& path) {
  std::vector<std::array<double, 6>> out;
  for (const auto& r : read_table(path)) {
    if (r.size() < 6) throw std::runtime_error("short ray line in " + path);
    out.push_back({r[0], r[1], r[2], r[3], r[4], r[5]});
  }
  return out;
}

std::vector<std::array<double, 3>> read_rgb(const std::string& path) {
  std::vector<std::array<double, 3>> out;
  for (const auto& r : read_table(path)) {
    if (r.size() < 3) throw std::runtime_error("short value line in " + path);
    out.push_back({r[0], r[1], r[2]});
  }
  return out;
}

} // namespace radcl::test
