// Klems angle bases: a hemisphere cut into rings of constant polar angle, each ring into equal
// azimuth patches. The three LBNL bases are built in; a BSDF file may define others.
//
// Directions here are in a hemisphere's canonical frame: z >= 0 is the polar axis (the surface
// normal), phi is measured from +x towards +y and patch j of a ring is centred on
// phi = j * 360 / nphis degrees (so patch 0 straddles +x). How a component's incident and
// outgoing vectors map into this frame is incident_patch()/outgoing_patch() below.
//
// Layout for a device: theta bounds (rings + 1 floats, degrees), nphis and first patch per ring
// (ints); the patch of a direction is found by scanning the rings, as patch() does.
#pragma once

#include "radcl/util/vec3.h"

#include <string>
#include <vector>

namespace radcl::bsdf {

class KlemsBasis {
public:
  KlemsBasis() = default;
  // theta_bounds: rings + 1 polar angles in degrees, increasing, the first 0, at most 90;
  // nphis: patches per ring (1 only for a polar cap). Throws FatalError(message) when invalid.
  KlemsBasis(std::string name, std::vector<double> theta_bounds, std::vector<int> nphis);

  // "LBNL/Klems Full" (145 patches), "LBNL/Klems Half" (73), "LBNL/Klems Quarter" (41), matched
  // without regard to case; nullptr for any other name.
  static const KlemsBasis* standard(const std::string& name);

  const std::string& name() const { return name_; }
  int size() const { return size_; }
  int rings() const { return static_cast<int>(nphis_.size()); }
  double theta_lower(int ring) const { return theta_[ring]; } // degrees
  double theta_upper(int ring) const { return theta_[ring + 1]; }
  int nphis(int ring) const { return nphis_[ring]; }
  int first_patch(int ring) const { return first_[ring]; }
  int ring_of(int patch) const;

  // Patch holding a canonical direction (need not be unit), or -1 below the horizon (z < 0), at
  // or beyond the last ring's upper bound.
  int patch(const vec::Vec3& dir) const;
  // The unit direction at a patch's centre: the middle polar angle of its ring (the pole for a
  // one-patch cap starting at 0) and the middle azimuth of the patch.
  vec::Vec3 centre(int patch) const;
  // Projected solid angle of a patch, the integral of cos(theta) over it:
  // pi * (cos^2 lower - cos^2 upper) / nphis (Radiance's "lambda").
  double lambda(int patch) const;

private:
  std::string name_;
  std::vector<double> theta_;
  std::vector<int> nphis_;
  std::vector<int> first_;
  int size_ = 0;
};

// Radiance's Klems conventions for vectors in the BSDF's local frame (front = +Z, both vectors
// pointing away from the surface). An incident vector (towards the light) is indexed by the
// direction the light travels across the surface: the patch of (-x, -y, |z|); an outgoing one
// by (x, y, |z|). So the matrix diagonal is the mirror direction for reflection and the
// straight-through direction for transmission. `front` names the side the vector must be on
// (z > 0 front, z < 0 back; z == 0 is on both); -1 when it is on the other side.
int incident_patch(const KlemsBasis& basis, const vec::Vec3& in, bool front);
int outgoing_patch(const KlemsBasis& basis, const vec::Vec3& out, bool front);

} // namespace radcl::bsdf
