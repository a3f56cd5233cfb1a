// Host reference evaluation of BSDF data, for tests and checks of the device code. It follows
// Radiance's SDevalBSDF/SDdirectHemi on the raw data (Radiance also splits off a Lambertian
// part, which changes no value).
#pragma once

#include "radcl/bsdf/bsdf_data.h"

namespace radcl::bsdf {

// CIE XYZ of a BSDF value (1/sr) or of a hemispherical total. Grey data give X = Y = Z (the
// equal-energy white Radiance gives grey BSDFs).
struct Xyz {
  double x = 0, y = 0, z = 0;
};

// One component's BSDF for vectors in the local frame (front = +Z, both pointing away from the
// surface; bsdf_data.h). Zero where the pair does not fit the component's sides, after
// Radiance's reciprocity: a pair that fits with in and out exchanged is looked up that way (for
// Klems when neither direction has a patch, for tensor trees for transmission).
Xyz f(const Component& c, const vec::Vec3& in, const vec::Vec3& out);

// The component Radiance evaluates for a pair: reflection when in and out lie on the same side
// (front where z > 0), else transmission; when the file has no transmission for light arriving
// on in's side, the other side's (through the reciprocity above). nullptr when there is none.
const Component* component_for(const BsdfData& d, const vec::Vec3& in, const vec::Vec3& out);

// The BSDF for a pair of directions: f of component_for, or 0.
Xyz f(const BsdfData& d, const vec::Vec3& in, const vec::Vec3& out);

// Directional-hemispherical reflectance (`reflection`) or transmittance for light from `in`:
// the integral of f cos(theta) over the outgoing hemisphere. Klems data are constant over each
// patch, so that is the sum of f * lambda over the outgoing patches (exact). Tensor trees are
// integrated by the midpoint rule on an n x n grid of the Shirley-Chiu square (an equal-area map
// of the projected hemisphere), turned for an isotropic tree with the incident plane so that the
// cells fall inside the tree's leaves: exact once n is a multiple of the finest leaf resolution.
Xyz hemispherical(const BsdfData& d, const vec::Vec3& in, bool reflection, int n = 256);

} // namespace radcl::bsdf
