#include "radcl/render/compile/contrib_tables.h"

#include <bit>
#include <cctype>
#include <cstdlib>
#include <map>

#include "radcl/render/compile/compiled_scene.h"
#include "radcl/render/compile/pattern_compiler.h"
#include "radcl/util/error.h"

namespace radcl::render {

namespace {

float bits(std::uint32_t u) {
  return std::bit_cast<float>(u);
}

bool emits(std::uint32_t type) {
  return type == RC_OBJ_LIGHT || type == RC_OBJ_GLOW || type == RC_OBJ_SPOTLIGHT;
}

} // namespace

std::vector<std::pair<std::string, double>> parse_contrib_params(const std::string& text) {
  std::vector<std::pair<std::string, double>> out;
  std::size_t i = 0;
  const auto bad = [&] { return FatalError("bad parameter list '" + text + "'"); };
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    if (!std::isalpha(static_cast<unsigned char>(text[i]))) throw bad();
    std::size_t start = i;
    while (i < text.size() && text[i] != '=' && !std::isspace(static_cast<unsigned char>(text[i])))
      ++i;
    std::string name = text.substr(start, i - start);
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
      ++i;
    if (i >= text.size() || text[i] != '=') throw bad();
    ++i;
    const char* from = text.c_str() + i;
    char* end = nullptr;
    double v = std::strtod(from, &end);
    if (end == from) throw bad();
    i += static_cast<std::size_t>(end - from);
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
      ++i;
    if (i < text.size() && (text[i] == ',' || text[i] == ';' || text[i] == ':')) ++i;
    out.emplace_back(name, v);
  }
  return out;
}

std::size_t ContribSpec::total_bins() const {
  std::size_t n = 0;
  for (const Modifier& m : modifiers)
    n += static_cast<std::size_t>(m.nbins);
  return n;
}

void compile_contrib(const ContribSpec& spec, CompiledScene& cs, PatternCompiler& patterns,
                     const std::array<double, 3>& centre) {
  std::vector<float>& a = cs.args;
  cs.contrib_table = static_cast<std::uint32_t>(a.size());
  // Identity function space, translated by the centre: world coordinates (patterns.cl's
  // layout: rows, translation, scale, rotation, the world origin).
  const float id[25] = {1,
                        0,
                        0,
                        0,
                        1,
                        0,
                        0,
                        0,
                        1,
                        static_cast<float>(centre[0]),
                        static_cast<float>(centre[1]),
                        static_cast<float>(centre[2]),
                        1,
                        1,
                        0,
                        0,
                        0,
                        1,
                        0,
                        0,
                        0,
                        1,
                        0,
                        0,
                        0};
  a.insert(a.end(), id, id + 25);
  const auto nmods = static_cast<std::uint32_t>(spec.modifiers.size());
  a.push_back(bits(nmods));
  a.push_back(bits(kContribHeader + 3 * nmods)); // surface table
  a.push_back(bits(RC_NONE));                    // source table: compile_contrib_sources
  a.push_back(bits(0));
  // One context per parameter set: the files and statements are loaded into each, then its
  // parameters override their values, as Radiance sets them before each evaluation.
  std::map<std::string, std::string> contexts;
  std::map<std::string, std::uint32_t> index;
  std::uint32_t first = 0;
  for (std::uint32_t m = 0; m < nmods; ++m) {
    const ContribSpec::Modifier& mod = spec.modifiers[m];
    index.emplace(mod.name, m);
    std::uint32_t fn = RC_NONE;
    if (mod.nbins > 1 || mod.bin_expr != "0") {
      auto [it, fresh] = contexts.emplace(mod.params, "rcontrib" + std::to_string(contexts.size()));
      if (fresh) {
        // Set before the files too: a file may fold its constants from them at load
        // (reinhart.cal's MF), and after, over the file's own values (reinhartb.cal's MF = 1).
        const auto params = parse_contrib_params(mod.params);
        for (const auto& [name, v] : params)
          patterns.set_parameter(it->second, name, v);
        for (const ContribSpec::CalSource& c : spec.cal)
          patterns.load_into(it->second, c.is_file, c.text, c.is_file ? c.text : "-e");
        for (const auto& [name, v] : params)
          patterns.set_parameter(it->second, name, v);
      }
      fn = patterns.request_expression(mod.bin_expr, it->second,
                                       "bin expression of modifier '" + mod.name + "'");
    }
    a.push_back(bits(first));
    a.push_back(bits(static_cast<std::uint32_t>(mod.nbins)));
    a.push_back(bits(fn));
    first += static_cast<std::uint32_t>(mod.nbins);
  }
  for (std::size_t s = 0; s < cs.surfaces.size(); ++s) {
    const std::string& name = cs.modifier_names[s];
    auto it = name.empty() || name == "void" ? index.end() : index.find(name);
    a.push_back(bits(it == index.end() ? RC_NONE : it->second));
    if (it == index.end() || !spec.contributions) continue;
    // -V+ is the radiance of the ray that met the surface; radcl knows it where the surface
    // emits (a light, glow or spotlight), not where its value is a whole subtree's.
    const std::uint32_t mat = cs.surfaces[s].material;
    if (mat != RC_NONE && !emits(cs.materials[mat].type))
      throw FatalError("-V+ for modifier '" + name +
                       "' is not supported: radcl computes contributions of light, glow and "
                       "spotlight modifiers only (use -V- for coefficients)");
  }
}

void compile_contrib_sources(CompiledScene& cs) {
  std::vector<float>& a = cs.args;
  const std::uint32_t t = cs.contrib_table;
  const std::uint32_t surf_table = std::bit_cast<std::uint32_t>(a[t + 26]);
  const auto nreal = static_cast<std::uint32_t>(cs.sources.object_surface.size());
  a[t + 27] = bits(static_cast<std::uint32_t>(a.size()) - t);
  a[t + 28] = bits(nreal);
  for (std::uint32_t surf : cs.sources.object_surface)
    a.push_back(surf < cs.surfaces.size() ? a[t + surf_table + surf] : bits(RC_NONE));
}

} // namespace radcl::render
