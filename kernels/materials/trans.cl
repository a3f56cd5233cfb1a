/* trans: thin translucent surface (../shared/docs/radiance/scene-format.md §3.2). Reflection as
 * plastic with rho_d = 1 - tau - s'; transmission tau = trans (1 - s') split into a clear part
 * tau_s and a diffuse part tau_d, both coloured by the material. */
#include "materials/ward_iso.cl"

/* a = the 7 real arguments, color = (a0,a1,a2) x pattern, cos1 = -d.n with n facing the ray. */
static inline rc_ward_iso rc_trans_setup(float3 color, global const float* a, float cos1) {
  rc_ward_iso m;
  m.alpha2 = a[4] * a[4];
  m.spec = a[3];
  m.pdot = fmax(cos1, 0.001f);
  m.fresnel = m.alpha2 <= RC_PURE_SPECULAR_ALPHA2 && m.spec >= RC_FRESNEL_MIN_SPEC;
  float s = m.spec;
  if (m.fresnel) s += rc_ward_fresnel(m.pdot) * (1.0f - s);
  m.trans = a[5] * (1.0f - s);
  m.tspec = m.trans * a[6];
  m.tdiff = m.trans - m.tspec;
  m.tcolor = color;
  m.specular = (float3)(s);
  m.diffuse = color * (1.0f - m.trans - s);
  return m;
}

/* The clear part passes as a straight ray (and so do shadow rays) only when the surface is
 * purely specular; rough transmission is sampled or folded into the ambient instead. */
static inline int rc_trans_pure(const rc_ward_iso* m) {
  return m->alpha2 <= RC_PURE_SPECULAR_ALPHA2 && m->tspec > RC_WARD_FTINY;
}
