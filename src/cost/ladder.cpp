#include "radcl/cost/ladder.h"

#include <algorithm>
#include <sstream>

#include "radcl/util/error.h"

namespace radcl::cost {

namespace {

const char* const kFamilies[] = {"cache", "mc", "ab", "lw"};

// The cache ladder: each step doubles -ad and -as and lowers -aa, as a designer tightening
// the usual settings would (the middle step is Radiance's documented "accurate" corner).
struct CacheStep {
  const char *aa, *ad, *as, *ar;
};
constexpr CacheStep kCache[] = {
    {"0.25", "256", "64", "128"},
    {"0.2", "512", "128", "128"},
    {"0.15", "1024", "256", "256"},
    {"0.1", "2048", "512", "512"},
};
constexpr const char* kMc[] = {"256", "1024", "4096", "16384"};

Step cache_step(int ab, const CacheStep& c, const char* family) {
  return Step{family,
              {"-ab", std::to_string(ab), "-aa", c.aa, "-ad", c.ad, "-as", c.as, "-ar", c.ar, "-lw",
               "1e-3"},
              std::stod(c.ad) * std::stod(c.as) / 256.0 * ab};
}

Step mc_step(int ab, const char* ad, const char* lw, const char* family) {
  return Step{family,
              {"-ab", std::to_string(ab), "-aa", "0", "-ad", ad, "-as", "0", "-lw", lw},
              std::stod(ad) * ab};
}

} // namespace

std::string Step::label() const {
  std::string s;
  for (const std::string& w : options)
    s += (s.empty() ? "" : " ") + w;
  return s;
}

std::vector<std::string> parse_families(const std::string& list) {
  if (list == "all") return {std::begin(kFamilies), std::end(kFamilies)};
  std::vector<std::string> out;
  std::istringstream in(list);
  for (std::string f; std::getline(in, f, ',');) {
    if (std::find(std::begin(kFamilies), std::end(kFamilies), f) == std::end(kFamilies))
      throw FatalError("unknown ladder \"" + f + "\" (cache, mc, ab, lw or all)");
    if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
  }
  if (out.empty()) throw FatalError("empty ladder list");
  return out;
}

std::vector<Step> make_ladder(int ab, const std::vector<std::string>& families) {
  if (ab < 1) throw FatalError("the ladder needs -ab 1 or more");
  std::vector<Step> steps;
  for (const std::string& f : families) {
    if (f == "cache") {
      for (const CacheStep& c : kCache)
        steps.push_back(cache_step(ab, c, "cache"));
    } else if (f == "mc") {
      for (const char* ad : kMc)
        steps.push_back(mc_step(ab, ad, "1e-4", "mc"));
    } else if (f == "ab") {
      // Fewer bounces than B, and two more: what each bounce costs and brings.
      for (int b : {1, 2, 3, ab + 2})
        if (b != ab && (b < ab || b == ab + 2)) steps.push_back(cache_step(b, kCache[2], "ab"));
    } else if (f == "lw") {
      for (const char* lw : {"1e-2", "1e-3"})
        steps.push_back(mc_step(ab, "1024", lw, "lw"));
    } else {
      throw FatalError("unknown ladder \"" + f + "\" (cache, mc, ab, lw or all)");
    }
  }
  return steps;
}

} // namespace radcl::cost
