/* dielectric (and the shared part of interface): refraction with Fresnel, total internal
 * reflection, and the media the rays travel in (../shared/docs/radiance/scene-format.md §3.4-3.5).
 * A ray carries the extinction of its medium; a hit on the inside of a dielectric sets the arriving
 * ray's own medium (as Radiance sets r->cext there), the refracted ray gets the medium it enters.
 */
#ifndef RC_DIELECTRIC_CL
#define RC_DIELECTRIC_CL

#include "materials/raynormal.cl"

/* Radiance's guarded logarithm for extinction: none for tn >= 1, capped for tn ~ 0. */
static inline float rc_ext_log(float x) {
  return x < 1e-37f ? -100.0f : (x >= 1.0f ? 0.0f : log(x));
}
static inline float3 rc_extinction(global const float* a) {
  return (float3)(-rc_ext_log(a[0]), -rc_ext_log(a[1]), -rc_ext_log(a[2]));
}

typedef struct rc_refraction {
  float3 n;        /* normal (tilted by textures) facing the arriving ray */
  float cos1;      /* -d.n > 0 */
  int set_medium;  /* the hit decides the arriving ray's medium ... */
  float3 cext_in;  /* ... which is this */
  float3 cext_out; /* medium of the refracted ray */
  float refl;      /* Fresnel reflectance, 1 on total internal reflection */
  float trans;     /* (1 - R) eta^2 (radiance change across the boundary), 0 on TIR */
  float3 tdir;     /* refracted direction */
  float3 rdir;     /* reflected direction */
  float ratio;     /* index ratio across the boundary */
  int textured;    /* a texture tilted the normal */
#ifdef RADCL_HAS_MEDIUM
  int to_global; /* the refracted ray leaves a dielectric into the global medium (-me) */
#endif
} rc_refraction;

/* type = RC_OBJ_DIELECTRIC (a: tn x3, n, hartmann) or RC_OBJ_INTERFACE (a: tn1 x3, n1, tn2
 * x3, n2; medium 1 inside, behind the normal). d = ray direction, nrm = geometric normal,
 * pert = the textures' perturbation (world space, the surface's own orientation). As Radiance's
 * m_dielectric, the tilted normal decides Fresnel and both directions; where it would send the
 * refracted ray back or the reflected one through, the geometric normal takes over. */
static inline rc_refraction rc_refract_tex(uint type, global const float* a, float3 d, float3 nrm,
                                           float3 pert) {
  rc_refraction f;
  int iface = type == RC_OBJ_INTERFACE;
  float ratio = iface ? a[3] / a[7] : a[3] + a[4] / 500.0f; /* Hartmann at 500 nm */
  float rod = -dot(d, nrm);
  f.cos1 = rc_raynormal(nrm, pert, d, rod, &f.n);
  f.textured = rc_has_texture(pert);
  float side = f.textured ? 1.0f : 0.0f; /* Radiance's hastexture, signed by the side */
  float3 none = (float3)(0.0f);
  if (f.cos1 < 0.0f) { /* leaving the inside medium */
    f.cos1 = -f.cos1;
    f.n = -f.n;
    side = -side;
    f.set_medium = 1;
    f.cext_in = rc_extinction(a);
    f.cext_out = iface ? rc_extinction(a + 4) : none; /* the caller adds a global medium */
#ifdef RADCL_HAS_MEDIUM
    f.to_global = !iface;
#endif
  } else {
    ratio = 1.0f / ratio;
    f.set_medium = iface;
    f.cext_in = iface ? rc_extinction(a + 4) : none;
    f.cext_out = rc_extinction(a);
#ifdef RADCL_HAS_MEDIUM
    f.to_global = 0;
#endif
  }
  f.ratio = ratio;
  float3 rd = d + 2.0f * f.cos1 * f.n;
  if (f.textured && dot(rd, nrm) * side <= 1e-6f) rd = d + 2.0f * rod * nrm;
  f.rdir = normalize(rd);
  float d2 = 1.0f - ratio * ratio * (1.0f - f.cos1 * f.cos1);
  f.refl = 1.0f;
  f.trans = 0.0f;
  f.tdir = d;
  if (d2 < 1e-6f) return f; /* total internal reflection */
  float cos2 = sqrt(d2);
  float rs = (f.cos1 - ratio * cos2) / (f.cos1 + ratio * cos2);
  float rp = (1.0f / f.cos1 - ratio / cos2) / (1.0f / f.cos1 + ratio / cos2);
  f.refl = 0.5f * (rs * rs + rp * rp);
  f.trans = (1.0f - f.refl) * ratio * ratio;
  float d1 = ratio * f.cos1 - cos2;
  float3 t = ratio * d + d1 * f.n;
  if (f.textured && dot(t, nrm) * side >= -1e-6f) t = ratio * d + d1 * side * nrm; /* not exact */
  f.tdir = normalize(t);
  return f;
}

static inline rc_refraction rc_refract(uint type, global const float* a, float3 d, float3 nrm) {
  return rc_refract_tex(type, a, d, nrm, (float3)(0.0f));
}

#endif
