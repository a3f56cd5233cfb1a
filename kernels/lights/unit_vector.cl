/* A vector scaled to unit length, for vectors known to be far from zero and from overflow
 * (sums of unit vectors, cross products of non-parallel ones): OpenCL's normalize() guards
 * against both, which costs PoCL range checks besides its square root and division. */
#ifndef RADCL_RENDER_UNIT_VECTOR_CL
#define RADCL_RENDER_UNIT_VECTOR_CL

static inline float3 rc_unit(float3 v) {
  return v * rsqrt(dot(v, v));
}

#endif
