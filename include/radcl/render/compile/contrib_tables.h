// rcontrib's tracked modifiers as the kernels see them: which surfaces and light sources add
// into which bins, and each modifier's bin expression compiled to device code
// (kernels/pipeline/contrib.cl). The tables live in the argument buffer at
// rc_params.contrib, as 32-bit words:
//   [0, 25)   an identity function space (patterns.cl's transform layout) whose translation is
//             the re-centring origin, so bin expressions see world coordinates
//   [25]      modifier count, [26] offset of the surface table, [27] offset of the source table
//             (both from the table's start), [28] real (non-virtual) light sources
//   [29 + 3m] modifier m: its first bin in a record, its bin count, its bin function's
//             dispatcher number (RC_NONE: the constant bin 0)
//   surfaces  per compiled surface, the tracked modifier it names, or RC_NONE
//   sources   per real light source, the tracked modifier of its surface, or RC_NONE
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace radcl::render {

class PatternCompiler;
struct CompiledScene;

// What rcontrib tracks (its -f/-e, -p, -b/-bn, -m/-M and -V options).
struct ContribSpec {
  struct CalSource {
    bool is_file = false;
    std::string text; // a function file's name (RAYPATH) or statements
  };
  struct Modifier {
    std::string name;
    std::string params;         // -p in force: "name=value,..." ("" = none)
    std::string bin_expr = "0"; // -b in force
    int nbins = 1;
  };
  std::vector<CalSource> cal;
  std::vector<Modifier> modifiers;
  bool contributions = false; // -V+: radiance times coefficient; -V-: the coefficient alone
  // Bins in one record: every modifier's, in order.
  std::size_t total_bins() const;
};

inline constexpr std::uint32_t kContribHeader = 29;

// A -p list as Radiance's set_eparams reads it: "name=value" pairs separated by spaces,
// commas, semicolons or colons. Throws FatalError("bad parameter list '...'").
std::vector<std::pair<std::string, double>> parse_contrib_params(const std::string& text);

// Compiles the bin expressions (through the scene's pattern compiler, in a context of their own
// per parameter set) and appends the tables but the source table to cs.args; sets
// cs.contrib_table. Throws FatalError for what radcl cannot compute (-V+ on a modifier that is
// not a light, glow or spotlight).
void compile_contrib(const ContribSpec& spec, CompiledScene& cs, PatternCompiler& patterns,
                     const std::array<double, 3>& centre);
// After the light sources are compiled: the source table (each real source's surface's entry).
void compile_contrib_sources(CompiledScene& cs);

} // namespace radcl::render
