/* Evaluates generated .cal expressions for tests: work-item i runs expression i of the
 * generated dispatcher rc_calc_probe_eval on ray i (tests/calc/device_agreement.cpp). */
#include "generated.cl"
#include "radcl/calc/device_context.h"

kernel void rc_calc_probe(global const rc_calc_ray* rays, global const float* args,
                          global rc_calc_real* out, global int* errors, uint count) {
  uint i = get_global_id(0);
  if (i >= count) return;
  rc_calc_env e;
  e.ray = rays[i];
  e.args = args;
  e.error = 0;
  out[i] = rc_calc_probe_eval(&e, i);
  errors[i] = e.error;
}
