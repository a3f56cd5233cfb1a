// brighttext, colortext and mixtext (../shared/docs/radiance/scene-format.md §4, Radiance's
// text.c): the text, its font and its layout are prepared on the host and packed into the kernels'
// float argument buffer, where kernels/patterns/text.cl tests whether a hit lies inside a glyph.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "radcl/render/compile/font_file.h"
#include "radcl/scene/scene.h"

namespace radcl::render {

// Layout in the argument buffer (integers and offsets stored as their bit patterns, marked b):
//   descriptor (follows the pattern's 25 transform floats): origin O (3), right and down vectors
//     scaled so that a point's coordinates along them come out in lines and characters (3 + 3),
//     the horizontal scale to glyph units (1), foreground and background colours (3 + 3, zero
//     for mixtext), line count (b), then each line's offset (b);
//   line: width in glyph units, entry count n (b), then n pairs {advance, glyph offset (b) or
//     ~0u}: the advance before character i and character i's glyph (the last entry has none);
//   glyph: vertex count, left, right, bottom, top, then x y of each vertex.
class TextPatterns {
public:
  // The descriptor of text pattern `o` (brighttext, colortext or mixtext); its fonts (once per
  // file) and lines are appended to `args` first. Throws FatalError for bad arguments, an
  // illegal motion vector, or a text or font file that cannot be found or read.
  std::vector<float> compile(const scene::Object& o, const std::string& where,
                             std::vector<float>& args);
  bool empty() const { return !used_; }

  static bool is_text(std::uint32_t type);

private:
  struct PackedFont {
    Font font;
    std::array<std::uint32_t, 256> glyph; // offset of each character's glyph, ~0u: none
  };
  // Font file `file`, found on RAYPATH and packed into `args` on first use.
  const PackedFont& font(const std::string& file, const std::string& where,
                         std::vector<float>& args);

  bool used_ = false;
  std::map<std::string, PackedFont> fonts_;
};

} // namespace radcl::render
