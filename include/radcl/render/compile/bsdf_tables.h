// BSDF files flattened for the device: the records and the two arrays of
// include/radcl/bsdf_device_types.h (which documents the layout), which
// kernels/materials/bsdf_eval.cl evaluates and samples.
//
// Radiance's preprocessing (bsdf_m.c, bsdf_t.c, SDloadFile in bsdf.c) is applied here, since
// radcl::bsdf keeps the data as read:
// - Lambertian split. The smallest value of each component is split off as a Lambertian
//   part, unless it is at most 0.01/pi. Klems: over the whole matrix. Tensor trees: over the
//   leaves a lookup can reach (TT3 never reads the upper half of its incident dimension), and
//   for grey trees not when it is 1.5/pi or more. Where Radiance works with colour in its own
//   RGB space (chromaticities quantised, minima of RGB), radcl subtracts the minimum of each of
//   CIE X, Y and Z, so that the Lambertian part plus the residual give back every value.
// - The residual's maxHemi, as Radiance computes it: the largest total over the incident
//   patches (Klems), or pi times the largest mean of the tree over strips of the incident
//   dimensions as wide as its smallest leaf but at least 1/32, less the Lambertian total.
// - A residual whose maxHemi is at most 0.001 is dropped; its Lambertian part stays.
// - Where a file has transmission for one side only, the other side's Lambertian transmission
//   is the same (the residual is used through reciprocity, as radcl::bsdf::f does).
// So the device's f of a file is the host's (radcl::bsdf::f) except where a residual was
// dropped, and beyond a Klems basis that ends before 90 degrees, where the Lambertian part
// still applies (as in Radiance) and the host gives 0.
// Tensor trees are stored with the Y, u' and v' trees merged into one tree of XYZ leaves and
// every leaf grid divided into single-value leaves, so that a lookup and a sample are one walk.
#pragma once

#include "radcl/bsdf/bsdf_data.h"
#include "radcl/bsdf_device_types.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace radcl::render {

class BsdfTables {
public:
  // Appends one file; returns the index of its rc_bsdf record. Throws FatalError when the
  // tables would exceed the device's 32-bit offsets (a very deep tensor tree).
  std::uint32_t add(const bsdf::BsdfData& data);

  std::vector<rc_bsdf> files;
  std::vector<rc_bsdf_comp> comps;
  std::vector<float> vals;
  std::vector<std::int32_t> ints;

private:
  std::map<std::vector<double>, std::uint32_t> bases_; // Klems bases already stored
  std::uint32_t add_basis(const bsdf::KlemsBasis& b, const std::string& file);
  // Fill rec (its Lambertian part always) and append the residual's data; false, appending
  // nothing, when the residual is dropped.
  bool add_klems(const bsdf::Component& c, const std::string& file, rc_bsdf_comp& rec);
  bool add_tree(const bsdf::Component& c, const std::string& file, rc_bsdf_comp& rec);
};

} // namespace radcl::render
