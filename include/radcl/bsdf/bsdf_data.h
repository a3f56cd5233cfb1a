// The data of a Radiance BSDF file (LBNL WINDOW XML), as read: the host side of the BSDF and
// aBSDF materials. read_bsdf_xml() (xml_reader.h) fills it; evaluate.h evaluates it.
//
// Frame and sides follow Radiance (bsdf.h): in the BSDF's local frame X lies in the surface,
// Y is "up" and Z is the surface normal; the front is the +Z side. That is the reverse of
// WINDOW's naming, whose front is the exterior: a block the file calls "Transmission Front"
// (light arriving on WINDOW's front) is Radiance's back-incident transmission, TransmitBack here.
// Both vectors of a BSDF point away from the surface: `in` towards the light, `out` towards the
// viewer.
#pragma once

#include "radcl/bsdf/klems_basis.h"
#include "radcl/bsdf/tensor_tree.h"

#include <string>
#include <vector>

namespace radcl::bsdf {

enum class Format { Klems, TensorTree3, TensorTree4 };

// Radiance's four components (rf, rb, tf, tb), named by the side light arrives on.
enum class Part {
  ReflectFront,  // in and out on +Z; the file's "Reflection Back"
  ReflectBack,   // in and out on -Z; "Reflection Front"
  TransmitFront, // in on +Z, out on -Z; "Transmission Back"
  TransmitBack,  // in on -Z, out on +Z; "Transmission Front"
};

// A Klems matrix. Values are BSDFs in 1/sr (negative ones read as 0, as Radiance does), stored
// with the outgoing patch as the row: value(in i, out o) at [o * in_basis.size() + i], whichever
// IncidentDataStructure ("Columns": the file's rows are outgoing; "Rows": incident) the file
// used. The column basis of the file is the incident basis, the row basis the outgoing one.
struct KlemsMatrix {
  KlemsBasis in_basis;
  KlemsBasis out_basis;
  std::vector<float> y;    // CIE Y ("Visible")
  std::vector<float> x, z; // CIE X and Z ("CIE-X", "CIE-Z"); both empty unless the file has both
  float value(int in_patch, int out_patch) const {
    return y[out_patch * in_basis.size() + in_patch];
  }
};

// Tensor trees of one component: Y, and the CIE 1976 u' and v' chromaticity trees for colour.
struct TreeSet {
  TensorTree y;    // "Visible"
  TensorTree u, v; // "CIE-u", "CIE-v"; both empty unless the file has both
};

struct Component {
  Part part = Part::ReflectFront;
  Format format = Format::Klems;
  std::string direction;       // as the file names it, e.g. "Transmission Back"
  std::string scattering_type; // "BTDF"/"BRDF" as written; unused (Radiance ignores it)
  KlemsMatrix klems;           // Format::Klems
  TreeSet tree;                // tensor-tree formats
  bool colour() const { return format == Format::Klems ? !klems.x.empty() : !tree.u.empty(); }
};

struct BsdfData {
  std::string name; // the file, as messages name it
  Format format = Format::Klems;
  // <Material>: name, manufacturer, device type; width, height and thickness in meters (0 when
  // absent).
  std::string material, manufacturer, device_type;
  double width = 0, height = 0, thickness = 0;
  std::string mgf;                   // <Geometry><MGFblock> text from its first non-blank
  double mgf_scale = 1;              // its unit in meters
  std::vector<Component> components; // at most one per Part, in the file's order

  const Component* find(Part part) const {
    for (const Component& c : components)
      if (c.part == part) return &c;
    return nullptr;
  }
};

} // namespace radcl::bsdf
