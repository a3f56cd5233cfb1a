// Host evaluation of a prism1/prism2 material's redirections (Radiance's m_direct functions),
// which the virtual sources of its surfaces need before rendering: the coefficient and new
// direction for a ray of given direction meeting a given point.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "radcl/scene/scene.h"

namespace radcl::render {

class RedirectFunction {
public:
  using V3 = std::array<double, 3>;
  // Loads the material's function file (on RAYPATH) and parses its expressions; FatalError
  // as when the material is compiled.
  explicit RedirectFunction(const scene::Object& material);
  ~RedirectFunction();
  RedirectFunction(RedirectFunction&&) noexcept;
  RedirectFunction& operator=(RedirectFunction&&) noexcept;

  int count() const { return count_; } // redirections: 1 (prism1) or 2 (prism2)
  // Redirection k for a ray of unit world direction d meeting world point p whose surface
  // normal is n (DxA, DyA, DzA = 0). False on a compute error; else the coefficient and the new
  // direction in world space (not normalised, as Radiance's dir_proj).
  bool eval(int k, const V3& p, const V3& d, const V3& n, double& coef, V3& dir) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int count_ = 1;
};

} // namespace radcl::render
