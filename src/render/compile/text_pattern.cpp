#include "radcl/render/compile/text_pattern.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "radcl/device_types.h"
#include "radcl/scene/raypath.h"
#include "radcl/util/error.h"

namespace radcl::render {

namespace {

using V3 = std::array<double, 3>;

V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

float bits(std::uint32_t u) {
  return std::bit_cast<float>(u);
}

// The lines of a text file as Radiance reads them (fgets into a 512-byte buffer): a line
// longer than 511 characters continues as the next line, and text stops at a NUL.
std::vector<std::string> read_lines(const std::string& path, const std::string& name) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FatalError("cannot open text file \"" + name + "\"");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::vector<std::string> lines;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t n = 0;
    while (n < 511 && pos + n < text.size() && text[pos + n] != '\n')
      ++n;
    bool newline = n < 511 && pos + n < text.size(); // the line's '\n' fits in the buffer
    std::string line = text.substr(pos, n);
    pos += n + (newline ? 1 : 0);
    line.resize(std::strlen(line.c_str()));
    lines.push_back(std::move(line));
  }
  return lines;
}

} // namespace

bool TextPatterns::is_text(std::uint32_t type) {
  return type == RC_OBJ_BRIGHTTEXT || type == RC_OBJ_COLORTEXT || type == RC_OBJ_MIXTEXT;
}

const TextPatterns::PackedFont&
TextPatterns::font(const std::string& file, const std::string& where, std::vector<float>& args) {
  if (auto it = fonts_.find(file); it != fonts_.end()) return it->second;
  std::string path = scene::find_on_raypath(file);
  if (path.empty()) throw FatalError(where + ": cannot find font file \"" + file + "\"");
  PackedFont pf;
  try {
    pf.font = read_font_file(path, file);
  } catch (const FatalError& e) {
    throw FatalError(where + ": " + e.what());
  }
  pf.glyph.fill(~0u);
  for (std::size_t c = 0; c < 256; ++c) {
    const auto& g = pf.font.glyphs[c];
    if (!g) continue;
    pf.glyph[c] = static_cast<std::uint32_t>(args.size());
    for (int v : {g->vertices(), g->left, g->right, g->bottom, g->top})
      args.push_back(static_cast<float>(v));
    for (int v : g->coords)
      args.push_back(static_cast<float>(v));
  }
  return fonts_.emplace(file, std::move(pf)).first->second;
}

std::vector<float> TextPatterns::compile(const scene::Object& o, const std::string& where,
                                         std::vector<float>& args) {
  // String arguments: [foreground background] fontfile, then a text file or "." and words.
  // Real arguments: O R D, then the colours of brighttext/colortext, then the spacing.
  const bool mix = o.type == RC_OBJ_MIXTEXT;
  const std::size_t font_arg = mix ? 2 : 0, text_arg = font_arg + 1;
  const std::size_t spacing_arg = o.type == RC_OBJ_BRIGHTTEXT  ? 11
                                  : o.type == RC_OBJ_COLORTEXT ? 15
                                                               : 9;
  if (o.sargs.size() < text_arg + 1 || o.fargs.size() < spacing_arg)
    throw FatalError("bad # arguments for " + where);
  const V3 origin{o.fargs[0], o.fargs[1], o.fargs[2]};
  const V3 r{o.fargs[3], o.fargs[4], o.fargs[5]}, d{o.fargs[6], o.fargs[7], o.fargs[8]};
  // right and down: dual to R and D, so that a point O + a R + b D (+ any normal offset) has
  // coordinates a along right and b along down.
  const V3 dxr = cross(d, r);
  V3 right = cross(dxr, d);
  const double rr = dot(right, right);
  if (rr <= 1e-24) throw FatalError("illegal motion vector for " + where);
  V3 down = cross(r, dxr);
  const double dd = dot(down, down);
  for (int k = 0; k < 3; ++k) {
    right[k] *= dot(d, d) / rr;
    down[k] *= dot(r, r) / dd;
  }

  std::vector<std::string> lines;
  if (o.sargs.size() > text_arg + 1) { // one line of words
    std::string line;
    for (std::size_t i = text_arg + 1; i < o.sargs.size(); ++i)
      line += (i > text_arg + 1 ? " " : "") + o.sargs[i];
    lines.push_back(line);
  } else {
    const std::string& file = o.sargs[text_arg];
    std::string path = scene::find_on_raypath(file);
    if (path.empty()) throw FatalError(where + ": cannot find text file \"" + file + "\"");
    lines = read_lines(path, file);
  }

  const PackedFont& pf = font(o.sargs[font_arg], where, args);
  const bool has_spacing = o.fargs.size() > spacing_arg;
  const double spacing = has_spacing ? o.fargs[spacing_arg] : 0.0;
  const int gap = static_cast<int>(spacing * 255.0);
  std::vector<std::uint32_t> line_at;
  for (const std::string& line : lines) {
    LineSpacing sp = gap < 0   ? squeezed_spacing(line, pf.font, -gap)
                     : gap > 0 ? proportional_spacing(line, pf.font, gap, 3)
                               : uniform_spacing(line, pf.font);
    line_at.push_back(static_cast<std::uint32_t>(args.size()));
    args.push_back(static_cast<float>(sp.width));
    args.push_back(bits(static_cast<std::uint32_t>(sp.offset.size())));
    for (std::size_t i = 0; i < sp.offset.size(); ++i) {
      args.push_back(static_cast<float>(sp.offset[i]));
      args.push_back(bits(i < line.size() ? pf.glyph[static_cast<unsigned char>(line[i])] : ~0u));
    }
  }

  std::vector<float> desc;
  for (const V3& v : {origin, right, down})
    for (double c : v)
      desc.push_back(static_cast<float>(c));
  // With a spacing argument (even 0) Radiance measures a character as the mean glyph width
  // plus the spacing, otherwise as a 255-unit cell.
  desc.push_back(has_spacing ? static_cast<float>(pf.font.mean_width + 255.0 * std::fabs(spacing))
                             : 255.0f);
  std::array<double, 6> colours{};
  if (o.type == RC_OBJ_BRIGHTTEXT)
    colours = {o.fargs[9], o.fargs[9], o.fargs[9], o.fargs[10], o.fargs[10], o.fargs[10]};
  else if (o.type == RC_OBJ_COLORTEXT)
    for (int k = 0; k < 6; ++k)
      colours[k] = o.fargs[9 + k];
  for (double c : colours)
    desc.push_back(static_cast<float>(c));
  desc.push_back(bits(static_cast<std::uint32_t>(line_at.size())));
  for (std::uint32_t l : line_at)
    desc.push_back(bits(l));
  used_ = true;
  return desc;
}

} // namespace radcl::render
