// prism1/prism2 redirections on the host, with the calc module's evaluator: the same function
// file, expressions and transform the material's device record holds (func_materials.cpp).
#include "radcl/render/lights/redirect_function.h"

#include <cmath>
#include <string>

#include "radcl/calc/evaluator.h"
#include "radcl/calc/program.h"
#include "radcl/scene/object_type.h"
#include "radcl/scene/raypath.h"
#include "radcl/scene/transform.h"
#include "radcl/util/error.h"

namespace radcl::render {

struct RedirectFunction::Impl {
  calc::Program program;
  std::vector<calc::Expression> exprs; // coef, dx, dy, dz per redirection
  scene::Transform xf, inv;            // function space -> world, and back
  std::vector<double> args;
};

RedirectFunction::RedirectFunction(const scene::Object& m) : impl_(std::make_unique<Impl>()) {
  const std::string where = std::string(scene::type_name(m.type)) + " \"" + m.name + "\"";
  const std::size_t nexpr = m.type == RC_OBJ_PRISM2 ? 8 : 4;
  count_ = static_cast<int>(nexpr / 4);
  if (m.sargs.size() < nexpr + 1) throw FatalError("bad # arguments for " + where);
  impl_->program.load_rayinit();
  std::string ctx;
  if (m.sargs[nexpr] != ".") {
    const std::string path = scene::find_on_raypath(m.sargs[nexpr]);
    if (path.empty())
      throw FatalError(where + ": cannot find function file \"" + m.sargs[nexpr] + "\"");
    ctx = calc::Program::context_for_file(m.sargs[nexpr]);
    impl_->program.load_file(path, ctx);
  }
  for (std::size_t i = 0; i < nexpr; ++i)
    impl_->exprs.push_back(impl_->program.parse_expression(m.sargs[i], ctx, where));
  try {
    impl_->xf = scene::parse_transform(m.sargs, nexpr + 1);
  } catch (const FatalError&) {
    throw FatalError("bad transform for " + where);
  }
  impl_->inv = impl_->xf.inverse();
  impl_->args.assign(m.fargs.begin(), m.fargs.end());
}

RedirectFunction::~RedirectFunction() = default;
RedirectFunction::RedirectFunction(RedirectFunction&&) noexcept = default;
RedirectFunction& RedirectFunction::operator=(RedirectFunction&&) noexcept = default;

namespace {
RedirectFunction::V3 unit(RedirectFunction::V3 v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (l > 0)
    for (double& x : v)
      x /= l;
  return v;
}
} // namespace

bool RedirectFunction::eval(int k, const V3& p, const V3& d, const V3& n, double& coef,
                            V3& dir) const {
  std::vector<double> slots(RC_CALC_NSLOTS, 0.0);
  const V3 df = unit(impl_->inv.vector(d)), nf = unit(impl_->inv.vector(n));
  const V3 pf = impl_->inv.point(p);
  for (int i = 0; i < 3; ++i) {
    slots[RC_CALC_DX + i] = df[i];
    slots[RC_CALC_NX + i] = nf[i];
    slots[RC_CALC_PX + i] = pf[i];
  }
  slots[RC_CALC_RDOT] = -(d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
  slots[RC_CALC_S] = 1 / impl_->xf.scale;
  calc::Evaluator ev(impl_->program);
  ev.set_warnings(false);
  ev.set_ray(slots);
  ev.set_args(impl_->args);
  const std::size_t b = static_cast<std::size_t>(4 * k);
  coef = ev.eval(impl_->exprs[b]);
  const V3 f{ev.eval(impl_->exprs[b + 1]), ev.eval(impl_->exprs[b + 2]),
             ev.eval(impl_->exprs[b + 3])};
  if (ev.errors() != 0) return false;
  dir = impl_->xf.vector(f);
  return std::isfinite(coef) && std::isfinite(dir[0]) && std::isfinite(dir[1]) &&
         std::isfinite(dir[2]);
}

} // namespace radcl::render
