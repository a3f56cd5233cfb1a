#include "radcl/render/compile/mist_materials.h"

#include <algorithm>
#include <cstring>

#include "radcl/util/error.h"

namespace radcl::render {
namespace {

constexpr char kRelay = '>'; // `relay>source`: a source seen in the relay surface

float bits_of(std::uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

// Whether source `sn` is the one `id` names: a real source by its object name, a virtual one
// by its relay surface's name, `>`, then what it relays (Radiance's srcmatch).
bool matches(std::uint32_t sn, std::string_view id, const CompiledSources& so,
             const std::vector<std::string>& surface_names) {
  for (;;) {
    const rc_source& s = so.sources[sn];
    const bool virt = (s.flags & RC_SRCF_VIRTUAL) != 0;
    const std::size_t cut = id.find(kRelay);
    if (cut == std::string_view::npos) return !virt && sn < so.names.size() && so.names[sn] == id;
    if (!virt || s.mirror >= so.mirrors.size()) return false;
    const std::uint32_t surf = so.mirrors[s.mirror].surface;
    if (surf >= surface_names.size() || surface_names[surf] != id.substr(0, cut)) return false;
    id.remove_prefix(cut + 1);
    sn = s.parent;
    if (sn >= so.sources.size()) return false;
  }
}

} // namespace

std::vector<float> mist_arguments(const scene::Object& o, MistSources& list) {
  std::vector<std::string>& names = list.names;
  const std::size_t n = o.fargs.size();
  std::vector<float> a(RC_MIST_NARGS, 0.0f);
  if (n > 2) // extinction, added to the medium the ray is in
    for (int c = 0; c < 3; ++c)
      a[c] = static_cast<float>(o.fargs[c]);
  if (n > 5) // albedo, replacing the medium's
    for (int c = 0; c < 3; ++c)
      a[RC_MIST_ALBEDO + c] = static_cast<float>(o.fargs[3 + c]);
  if (n > 6) a[RC_MIST_GECC] = static_cast<float>(o.fargs[6]);
  a[RC_MIST_NREALS] = static_cast<float>(n);
  std::uint32_t mask = 0;
  for (const std::string& id : o.sargs) {
    auto it = std::find(names.begin(), names.end(), id);
    if (it == names.end()) {
      if (names.size() == kMaxMistSources)
        throw FatalError("mist \"" + o.name + "\": more than " + std::to_string(kMaxMistSources) +
                         " light sources named by the scene's mists (radcl's limit)");
      it = names.insert(names.end(), id);
      list.mists.push_back(o.name);
    }
    const std::uint32_t bit = 1u << static_cast<std::uint32_t>(it - names.begin());
    if (mask & bit) warning("duplicate source \"" + id + "\" for mist \"" + o.name + "\"");
    mask |= bit;
  }
  a[RC_MIST_MASK] = bits_of(mask);
  return a;
}

std::vector<std::uint32_t> mist_source_table(const MistSources& list,
                                             const CompiledSources& sources,
                                             const std::vector<std::string>& surface_names) {
  const std::vector<std::string>& names = list.names;
  std::vector<std::uint32_t> table(kMaxMistSources + 1, RC_NONE);
  std::uint32_t known = 0;
  for (std::size_t b = 0; b < names.size(); ++b) {
    for (std::size_t i = sources.sources.size(); i-- > 0;)
      if (matches(static_cast<std::uint32_t>(i), names[b], sources, surface_names)) {
        table[b] = static_cast<std::uint32_t>(i);
        break;
      }
    if (table[b] != RC_NONE) known |= 1u << b;
    if (table[b] == RC_NONE)
      warning("unknown source \"" + names[b] + "\" for mist \"" + list.mists[b] + "\"");
  }
  table[kMaxMistSources] = known;
  return table;
}

} // namespace radcl::render
