#include "radcl/bsdf/evaluate.h"

#include <cmath>
#include <utility>

namespace radcl::bsdf {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Which side (front: +Z) light arrives on and leaves from, for each component.
bool in_front(Part p) {
  return p == Part::ReflectFront || p == Part::TransmitFront;
}
bool out_front(Part p) {
  return p == Part::ReflectFront || p == Part::TransmitBack;
}

Xyz grey(double y) {
  return {y, y, y};
}

Xyz klems_f(const Component& c, const vec::Vec3& in, const vec::Vec3& out) {
  const KlemsMatrix& m = c.klems;
  int i = incident_patch(m.in_basis, in, in_front(c.part));
  int o = outgoing_patch(m.out_basis, out, out_front(c.part));
  if (i < 0 && o < 0) {
    i = incident_patch(m.in_basis, out, in_front(c.part));
    o = outgoing_patch(m.out_basis, in, out_front(c.part));
  }
  if (i < 0 || o < 0) return {};
  const size_t at = static_cast<size_t>(o) * m.in_basis.size() + i;
  if (m.x.empty()) return grey(m.y[at]);
  return {m.x[at], m.y[at], m.z[at]};
}

Xyz tree_f(const Component& c, vec::Vec3 in, vec::Vec3 out) {
  switch (c.part) {
  case Part::ReflectFront:
    if (in[2] < 0 || out[2] < 0) return {};
    break;
  case Part::ReflectBack:
    if (in[2] > 0 || out[2] > 0) return {};
    break;
  case Part::TransmitFront:
    if (out[2] > 0) {
      if (in[2] > 0) return {};
      std::swap(in, out);
    } else if (in[2] < 0) {
      return {};
    }
    break;
  case Part::TransmitBack:
    if (in[2] > 0) {
      if (out[2] > 0) return {};
      std::swap(in, out);
    } else if (out[2] < 0) {
      return {};
    }
    break;
  }
  const double y = c.tree.y.value(in, out);
  if (c.tree.u.empty()) return grey(y);
  // CIE 1976 (u', v') to X and Z at this Y.
  const double u = c.tree.u.value(in, out), v = c.tree.v.value(in, out);
  if (!(v > 0)) return grey(y);
  return {y * 9 * u / (4 * v), y, y * (12 - 3 * u - 20 * v) / (4 * v)};
}

Xyz add(Xyz a, const Xyz& b, double w) {
  a.x += w * b.x;
  a.y += w * b.y;
  a.z += w * b.z;
  return a;
}

// Klems data are constant over each patch: the integral is a sum over the outgoing patches.
// Those are the outgoing basis's, or under reciprocity (`in` has no incident patch here) the
// incident basis's, whose directions are reversed across the surface.
Xyz klems_hemispherical(const Component& c, const vec::Vec3& in, double zsign) {
  const KlemsMatrix& m = c.klems;
  const bool reverse = incident_patch(m.in_basis, in, in_front(c.part)) < 0;
  const KlemsBasis& b = reverse ? m.in_basis : m.out_basis;
  const double flip = reverse ? -1 : 1;
  Xyz sum;
  for (int o = 0; o < b.size(); ++o) {
    const vec::Vec3 d = b.centre(o);
    sum = add(sum, klems_f(c, in, {flip * d[0], flip * d[1], zsign * d[2]}), b.lambda(o));
  }
  return sum;
}

} // namespace

Xyz f(const Component& c, const vec::Vec3& in, const vec::Vec3& out) {
  return c.format == Format::Klems ? klems_f(c, in, out) : tree_f(c, in, out);
}

const Component* component_for(const BsdfData& d, const vec::Vec3& in, const vec::Vec3& out) {
  const bool fin = in[2] > 0, fout = out[2] > 0;
  if (fin && fout) return d.find(Part::ReflectFront);
  if (!fin && !fout) return d.find(Part::ReflectBack);
  const Part mine = fin ? Part::TransmitFront : Part::TransmitBack;
  const Part other = fin ? Part::TransmitBack : Part::TransmitFront;
  const Component* c = d.find(mine);
  return c ? c : d.find(other);
}

Xyz f(const BsdfData& d, const vec::Vec3& in, const vec::Vec3& out) {
  const Component* c = component_for(d, in, out);
  return c ? f(*c, in, out) : Xyz{};
}

Xyz hemispherical(const BsdfData& d, const vec::Vec3& in, bool reflection, int n) {
  const bool front_in = in[2] > 0;
  const double zsign = (front_in == reflection) ? 1 : -1;
  const Component* c = component_for(d, in, {0, 0, zsign});
  if (!c) return {};
  if (c->format == Format::Klems) return klems_hemispherical(*c, in, zsign);
  if (n <= 0) return {};
  // A TT3 lookup turns the outgoing vector by minus this angle; turning the grid by it makes
  // the lookup see the grid's own cells (only where the tree's incident vector is `in`).
  double angle = 0;
  if (c->format == Format::TensorTree3) angle = std::atan2(-in[1], -in[0]);
  const double ca = std::cos(angle), sa = std::sin(angle);
  Xyz sum;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto dk = square_to_disk((i + 0.5) / n, (j + 0.5) / n);
      const double z = std::sqrt(std::fmax(0.0, 1 - dk[0] * dk[0] - dk[1] * dk[1]));
      const vec::Vec3 out{dk[0] * ca - dk[1] * sa, dk[0] * sa + dk[1] * ca, zsign * z};
      sum = add(sum, f(*c, in, out), 1);
    }
  const double w = kPi / (static_cast<double>(n) * n);
  return {sum.x * w, sum.y * w, sum.z * w};
}

} // namespace radcl::bsdf
