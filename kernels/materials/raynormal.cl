/* Radiance's raynormal(): a surface normal tilted by the textures' perturbation, shared by the
 * materials that bend their rays with it (glass, dielectric, the BRDF materials). */
#ifndef RC_RAYNORMAL_CL
#define RC_RAYNORMAL_CL

/* Whether a perturbation counts (Radiance's hastexture: |pert|^2 > FTINY^2). */
static inline int rc_has_texture(float3 pert) {
  return dot(pert, pert) > 1e-12f;
}

/* ron tilted by pert for a ray of direction d (rod = -d . ron), turned back to the side the ray
 * sees if the tilt would change it. Returns -d . normal (the sign of rod) and the normal. */
static float rc_raynormal(float3 ron, float3 pert, float3 d, float rod, float3* pn) {
  *pn = ron;
  if (!rc_has_texture(pert)) return rod;
  float3 nn = ron + pert;
  float len = length(nn);
  if (len == 0.0f) return rod;
  nn /= len;
  float nd = -dot(nn, d);
  if ((nd > 0.0f) != (rod > 0.0f)) { /* mirrored about the plane across the ray */
    nn += 2.0f * nd * d;
    nd = -nd;
  }
  *pn = nn;
  return nd;
}

#endif
