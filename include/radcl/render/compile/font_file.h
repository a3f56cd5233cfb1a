// Polygonal fonts of the text patterns (../shared/docs/radiance/scene-format.md §4.2): Radiance's
// font-file format read on the host, and the three ways Radiance spaces a line of text in such a
// font.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace radcl::render {

// One character: a closed polygon in a 256 x 256 cell, (0, 0) lower left. A glyph without
// vertices is a space.
struct Glyph {
  std::vector<int> coords; // x0 y0 x1 y1 ...
  // The extent as Radiance records it: each bound starts at 128, so a glyph that lies on one
  // side of the middle still reaches it.
  int left = 128, right = 128, bottom = 128, top = 128;
  int vertices() const { return static_cast<int>(coords.size() / 2); }
};

struct Font {
  std::array<std::optional<Glyph>, 256> glyphs; // by character code (1..255)
  int mean_width = 0, mean_height = 0;          // over the glyphs with a non-empty extent
};

// Reads font file `path` (`name` as the scene gives it). Throws FatalError with Radiance's
// messages: "non-integer in font file", "illegal character (N) in font file", "duplicate
// character (N) ...", "bad # vertices for character (N) ...", "bad vertex for character (N) ..."
// (each naming `path`), or "cannot open font file".
Font read_font_file(const std::string& path, const std::string& name);

// A line's character spacing: offset[0] is where the first character's cell starts, and
// offset[i + 1] the advance from character i's cell to the next (the line's length + 1 entries;
// characters without a glyph advance 0); `width` is their sum.
struct LineSpacing {
  std::vector<int> offset;
  int width = 0;
};

// Every character with a glyph gets a 255-wide cell (spacing 0).
LineSpacing uniform_spacing(const std::string& line, const Font& font);
// Glyphs packed `gap` apart (spacing < 0), spaces as wide as the mean glyph.
LineSpacing squeezed_spacing(const std::string& line, const Font& font, int gap);
// Proportional spacing (spacing > 0): squeezed, then each run of text re-spread so that every
// character takes the mean width plus `gap`, keeping runs after `indent` + 1 spaces aligned.
LineSpacing proportional_spacing(const std::string& line, const Font& font, int gap, int indent);

} // namespace radcl::render
