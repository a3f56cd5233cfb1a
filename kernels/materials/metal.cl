/* metal: specular reflection coloured by the material (../shared/docs/radiance/scene-format.md
 * §3.1). */
#include "materials/ward_iso.cl"

static inline rc_ward_iso rc_metal_setup(float3 color, float spec, float rough, float cos1) {
  rc_ward_iso m;
  m.alpha2 = rough * rough;
  m.spec = spec;
  m.fresnel = m.alpha2 <= RC_PURE_SPECULAR_ALPHA2 && spec >= RC_FRESNEL_MIN_SPEC;
  float s = spec;
  if (m.fresnel) {
    float f = rc_ward_fresnel(fmax(cos1, 0.001f));
    s = spec + f * (1.0f - spec);
    m.specular = (float3)(f) + color * (spec * (1.0f - f));
  } else {
    m.specular = color * spec;
  }
  m.diffuse = color * (1.0f - s);
  rc_ward_iso_opaque(&m);
  return m;
}
