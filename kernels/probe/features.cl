/* Evaluates the direct lobe of each material module this program was built with, at a fixed
 * geometry; out[type] keeps its sentinel for types that are absent. Used by radcl's self-check
 * and the specialisation test. Inputs: in[0..2] colour, in[3] spec, in[4] rough. */
#include "radcl/device_types.h"
#include "generated.cl"

kernel void rc_feature_probe(global const float* in, global float* out) {
  if (get_global_id(0) != 0) return;
  float3 color = (float3)(in[0], in[1], in[2]);
  float3 n = (float3)(0.0f, 0.0f, 1.0f);
  float3 d = normalize((float3)(0.3f, 0.0f, -1.0f));
  float3 l = normalize((float3)(-0.2f, 0.1f, 1.0f));
  float3 ls = (float3)(1000.0f);
  float omega = 1e-3f;
  (void)color, (void)n, (void)d, (void)l, (void)ls, (void)omega;
#ifdef RADCL_HAS_PLASTIC
  {
    rc_ward_iso m = rc_plastic_setup(color, in[3], in[4], -dot(d, n));
    out[RC_OBJ_PLASTIC] = rc_ward_iso_direct(&m, ls, l, omega, n, d, 1).x;
  }
#endif
#ifdef RADCL_HAS_METAL
  {
    rc_ward_iso m = rc_metal_setup(color, in[3], in[4], -dot(d, n));
    out[RC_OBJ_METAL] = rc_ward_iso_direct(&m, ls, l, omega, n, d, 1).x;
  }
#endif
}
