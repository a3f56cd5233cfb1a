/* Test kernel for lights/sources.cl (not embedded: tests/render/lights/source_sampling.cpp
 * loads it): irradiance at points from one source, summing
 * L * omega * cos over every sample the -ds partition makes. Point i: pts[i].xyz, normal
 * nrm[i].xyz. out[2i] = (E rgb, cells); out[2i+1] = (usable samples, sum of omega, distance
 * and direction.z of the first usable sample). */
#include "radcl/rng.h"
#include "lights/sources.cl"

kernel void rc_test_source_irradiance(global const rc_source* src, global const float4* verts,
                                      global const float4* pts, global const float4* nrm, uint npts,
                                      float ds, float dj, uint seed, global float4* out) {
  uint i = get_global_id(0);
  if (i >= npts) return;
  float3 p = pts[i].xyz, n = nrm[i].xyz;
  uint cells = rc_source_cells(src, p, ds);
  rc_rng_key key = rc_make_key(i, 0u, 0u, seed);
  float3 e = (float3)(0.0f);
  float usable = 0.0f, osum = 0.0f, first_dist = -1.0f, first_z = 0.0f;
  for (uint k = 0; k < cells; ++k) {
    float2 xi = (float2)(rc_random(key, 2u * k), rc_random(key, 2u * k + 1u));
    float3 l;
    float dist, omega;
    if (!rc_source_sample(src, verts, p, n, k, cells, dj, xi, &l, &dist, &omega)) continue;
    float3 ls = rc_source_radiance(src, l, dist);
    e += ls * omega * fmax(0.0f, dot(l, n));
    usable += 1.0f;
    osum += omega;
    if (first_dist < 0.0f) {
      first_dist = dist;
      first_z = l.z;
    }
  }
  out[2u * i] = (float4)(e, (float)cells);
  out[2u * i + 1u] = (float4)(usable, osum, first_dist, first_z);
}
