/* Support for code generated from .cal files (src/calc/codegen.cpp): Radiance's arithmetic
 * error rules (a non-finite result becomes 0 and raises an error bit,
 * ../shared/docs/radiance/calc-language.md §3.2), its rand(), arg() and the shared noise functions.
 */
#include "radcl/calc/device_context.h"
#include "radcl/device_types.h" /* RC_NOINLINE */
/* Empty: PoCL's compile time grows exponentially with unrolled recursion marked noinline. */
#define RC_CALC_NOINLINE
#define RC_NOISE_REAL rc_calc_real
#include "radcl/calc/noise.h"

rc_calc_real rc_calc_check(rc_calc_env* e, rc_calc_real r) {
  if (isfinite(r)) return r;
  e->error |= RC_CALC_ERR_DOMAIN;
  return (rc_calc_real)0;
}

rc_calc_real rc_calc_div(rc_calc_env* e, rc_calc_real a, rc_calc_real b) {
  if (b == (rc_calc_real)0) {
    e->error |= RC_CALC_ERR_DIVIDE;
    return (rc_calc_real)0;
  }
  return a / b;
}

/* atan2 with both arguments in rc_calc_real, as pow: a literal is double and a ray variable
 * rc_calc_real, and OpenCL's overloads cannot resolve atan2(float, double). */
rc_calc_real rc_calc_atan2(rc_calc_real y, rc_calc_real x) {
  return atan2(y, x);
}

rc_calc_real rc_calc_pow(rc_calc_env* e, rc_calc_real a, rc_calc_real b) {
  rc_calc_real r = pow(a, b);
  if (isfinite(r)) return r;
  e->error |= RC_CALC_ERR_POWER;
  return (rc_calc_real)0;
}

rc_calc_real rc_calc_rand(rc_calc_real x) {
  x *= 1.0 / (1.0 + x * x) + 2.71828182845904;
  x += 0.785398163397447 - floor(x);
  x = 1e5 / x;
  return x - floor(x);
}

/* (int)(x + .5) as Radiance rounds selectors and argument numbers, saturated. */
int rc_calc_index(rc_calc_real x) {
  rc_calc_real r = x + 0.5;
  if (r >= 1e9) return 1000000000;
  if (r <= -1e9) return -1000000000;
  return (int)r;
}

rc_calc_real rc_calc_arg(rc_calc_env* e, rc_calc_real x) {
  int k = rc_calc_index(x);
  if (k < 1) return (rc_calc_real)e->ray.nargs;
  if (k > e->ray.nargs) {
    e->error |= RC_CALC_ERR_ARGUMENT;
    return (rc_calc_real)0;
  }
  return (rc_calc_real)e->args[e->ray.arg_base + k - 1];
}

rc_calc_real rc_calc_too_deep(rc_calc_env* e) {
  e->error |= RC_CALC_ERR_DEPTH;
  return (rc_calc_real)0;
}
