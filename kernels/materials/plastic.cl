/* plastic: uncoloured specular highlight over a coloured diffuse base
 * (../shared/docs/radiance/scene-format.md §3.1). */
#include "materials/ward_iso.cl"

/* color = (A1,A2,A3) x pattern colour, cos1 = -d.n of the incoming ray. */
static inline rc_ward_iso rc_plastic_setup(float3 color, float spec, float rough, float cos1) {
  rc_ward_iso m;
  m.alpha2 = rough * rough;
  m.spec = spec;
  m.fresnel = m.alpha2 <= RC_PURE_SPECULAR_ALPHA2 && spec >= RC_FRESNEL_MIN_SPEC;
  float s = spec;
  if (m.fresnel) s = spec + rc_ward_fresnel(fmax(cos1, 0.001f)) * (1.0f - spec);
  m.specular = (float3)(s);
  m.diffuse = color * (1.0f - s);
  rc_ward_iso_opaque(&m);
  return m;
}
