/* glass: a thin pane as one surface (../shared/docs/radiance/scene-format.md §3.3). The arguments
 * are transmissivities tn (one pass through the pane at normal incidence); the pane's reflectance
 * and transmittance sum the series of internal reflections, per polarisation, with Fresnel at each
 * face. */
#ifndef RC_GLASS_CL
#define RC_GLASS_CL

#include "materials/raynormal.cl"

#define RC_GLASS_INDEX 1.52f

typedef struct rc_glass {
  float3 trans; /* T per channel (before any pattern) */
  float3 refl;  /* R per channel */
  int hastrans; /* some channel transmits: otherwise opaque to shadow rays */
  float3 pnorm; /* the normal tilted by textures, facing the ray (rc_glass_hit) */
  float pdot;   /* -d . pnorm: the cosine the Fresnel terms and the reflection use */
  int textured; /* a texture tilts the normal: the transmitted ray is bent */
} rc_glass;

static inline float rc_glass_index(global const float* a, uint nargs) {
  return nargs >= 4u ? a[3] : RC_GLASS_INDEX;
}

/* a = real arguments (3, or 4 with the index), cos1 = -d.n > 0 with n facing the ray. */
static inline rc_glass rc_glass_setup(global const float* a, uint nargs, float cos1) {
  rc_glass g;
  float n = rc_glass_index(a, nargs);
  float3 tn = (float3)(a[0], a[1], a[2]);
  g.hastrans = fmax(tn.x, fmax(tn.y, tn.z)) > 1e-15f;
  if (g.hastrans) tn = fmax(tn, (float3)(1e-15f));
  /* Internal cosine; the path through the pane grows as 1/cos2. */
  float n2 = n * n;
  float cos2 = sqrt((1.0f - 1.0f / n2) + cos1 * cos1 / n2);
  /* tn^(1/cos2) as exp2 of log2 (tn > 0 here): pow's extended precision was 2% of a run */
  float3 t = g.hastrans ? exp2(log2(tn) / cos2) : tn;
  float re = (cos1 - n * cos2) / (cos1 + n * cos2);
  re *= re; /* TE */
  float rm = (1.0f / cos1 - n / cos2) / (1.0f / cos1 + n / cos2);
  rm *= rm; /* TM */
  float3 t2 = t * t;
  g.trans = 0.5f * (1.0f - re) * (1.0f - re) * t / (1.0f - re * re * t2) +
            0.5f * (1.0f - rm) * (1.0f - rm) * t / (1.0f - rm * rm * t2);
  g.refl = 0.5f * re * (1.0f + (1.0f - 2.0f * re) * t2) / (1.0f - re * re * t2) +
           0.5f * rm * (1.0f + (1.0f - 2.0f * rm) * t2) / (1.0f - rm * rm * t2);
  return g;
}

/* The pane seen by a ray of direction d, n its normal facing the ray and pert the textures'
 * perturbation on that side (Radiance flips both with the surface): as m_glass, the tilted
 * normal decides the Fresnel terms and the reflection. */
static inline rc_glass rc_glass_hit(global const float* a, uint nargs, float3 d, float3 n,
                                    float3 pert) {
  float3 pn;
  float pdot = rc_raynormal(n, pert, d, -dot(d, n), &pn);
  rc_glass g = rc_glass_setup(a, nargs, pdot);
  g.pnorm = pn;
  g.pdot = pdot;
  g.textured = rc_has_texture(pert);
  return g;
}

/* The transmitted ray of a textured pane (not for shadow and ambient rays, which go straight):
 * the perturbation seen through a pane of index n bends it by 2 (1 - n) pert, as m_glass does. */
static inline float3 rc_glass_bend(float3 d, float3 pert, float n) {
  float3 t = d + 2.0f * (1.0f - n) * pert;
  float len = length(t);
  return len > 0.0f ? t / len : d;
}

#endif
