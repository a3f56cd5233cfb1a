#include "radcl/options/render_options.h"

#include "cformat.h"
#include "radcl/util/error.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace radcl::options {
namespace {

constexpr int kMaxPhotonMaps = 6;  // Radiance's NUM_PMAP_TYPES
constexpr int kDefaultGather = 40; // photons per lookup when -ap gives no bandwidth

bool read_words(const std::string& path, std::vector<std::string>& out) {
  std::error_code ec;
  if (path.empty() || std::filesystem::is_directory(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  for (auto& w : split_words(ss.str()))
    out.push_back(std::move(w));
  return true;
}

// -ai/-aI/-ae/-aE: switching list kind restarts the list; file variants add the file's words.
void add_to_list(ModifierList& list, ModifierList::Kind kind, bool from_file,
                 const std::string& value, const FileFinder& find_file, const char* what) {
  if (list.kind != kind) {
    list.kind = kind;
    list.names.clear();
  }
  if (!from_file) {
    list.names.push_back(value);
    return;
  }
  if (!read_words(find_file(value), list.names))
    throw FatalError(std::string("cannot open ") + what + " file \"" + value + "\"");
}

double real_at(const ArgList& a, std::size_t i) {
  return std::atof(a[i].c_str());
}
int int_at(const ArgList& a, std::size_t i) {
  return std::atoi(a[i].c_str());
}

int parse_photon_option(RenderOptions& o, const ArgList& a, std::size_t i) {
  const std::string& w = a[i];
  if (w.size() < 3 || w[1] != 'a') return -1;
  bool glued = w.size() > 3;
  if (w[2] == 'p') {
    o.ambient_bounces += o.ambient_bounces == 0; // a photon map implies ambient bounces
    if (glued || !a.values_ok(i, "s")) return -1;
    if (static_cast<int>(o.photon_maps.size()) >= kMaxPhotonMaps)
      throw FatalError("too many photon maps");
    PhotonMapOption pm;
    pm.file = a[i + 1];
    pm.min_gather = pm.max_gather = kDefaultGather;
    if (!a.values_ok(i, "si")) {
      o.photon_maps.push_back(pm);
      warning("missing photon lookup bandwidth, defaulting to " + std::to_string(kDefaultGather));
      return 1;
    }
    pm.min_gather = pm.max_gather = int_at(a, i + 2);
    if (pm.min_gather == 0) {
      o.photon_maps.push_back(pm); // Radiance has already taken the slot
      return -1;
    }
    if (!a.values_ok(i, "sii")) {
      o.photon_maps.push_back(pm);
      return 2;
    }
    pm.max_gather = int_at(a, i + 3);
    o.photon_maps.push_back(pm);
    return pm.min_gather >= pm.max_gather ? -1 : 3;
  }
  if (w[2] == 'm') {
    if (glued || !a.values_ok(i, "f") || (o.photon_max_radius = real_at(a, i + 1)) <= 0)
      throw FatalError("invalid max photon search radius");
    return 1;
  }
  return -1;
}

} // namespace

RenderOptions RenderOptions::rtrace_defaults() {
  return RenderOptions{};
}

RenderOptions RenderOptions::rpict_defaults() {
  RenderOptions o;
  o.uncorrelated = false;
  o.direct_threshold = 0.05;
  o.direct_certainty = 0.5;
  o.direct_sampling = 0.25;
  o.direct_relays = 1;
  o.ambient_accuracy = 0.2;
  o.ambient_resolution = 64;
  o.ambient_divisions = 512;
  o.ambient_supersamples = 128;
  o.max_depth = 7;
  o.min_weight = 1e-3;
  return o;
}

// rcontrib.c's globals: no shadow-test threshold (-dt 0) nor ambient cache (-aa 0, -as 0), since
// coefficients must not depend on the source and sky values; rcontrib forces those three again
// after parsing (override_options).
RenderOptions RenderOptions::rcontrib_defaults() {
  RenderOptions o;
  o.direct_threshold = 0.0;
  o.direct_jitter = 0.9;
  o.direct_relays = 3;
  o.specular_threshold = 0.02;
  o.ambient_accuracy = 0.0;
  o.ambient_divisions = 350;
  o.ambient_supersamples = 0;
  o.ambient_bounces = 1;
  return o;
}

int parse_render_option(RenderOptions& o, const ArgList& a, std::size_t i,
                        const FileFinder& find_file) {
  if (i >= a.size() || a[i].size() < 2 || a[i][0] != '-') return -1;
  const std::string& w = a[i];
  const char c2 = w.size() > 2 ? w[2] : '\0';
  // An option letter pair followed by values: nothing may be glued on, values must match.
  auto ok = [&](const char* types) { return w.size() == 3 && a.values_ok(i, types); };
  auto rgb = [&](Rgb& v) {
    if (!ok("fff")) return -1;
    v = {real_at(a, i + 1), real_at(a, i + 2), real_at(a, i + 3)};
    return 3;
  };
  auto real = [&](double& v) {
    if (!ok("f")) return -1;
    v = real_at(a, i + 1);
    return 1;
  };
  auto integer = [&](int& v) {
    if (!ok("i")) return -1;
    v = int_at(a, i + 1);
    return 1;
  };
  auto boolean = [&](std::size_t pos, bool& v) { return apply_bool_suffix(w, pos, v) ? 0 : -1; };

  switch (w[1]) {
  case 'u':
    return boolean(2, o.uncorrelated);
  case 'b':
    if (c2 == 'v') return boolean(3, o.back_visible);
    break;
  case 'd':
    switch (c2) {
    case 't':
      return real(o.direct_threshold);
    case 'c':
      return real(o.direct_certainty);
    case 'j':
      return real(o.direct_jitter);
    case 'r':
      return integer(o.direct_relays);
    case 'p':
      return integer(o.direct_pretest);
    case 'v':
      return boolean(3, o.direct_visible);
    case 's':
      return real(o.direct_sampling);
    }
    break;
  case 's':
    switch (c2) {
    case 't':
      return real(o.specular_threshold);
    case 's':
      return real(o.specular_sampling);
    }
    break;
  case 'l':
    switch (c2) {
    case 'r':
      return integer(o.max_depth);
    case 'w':
      return real(o.min_weight);
    }
    break;
  case 'i':
    return boolean(2, o.irradiance);
  case 'a':
    switch (c2) {
    case 'v':
      return rgb(o.ambient_value);
    case 'w':
      return integer(o.ambient_value_weight);
    case 'a':
      return real(o.ambient_accuracy);
    case 'r':
      return integer(o.ambient_resolution);
    case 'd':
      return integer(o.ambient_divisions);
    case 's':
      return integer(o.ambient_supersamples);
    case 'b':
      return integer(o.ambient_bounces);
    case 'i':
    case 'I':
    case 'e':
    case 'E': {
      if (!ok("s")) return -1;
      bool include = c2 == 'i' || c2 == 'I';
      bool file = c2 == 'I' || c2 == 'E';
      add_to_list(o.ambient_list,
                  include ? ModifierList::Kind::Include : ModifierList::Kind::Exclude, file,
                  a[i + 1], find_file, include ? "ambient include" : "ambient exclude");
      return 1;
    }
    case 'f':
      if (!ok("s")) return -1;
      o.ambient_file = a[i + 1];
      return 1;
    }
    break;
  case 'm':
    switch (c2) {
    case 'e':
      return rgb(o.mist_extinction);
    case 'a':
      return rgb(o.mist_albedo);
    case 'g':
      return real(o.mist_eccentricity);
    case 's':
      return real(o.mist_sampling);
    }
    break;
  }
  return parse_photon_option(o, a, i);
}

std::string format_render_defaults(const RenderOptions& o) {
  std::string s;
  auto onoff = [&](bool v, const char* opt, const char* on, const char* off) {
    s += cformat("%s%c\t\t\t\t# %s\n", opt, v ? '+' : '-', v ? on : off);
  };
  onoff(o.irradiance, "-i", "irradiance calculation on", "irradiance calculation off");
  onoff(o.uncorrelated, "-u", "uncorrelated Monte Carlo sampling",
        "correlated quasi-Monte Carlo sampling");
  onoff(o.back_visible, "-bv", "back face visibility on", "back face visibility off");
  s += cformat("-dt %f\t\t\t# direct threshold\n", o.direct_threshold);
  s += cformat("-dc %f\t\t\t# direct certainty\n", o.direct_certainty);
  s += cformat("-dj %f\t\t\t# direct jitter\n", o.direct_jitter);
  s += cformat("-ds %f\t\t\t# direct sampling\n", o.direct_sampling);
  s += cformat("-dr %-9d\t\t\t# direct relays\n", o.direct_relays);
  s += cformat("-dp %-9d\t\t\t# direct pretest density\n", o.direct_pretest);
  onoff(o.direct_visible, "-dv", "direct visibility on", "direct visibility off");
  s += cformat("-ss %f\t\t\t# specular sampling\n", o.specular_sampling);
  s += cformat("-st %f\t\t\t# specular threshold\n", o.specular_threshold);
  // Radiance keeps colours in float.
  auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  s += cformat("-av %f %f %f\t# ambient value\n", f(o.ambient_value[0]), f(o.ambient_value[1]),
               f(o.ambient_value[2]));
  s += cformat("-aw %-9d\t\t\t# ambient value weight\n", o.ambient_value_weight);
  s += cformat("-ab %-9d\t\t\t# ambient bounces\n", o.ambient_bounces);
  s += cformat("-aa %f\t\t\t# ambient accuracy\n", o.ambient_accuracy);
  s += cformat("-ar %-9d\t\t\t# ambient resolution\n", o.ambient_resolution);
  s += cformat("-ad %-9d\t\t\t# ambient divisions\n", o.ambient_divisions);
  s += cformat("-as %-9d\t\t\t# ambient super-samples\n", o.ambient_supersamples);
  s += cformat("-me %.2e %.2e %.2e\t# mist extinction coefficient\n", f(o.mist_extinction[0]),
               f(o.mist_extinction[1]), f(o.mist_extinction[2]));
  s += cformat("-ma %f %f %f\t# mist scattering albedo\n", f(o.mist_albedo[0]), f(o.mist_albedo[1]),
               f(o.mist_albedo[2]));
  s += cformat("-mg %f\t\t\t# mist scattering eccentricity\n", o.mist_eccentricity);
  s += cformat("-ms %f\t\t\t# mist sampling distance\n", o.mist_sampling);
  s += cformat("-lr %-9d\t\t\t# limit reflection%s\n", o.max_depth,
               o.max_depth <= 0 ? " (Russian roulette)" : "");
  s += cformat("-lw %.2e\t\t\t# limit weight\n", o.min_weight);
  s += cformat("-am %.1f\t\t\t\t# max photon search radius\n", o.photon_max_radius);
  return s;
}

} // namespace radcl::options
