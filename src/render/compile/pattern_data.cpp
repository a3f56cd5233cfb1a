#include "radcl/render/compile/pattern_data.h"

#include <bit>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "radcl/image/picture.h"
#include "radcl/util/error.h"

namespace radcl::render {

namespace {

// Whitespace-separated words of a data file, '#' starting a comment to the end of the line.
class Words {
public:
  Words(const std::string& path, const std::string& name) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FatalError("cannot open data file \"" + name + "\"");
    std::ostringstream ss;
    ss << in.rdbuf();
    text_ = ss.str();
  }
  double real() {
    std::string w = next();
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(w.c_str(), &end);
    if (*end != '\0' || errno == ERANGE) fail();
    return v;
  }
  int integer() {
    std::string w = next();
    char* end = nullptr;
    long v = std::strtol(w.c_str(), &end, 10);
    if (*end != '\0' || v < -1000000000L || v > 1000000000L) fail();
    return static_cast<int>(v);
  }
  [[noreturn]] void fail() const {
    throw FatalError(std::string(eof_ ? "unexpected EOF" : "bad format") + " in data file \"" +
                     path_ + "\"");
  }

private:
  std::string next() {
    for (;;) {
      while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
        ++pos_;
      if (pos_ < text_.size() && text_[pos_] == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n')
          ++pos_;
        continue;
      }
      break;
    }
    if (pos_ >= text_.size()) {
      eof_ = true;
      fail();
    }
    std::size_t b = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) &&
           text_[pos_] != '#')
      ++pos_;
    return text_.substr(b, pos_ - b);
  }
  std::string path_, text_;
  std::size_t pos_ = 0;
  bool eof_ = false;
};

float bits(std::uint32_t u) {
  return std::bit_cast<float>(u);
}

} // namespace

DataSet read_data_file(const std::string& path, const std::string& name) {
  Words in(path, name);
  int nd = in.integer();
  if (nd <= 0 || nd > kMaxDataDims)
    throw FatalError("bad number of dimensions for \"" + name + "\"");
  DataSet d;
  std::size_t size = 1;
  for (int i = 0; i < nd; ++i) {
    DataAxis a;
    a.begin = in.real();
    a.end = in.real();
    a.count = in.integer();
    if (a.count < 2 || size > (std::size_t{1} << 28) / a.count) in.fail();
    size *= static_cast<std::size_t>(a.count);
    if (a.begin == a.end) { // explicit coordinates, monotonic as Radiance checks it
      for (int j = 0; j < a.count; ++j)
        a.points.push_back(static_cast<float>(in.real()));
      for (int j = 1; j + 1 < a.count; ++j)
        if ((a.points[j - 1] < a.points[j]) != (a.points[j] < a.points[j + 1])) in.fail();
      a.begin = a.points.front();
      a.end = a.points.back();
    }
    d.axes.push_back(std::move(a));
  }
  d.values.resize(size);
  for (float& v : d.values)
    v = static_cast<float>(in.real());
  return d;
}

std::array<DataSet, 3> read_picture_data(const std::string& path, const std::string& name) {
  image::Picture p;
  try {
    p = image::read_picture(path);
  } catch (const FatalError&) {
    throw FatalError("bad picture file \"" + name + "\"");
  }
  double aspect = p.header.pixaspect();
  if (!(aspect > 1e-7) || p.width < 2 || p.height < 2)
    throw FatalError("bad picture file \"" + name + "\"");
  DataAxis v, u; // vertical then horizontal, as Radiance's (y major) picture data
  v.count = p.height;
  u.count = p.width;
  if (p.width <= p.height * aspect) {
    v.end = aspect * p.height / p.width;
    u.end = 1.0;
  } else {
    v.end = 1.0;
    u.end = static_cast<double>(p.width) / p.height / aspect;
  }
  std::array<DataSet, 3> out;
  std::vector<image::Color> c = p.colors();
  for (int ch = 0; ch < 3; ++ch) {
    out[ch].axes = {v, u};
    out[ch].values.reserve(c.size());
    for (int row = p.height - 1; row >= 0; --row) // bottom row first
      for (int x = 0; x < p.width; ++x)
        out[ch].values.push_back(c[std::size_t(row) * p.width + x][ch]);
  }
  return out;
}

std::uint32_t pack_data(const DataSet& d, std::vector<float>& args) {
  const auto off = static_cast<std::uint32_t>(args.size());
  args.push_back(bits(static_cast<std::uint32_t>(d.axes.size())));
  std::size_t points = off + 1 + 4 * d.axes.size() + d.values.size();
  for (const DataAxis& a : d.axes) {
    args.push_back(bits(static_cast<std::uint32_t>(a.count)));
    args.push_back(bits(a.points.empty() ? ~0u : static_cast<std::uint32_t>(points)));
    args.push_back(static_cast<float>(a.begin));
    args.push_back(static_cast<float>(a.end - a.begin));
    points += a.points.size();
  }
  args.insert(args.end(), d.values.begin(), d.values.end());
  for (const DataAxis& a : d.axes)
    args.insert(args.end(), a.points.begin(), a.points.end());
  return off;
}

} // namespace radcl::render
