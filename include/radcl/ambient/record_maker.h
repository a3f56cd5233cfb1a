// Making irradiance-cache records from sampled hemispheres on the device
// (kernels/ambient/ambient_record.cl, Radiance's doambient after sampling), and turning a made
// record into the file's form. Which points get records and how their samples are traced is
// the caller's business; docs/cache-internals.md ("Making a record") gives the inputs' meaning.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "radcl/ambient/record.h"
#include "radcl/device/buffer.h"
#include "radcl/device/program.h"
#include "radcl/device_types.h"

namespace radcl::ambient {

// Radiance's AVGREFL: the reflectance makeambient assumes for the weight and the value.
constexpr double kAvgRefl = 0.5;

// makeambient's record weight: AVGREFL^level, or 1.25 x the ray's weight where that is below a
// tenth of it. It is also the `wt` doambient gets (rc_amb_hemi.pos.w).
float ambient_record_weight(int level, double ray_weight);

// The settings every hemisphere of a pass shares, put into its rc_amb_hemi.
struct HemisphereSettings {
  double minarad = 0; // Radiance's minarad (ambient_min_radius)
  double maxarad = 0; // Radiance's maxarad
  double aa = 0;      // -aa
};

// An rc_amb_hemi: point p (re-centred) with unit normal n and unit tangent ux (uy = n x ux),
// ns divisions per axis, samples from index `first`.
rc_amb_hemi make_hemisphere(const std::array<double, 3>& p, const std::array<double, 3>& n,
                            const std::array<double, 3>& ux, unsigned ns, unsigned first, int level,
                            double weight, const HemisphereSettings& s);

struct MadeRecords {
  std::vector<rc_amb_record> records; // one per hemisphere (value and level always set)
  std::vector<rc_amb_made> made;      // corral bits and RC_AMB_* status
};

class RecordMaker {
public:
  explicit RecordMaker(device::Context& ctx);

  // Hemispheres and samples already on the device: fills `records` (rc_amb_record) and
  // `made` (rc_amb_made), `count` entries each. Queued; the caller reads or finishes.
  void run(const device::Buffer& hemis, const device::Buffer& samples, std::uint32_t count,
           device::Buffer& records, device::Buffer& made);
  // The same from host arrays.
  MadeRecords make(std::span<const rc_amb_hemi> hemis, std::span<const rc_amb_sample> samples);

private:
  device::Context& ctx_;
  device::Program program_;
  device::Kernel kernel_;
  device::Buffer hemis_, samples_, records_, made_; // make()'s, grown as needed
  device::Buffer& room(device::Buffer& b, std::size_t bytes);
};

// A made record in the file's form: world position (re-centred position + `centre`, in double),
// encoded normal and u axis, radii, gradients, value, level, weight and corral bits.
ambient::AmbientRecord to_ambient_record(const rc_amb_record& r, std::uint32_t corral,
                                         const std::array<double, 3>& centre);

} // namespace radcl::ambient
