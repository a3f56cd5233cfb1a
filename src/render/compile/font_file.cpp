#include "radcl/render/compile/font_file.h"

#include <cctype>
#include <climits>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "radcl/util/error.h"

namespace radcl::render {

namespace {

// The font file as whitespace-separated words, '#' starting a comment to the end of the line
// (Radiance's fgetval): each word must be an integer.
class IntReader {
public:
  explicit IntReader(std::string text) : text_(std::move(text)) {}

  enum class Result { kEnd, kBad, kOk };

  Result next(long& v) {
    for (;;) {
      while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
        ++pos_;
      if (pos_ >= text_.size() || text_[pos_] != '#') break;
      while (pos_ < text_.size() && text_[pos_] != '\n')
        ++pos_;
    }
    if (pos_ >= text_.size()) return Result::kEnd;
    std::size_t b = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) &&
           text_[pos_] != '#')
      ++pos_;
    std::string w = text_.substr(b, pos_ - b);
    if (w.size() >= 64) return Result::kBad; // longer than Radiance's word buffer
    std::size_t i = (w[0] == '+' || w[0] == '-') ? 1 : 0;
    if (i == w.size()) return Result::kBad;
    for (std::size_t k = i; k < w.size(); ++k)
      if (!std::isdigit(static_cast<unsigned char>(w[k]))) return Result::kBad;
    v = std::strtol(w.c_str(), nullptr, 10); // saturates; all limits checked are far smaller
    return Result::kOk;
  }

private:
  std::string text_;
  std::size_t pos_ = 0;
};

const Glyph* glyph_of(const Font& f, char c) {
  const auto& g = f.glyphs[static_cast<unsigned char>(c)];
  return g ? &*g : nullptr;
}

} // namespace

Font read_font_file(const std::string& path, const std::string& name) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FatalError("cannot open font file \"" + name + "\"");
  std::ostringstream ss;
  ss << in.rdbuf();
  IntReader rd(ss.str());
  const std::string file = " in font file \"" + path + "\"";
  Font f;
  long sum_w = 0, sum_h = 0, counted = 0;
  long code = 0;
  for (;;) {
    IntReader::Result r = rd.next(code);
    if (r == IntReader::Result::kEnd) break;
    if (r == IntReader::Result::kBad) throw FatalError("non-integer" + file);
    const std::string ch = " character (" + std::to_string(code) + ")" + file;
    if (code < 1 || code > 255) throw FatalError("illegal" + ch);
    if (f.glyphs[code]) throw FatalError("duplicate" + ch);
    long n = 0;
    if (rd.next(n) != IntReader::Result::kOk || n < 0 || n > 32000)
      throw FatalError("bad # vertices for" + ch);
    Glyph g;
    g.coords.resize(2 * static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < g.coords.size(); ++k) {
      long v = 0;
      if (rd.next(v) != IntReader::Result::kOk || v < 0 || v > 255)
        throw FatalError("bad vertex for" + ch);
      g.coords[k] = static_cast<int>(v);
      // Radiance widens a bound only when the other one did not move (if ... else if).
      int& lo = k % 2 == 0 ? g.left : g.bottom;
      int& hi = k % 2 == 0 ? g.right : g.top;
      if (v < lo)
        lo = static_cast<int>(v);
      else if (v > hi)
        hi = static_cast<int>(v);
    }
    if (g.right != g.left && g.top != g.bottom) {
      ++counted;
      sum_w += g.right - g.left;
      sum_h += g.top - g.bottom;
    }
    f.glyphs[code] = std::move(g);
  }
  if (counted) {
    f.mean_width = static_cast<int>(sum_w / counted);
    f.mean_height = static_cast<int>(sum_h / counted);
  }
  return f;
}

LineSpacing uniform_spacing(const std::string& line, const Font& font) {
  LineSpacing s;
  s.offset.assign(line.size() + 1, 0);
  for (std::size_t i = 0; i < line.size(); ++i)
    if (glyph_of(font, line[i])) {
      s.offset[i + 1] = 255;
      s.width += 255;
    }
  return s;
}

LineSpacing squeezed_spacing(const std::string& line, const Font& font, int gap) {
  LineSpacing s;
  std::vector<int>& off = s.offset;
  off.assign(line.size() + 1, 0);
  const int half = gap / 2;
  std::size_t i = 0, p = 0; // next character, entry being accumulated
  const Glyph* g = nullptr;
  while (i < line.size() && !(g = glyph_of(font, line[i++])))
    ++p; // leading characters without a glyph advance nothing
  off[p] = half;
  while (g) {
    if (g->vertices() > 0) { // up to the glyph's left edge, then its right edge and half a gap
      off[p] += half - g->left;
      s.width += off[p++];
      off[p] = g->right + half;
    } else { // a space: the mean glyph width
      s.width += off[p++];
      off[p] = font.mean_width;
    }
    g = nullptr;
    while (i < line.size() && !(g = glyph_of(font, line[i++])))
      s.width += off[p++]; // the pending advance moves past a character without glyph
  }
  off[p] += half;
  s.width += off[p];
  return s;
}

LineSpacing proportional_spacing(const std::string& line, const Font& font, int gap, int indent) {
  LineSpacing s = squeezed_spacing(line, font, gap);
  std::vector<int>& off = s.offset;
  const std::size_t n = line.size();
  int width = off[0];
  std::size_t sp = 1, t = 0;
  while (t < n) {
    // A run: characters up to the end, or to a glyph followed by more than `indent` spaces.
    int target = 0, actual = 0;
    std::size_t np = sp, end = t, next = t;
    for (end = t; end < n; end = next) {
      next = end + 1;
      actual += off[np++];
      if (glyph_of(font, line[end])) {
        const Glyph* g = nullptr;
        while (next < n && (g = glyph_of(font, line[next])) && g->vertices() == 0) {
          actual += off[np++];
          ++next;
        }
        target += static_cast<int>(next - end);
      }
      if (indent && static_cast<int>(next - end) > indent) break;
    }
    target *= font.mean_width + gap;
    width += target;
    int adjust = target - actual; // spread over the run's advances, truncating as C does
    while (sp < np) {
      int a = adjust / static_cast<int>(np - sp);
      off[sp++] += a;
      adjust -= a;
    }
    t = next;
  }
  s.width = width;
  return s;
}

} // namespace radcl::render
