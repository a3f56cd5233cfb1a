// The wavefront renderer: Embree traversal on the host, shading in OpenCL kernels, rays in
// waves (../shared/docs/design.md §3). Primary rays in, one result per primary out.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "radcl/ambient/record.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/render/compile/compiled_scene.h"
#include "radcl/render/pipeline/tuning.h"
#include "radcl/scene/loader.h"

namespace radcl::device {
class Context;
}

namespace radcl::render {

using Vec3d = std::array<double, 3>;

// Rendering settings with Radiance's meaning (../shared/docs/radiance/cli-rtrace-rpict.md §2);
// defaults are rtrace's.
struct RenderSettings {
  double ds = 0.2, dj = 0, dt = 0.03, dc = 0.75;
  int dr = 2;   // -dr: mirrors a virtual source may be relayed through (rpict's default is 1)
  int dp = 512; // -dp: virtual-source pretest density (samples/sr), 0 = always follow the way
  bool dv = true, bv = true;
  double ss = 1, st = 0.15;
  Vec3d av{0, 0, 0};
  // The global participating medium (-me, -ma, -mg, -ms): extinction per unit length, the
  // scattering albedo, the eccentricity and the source-scattering sample distance.
  Vec3d me{0, 0, 0}, ma{0, 0, 0};
  double mg = 0, ms = 0;
  int aw = 0; // -aw: weight of -av in its running average with the cache's values
  int ab = 0;
  int ad = 1024; // -aa 0 hemisphere divisions
  int as = 128;  // -as super-samples spread over a hemisphere's high-variance divisions
  // The irradiance cache (-aa > 0 with -ab > 0): these records (from -af) answer the ambient
  // lookups they cover, by Radiance's tests and weights. With make_records, points no record
  // covers get new records (Renderer::take_new_records), made from hemisphere samples as
  // Radiance makes them; without, they are sampled as with -aa 0.
  double aa = 0;
  double ambient_min_radius = 0; // Radiance's minarad: the octree cube's size / -ar
  double ambient_max_radius = 0; // Radiance's maxarad: 64 minarad, at most half the cube
  double cube_size = 0;          // the octree cube (sample points are clamped at 10 cubes)
  bool make_records = false;
  std::vector<ambient::AmbientRecord> ambient_records;
  // -ae/-ai/-aE/-aI: hits on surfaces whose modifier is excluded (or, with an include list, not
  // included) take -av instead of sampling.
  enum class AmbientList { None, Include, Exclude };
  AmbientList ambient_list = AmbientList::None;
  std::vector<std::string> ambient_names;
  int lr = -10;
  double lw = 2e-3;
  bool irradiance_i = false; // -i: primary hits become irradiance meters
  bool irradiance_I = false; // -I: the inputs are measurement points and normals
  std::uint32_t seed = 0;
  // Radiance's -u-: first-hit samples follow a low-discrepancy sequence over the primary ray
  // ids (neighbouring pixels stratify each other) instead of independent random numbers.
  bool low_discrepancy = false;
  std::size_t wave_size = 1u << 18; // primaries per wave
  // rtrace's trace modes: every ray of each primary's tree is reported (-ot), shadow rays
  // too (-oT).
  enum class Trace { Off, Rays, RaysAndShadows };
  Trace trace = Trace::Off;
  // rtrace's -oe (radcl's own): each primary's standard error from the spread of its first
  // hemispheres' divisions (PrimaryResult::std_error). Values are those without it, up to the
  // order their double sums are added in.
  bool std_error = false;
  // rcontrib: the tracked modifiers (null: rtrace and rpict). Each primary's result then
  // holds its bins (PrimaryResult::contrib) and `value` stays 0. Needs -aa 0, -as 0, -dt 0
  // and no trace mode, as rcontrib forces.
  std::shared_ptr<const ContribSpec> contrib;
  // How the pipeline runs (the same outputs whatever it says, leak_test aside).
  PipelineTuning tuning;
};

// One ray of a primary's tree in trace mode (rtrace -ot/-oT), in Radiance's terms.
struct TracedRay {
  int depth = 0; // ancestors: rtrace indents a traced ray by one TAB per ancestor
  bool shadow = false;
  Vec3d org{}, dir{};
  Vec3d value{};        // the ray's own radiance (Radiance's rcol)
  Vec3d contribution{}; // what it adds to the primary: value x coefficient (V)
  Vec3d coef{};         // product of coefficients back to the primary (W)
  double weight = 0;    // w
  bool hit = false;     // a surface (not just a distant source) was hit
  double t = 1e10;
  Vec3d point{}, normal{};
  std::uint32_t surface = RC_NONE;
};

struct PrimaryRay {
  Vec3d org{};
  Vec3d dir{};     // need not be unit
  double tmax = 0; // 0: unlimited
  // Identity keying this ray's random numbers (rpict: the pixel number); RC_NONE = its index
  // in the whole input. Ids must be unique within one render() call.
  std::uint32_t id = RC_NONE;
};

struct PrimaryResult {
  Vec3d value{};                   // radiance (or irradiance with -i/-I), W/sr/m2 or W/m2
  bool hit = false;                // a surface (not just a distant source) was hit
  double t = 1e10;                 // distance to the first intersection
  Vec3d point{};                   // first intersection (the origin if nothing was hit)
  Vec3d normal{};                  // unperturbed normal at it, 0 if nothing hit
  std::uint32_t surface = RC_NONE; // compiled surface of the first hit (names), or RC_NONE
  Vec3d mirrored{}; // part of `value` that came through the first hit's mirror reflection
  // Distance the mirror-reflected ray travelled (1e10: nothing hit; 0: reflected about a
  // texture-tilted normal, so the image lies at the surface), -1: none.
  double mirror_t = -1;
  double through_t = -1; // length of the straight transmission beyond the first hit, -1: none
  Vec3d through_at{};    // where that transmission last met a surface (its lengths add up)
  // The hit's normal perturbation once shaded (Radiance's r->pert): a smoothed mesh's tilt plus
  // the textures' (texfunc, texdata; a mixture's blended by its coefficients), world, in the
  // frame of `normal`: normal + pert, made unit, is the perturbed normal (rtrace's -on).
  Vec3d pert{};
  std::vector<TracedRay> traced; // trace mode: the tree in post-order (children first)
  // RenderSettings::std_error: the standard error of `value` (rgb) as the spread of the
  // hemisphere samples at the first ambient bounce estimates it (0 where none was sampled).
  Vec3d std_error{};
  // RenderSettings::contrib: every bin of every tracked modifier, in order, rgb (3 per bin).
  std::vector<double> contrib;
};

// Rays traced so far (what Embree was asked), for reports and benchmarks.
struct RenderStats {
  std::uint64_t primary = 0;      // first-wave rays (not counted for -I meters)
  std::uint64_t secondary = 0;    // reflected, transmitted, specular and ambient rays
  std::uint64_t shadow = 0;       // shadow-ray segments (one per surface passed)
  std::uint64_t shadow_steps = 0; // of those, the ones the device stepped (others: the host)
  std::uint64_t records = 0;      // irradiance-cache records made
  std::uint64_t leak_tests = 0;   // cache records' leak-test rays (Radiance's plugaleak)
  std::uint64_t leaks = 0;        // hits at which some record's test ray was blocked
  std::uint64_t bad_bins = 0;     // rcontrib: contributions to a bin beyond its modifier's count
  std::uint64_t total() const { return primary + secondary + shadow; }
};

class Renderer {
public:
  Renderer(const scene::LoadedScene& scene, const RenderSettings& settings, device::Context& ctx);
  ~Renderer();

  // Traces the primaries and their ray trees; results[i] belongs to rays[i].
  void render(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results);

  // Irradiance-cache records made since the last call (RenderSettings::make_records), in world
  // coordinates, for the -af file.
  std::vector<ambient::AmbientRecord> take_new_records();
  // True when misses become records: then a batch's values depend on which rays share it.
  bool builds_cache() const;
  // Adds records other processes wrote to the shared -af file.
  void add_records(std::span<const ambient::AmbientRecord> records);

  const CompiledScene& compiled() const;
  const RenderStats& stats() const;
  const geometry::SceneGeometry& geometry() const;

  struct Impl;

private:
  std::unique_ptr<Impl> impl_;
};

} // namespace radcl::render
