// The rendering options rtrace, rpict and rcontrib share (Radiance's renderopts.c and
// pmapopt.c), with each program's 5.4a defaults, parsing and the "-defaults" listing.
#pragma once

#include "radcl/options/args.h"

#include <array>
#include <string>
#include <vector>

namespace radcl::options {

using Rgb = std::array<double, 3>;

// -ae/-ai/-aE/-aI (and rtrace's -te/-ti/-tE/-tI): one list of names, either included or
// excluded. Switching between include and exclude starts a new list.
struct ModifierList {
  enum class Kind { None, Include, Exclude };
  Kind kind = Kind::None;
  std::vector<std::string> names;
};

// -ap file [bwidth [bwidth2]]
struct PhotonMapOption {
  std::string file;
  int min_gather = 40;
  int max_gather = 40;
};

struct RenderOptions {
  bool irradiance = false;                  // -i
  bool uncorrelated = true;                 // -u (rtrace on, rpict off)
  bool back_visible = true;                 // -bv
  double direct_threshold = 0.03;           // -dt
  double direct_certainty = 0.75;           // -dc
  double direct_jitter = 0.0;               // -dj
  double direct_sampling = 0.2;             // -ds (source subdivision ratio)
  int direct_relays = 2;                    // -dr
  int direct_pretest = 512;                 // -dp
  bool direct_visible = true;               // -dv
  double specular_sampling = 1.0;           // -ss
  double specular_threshold = 0.15;         // -st
  Rgb ambient_value{0, 0, 0};               // -av
  int ambient_value_weight = 0;             // -aw
  int ambient_bounces = 0;                  // -ab
  double ambient_accuracy = 0.1;            // -aa
  int ambient_resolution = 256;             // -ar
  int ambient_divisions = 1024;             // -ad
  int ambient_supersamples = 512;           // -as
  std::string ambient_file;                 // -af ("" = none)
  ModifierList ambient_list;                // -ae -ai -aE -aI
  Rgb mist_extinction{0, 0, 0};             // -me
  Rgb mist_albedo{0, 0, 0};                 // -ma
  double mist_eccentricity = 0.0;           // -mg
  double mist_sampling = 0.0;               // -ms
  int max_depth = -10;                      // -lr (<= 0: Russian roulette)
  double min_weight = 2e-3;                 // -lw
  std::vector<PhotonMapOption> photon_maps; // -ap
  double photon_max_radius = 0.0;           // -am

  static RenderOptions rtrace_defaults();
  static RenderOptions rpict_defaults();
  static RenderOptions rcontrib_defaults();
};

// Tries the rendering option at args[i] (already expanded). Returns the number of values it
// consumed, or -1 if it is not a (well-formed) rendering option: the caller then tries its own
// options and finally reports "command line error". Throws FatalError for the errors Radiance
// reports here ("cannot open ambient include file ...", "invalid max photon search radius",
// "too many photon maps").
int parse_render_option(RenderOptions& opt, const ArgList& args, std::size_t i,
                        const FileFinder& find_file = default_find_file);

// Radiance's print_rdefaults() lines, from "-i" to "-am".
std::string format_render_defaults(const RenderOptions& opt);

} // namespace radcl::options
