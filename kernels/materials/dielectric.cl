/* dielectric (and the shared part of interface): refraction with Fresnel, total internal
 * reflection, and the media the rays travel in (scene-format.md §3.4-3.5). A ray carries the
 * extinction of its medium; a hit on the inside of a dielectric sets the arriving ray's own
 * medium (as Radiance sets r->cext there), the refracted ray gets the medium it enters. */
#ifndef RC_DIELECTRIC_CL
#define RC_DIELECTRIC_CL

/* Radiance's guarded logarithm for extinction: none for tn >= 1, capped for tn ~ 0. */
static inline float rc_ext_log(float x) {
  return x < 1e-37f ? -100.0f : (x >= 1.0f ? 0.0f : log(x));
}
static inline float3 rc_extinction(global const float* a) {
  return (float3)(-rc_ext_log(a[0]), -rc_ext_log(a[1]), -rc_ext_log(a[2]));
}

typedef struct rc_refraction {
  float3 n;        /* normal facing the arriving ray */
  float cos1;      /* -d.n > 0 */
  int set_medium;  /* the hit decides the arriving ray's medium ... */
  float3 cext_in;  /* ... which is this */
  float3 cext_out; /* medium of the refracted ray */
  float refl;      /* Fresnel reflectance, 1 on total internal reflection */
  float trans;     /* (1 - R) eta^2 (radiance change across the boundary), 0 on TIR */
  float3 tdir;     /* refracted direction */
} rc_refraction;

/* type = RC_OBJ_DIELECTRIC (a: tn x3, n, hartmann) or RC_OBJ_INTERFACE (a: tn1 x3, n1, tn2
 * x3, n2; medium 1 inside, behind the normal). d = ray direction, nrm = geometric normal. */
static inline rc_refraction rc_refract(uint type, global const float* a, float3 d, float3 nrm) {
  rc_refraction f;
  int iface = type == RC_OBJ_INTERFACE;
  float ratio = iface ? a[3] / a[7] : a[3] + a[4] / 500.0f; /* Hartmann at 500 nm */
  f.cos1 = -dot(d, nrm);
  f.n = nrm;
  float3 none = (float3)(0.0f);
  if (f.cos1 < 0.0f) { /* leaving the inside medium */
    f.cos1 = -f.cos1;
    f.n = -nrm;
    f.set_medium = 1;
    f.cext_in = rc_extinction(a);
    f.cext_out = iface ? rc_extinction(a + 4) : none; /* no global medium (-me) */
  } else {
    ratio = 1.0f / ratio;
    f.set_medium = iface;
    f.cext_in = iface ? rc_extinction(a + 4) : none;
    f.cext_out = rc_extinction(a);
  }
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
  f.tdir = normalize(ratio * d + (ratio * f.cos1 - cos2) * f.n);
  return f;
}

#endif
