// The settings `radcl cost` tries, coarse to fine, in four families:
//   cache  the irradiance cache: -ad, -as and -ar raised together, -aa lowered (at -ab B)
//   mc     no cache (-aa 0): -ad paths per sensor raised (at -ab B)
//   ab     the cache's middle step at other numbers of bounces
//   lw     -aa 0 -ad 1024 with a coarser -lw cut-off
// where B is the user's -ab (5 when none is given).
#pragma once

#include <string>
#include <vector>

namespace radcl::cost {

struct Step {
  std::string family;               // cache, mc, ab, lw
  std::vector<std::string> options; // ambient options, as words (-ab first)
  // What one run costs, in proportion to others of its family (the progress bar's guess).
  double cost_hint = 1;
  std::string label() const; // the options joined by spaces
};

// The ladder over `families` (a subset of cache, mc, ab, lw; throws FatalError on others),
// each family in order of rising cost.
std::vector<Step> make_ladder(int ab, const std::vector<std::string>& families);

// "cache,mc" -> {"cache", "mc"}; "all" -> every family.
std::vector<std::string> parse_families(const std::string& list);

} // namespace radcl::cost
