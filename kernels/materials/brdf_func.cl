/* The BRDF materials (../shared/docs/radiance/scene-format.md §3.11, §3.12; Radiance's m_brdf.c):
 * plasfunc, metfunc, transfunc, plasdata, metdata, transdata and BRTDfunc. This part (included by
 * direct.cl) sets up a hit and gives the direct coefficient of one source sample;
 * materials/brdf_shade.cl shades. Each material has a function record (rc_material.func) in the
 * pattern buffer: its real arguments, its transform (patterns.cl's 25 floats) and then a
 * descriptor, integers as float bits (src/render/compile/func_materials.cpp): func and data
 * materials: flags, function (rc_brdf_call), data offset or RC_NONE, n, n coordinate functions
 * (rc_brdf_call); BRTDfunc: flags (bit 0: direct part even without diffuse), 6 coefficient
 * expressions (rc_pattern_call: reflection rgb, transmission rgb), 3 functions (RC_NONE: literal
 * 0). */

#include "materials/raynormal.cl"

typedef struct rc_brdf {
  rc_calc_env e;         /* the function record's ray variables, NxP .. CbP set */
  global const float* x; /* the record's transform; its descriptor follows at x + 25 */
  float3 mcolor;         /* material colour x pattern (CrP CgP CbP) */
  float3 rdiff, tdiff;   /* diffuse reflection and transmission */
  float3 pnorm;          /* perturbed normal, facing the ray (BRTDfunc: the front's side) */
  float pdot;            /* -d . pnorm */
  float rspec, trans, tspec;
  uint type;
} rc_brdf;

static inline int rc_brdf_is_trans(uint t) {
  return t == RC_OBJ_TRANSFUNC || t == RC_OBJ_TRANSDATA;
}

/* The function record's environment for a ray of direction d meeting h, the normal seen as
 * ron (flipped toward the ray for the func and data materials, as the hit's for BRTDfunc), plus
 * the material variables NxP NyP NzP RdotP CrP CgP CbP (../shared/docs/radiance/calc-language.md
 * §5.2). */
static void rc_brdf_env(const rc_scene_args* S, rc_brdf* b, const rc_material* m, float3 d,
                        const rc_hit* h, float3 ron) {
  rc_pattern pt = S->patterns[m->func];
  rc_hit hh = *h;
  hh.nrm = (float4)(ron, h->nrm.w);
  rc_pattern_env(S, &pt, d, &hh, &b->e);
  global const float* x = S->args + pt.xform;
  b->x = x;
  float3 r0 = (float3)(x[0], x[1], x[2]), r1 = (float3)(x[3], x[4], x[5]);
  float3 r2 = (float3)(x[6], x[7], x[8]);
  float3 pn = normalize(b->pnorm.x * r0 + b->pnorm.y * r1 + b->pnorm.z * r2);
  b->e.ray.v[RC_CALC_NXP] = pn.x;
  b->e.ray.v[RC_CALC_NYP] = pn.y;
  b->e.ray.v[RC_CALC_NZP] = pn.z;
  b->e.ray.v[RC_CALC_RDOTP] = clamp(b->pdot, -1.0f, 1.0f);
  b->e.ray.v[RC_CALC_CRP] = b->mcolor.x;
  b->e.ray.v[RC_CALC_CGP] = b->mcolor.y;
  b->e.ray.v[RC_CALC_CBP] = b->mcolor.z;
}

/* plasfunc .. transdata at a hit seen from direction d with normal n facing the ray (the
 * surface flipped, its texture perturbation `pert` with it), pattern colour pcol
 * (Radiance's m_brdf2 up to its ambient part). */
static void rc_brdf2_setup(const rc_scene_args* S, rc_brdf* b, const rc_material* m, float3 d,
                           const rc_hit* h, float3 n, float3 pert, float3 pcol) {
  global const float* a = S->args + m->args;
  b->type = m->type;
  b->mcolor = (float3)(a[0], a[1], a[2]) * pcol;
  b->rspec = a[3];
  float td = 0.0f;
  b->trans = b->tspec = 0.0f;
  if (rc_brdf_is_trans(m->type)) {
    b->trans = a[4] * (1.0f - b->rspec);
    b->tspec = b->trans * a[5];
    td = b->trans - b->tspec;
  }
  b->rdiff = b->mcolor * (1.0f - b->trans - b->rspec);
  b->tdiff = b->mcolor * td;
  b->pdot = rc_raynormal(n, pert, d, -dot(d, n), &b->pnorm);
  rc_brdf_env(S, b, m, d, h, n);
}

/* BRTDfunc at a hit (Radiance's m_brdf up to its rays): never flipped; the diffuse reflectance
 * is the front's or the back's, pnorm and pdot are turned toward the ray (and *pert with them). */
static void rc_brtdfunc_setup(const rc_scene_args* S, rc_brdf* b, const rc_material* m, float3 d,
                              const rc_hit* h, float3* pert, float3 pcol) {
  global const float* a = S->args + m->args;
  float3 ron = h->nrm.xyz;
  float rod = -dot(d, ron);
  b->type = m->type;
  b->rspec = b->tspec = 1.0f;
  b->trans = 0.5f;
  b->mcolor = pcol;
  b->rdiff = pcol * (rod > 0.0f ? (float3)(a[0], a[1], a[2]) : (float3)(a[3], a[4], a[5]));
  b->tdiff = pcol * (float3)(a[6], a[7], a[8]);
  b->pdot = rc_raynormal(ron, *pert, d, rod, &b->pnorm);
  if (rod < 0.0f) {
    b->pdot = -b->pdot;
    b->pnorm = -b->pnorm;
    *pert = -*pert;
  }
  rc_brdf_env(S, b, m, d, h, ron);
}

static inline uint rc_brdf_desc(const rc_brdf* b, uint k) {
  return as_uint(b->x[25 + k]);
}

/* BRTDfunc's coefficient expressions k .. k+2 (0: reflection, 3: transmission); 0 on a compute
 * error, which Radiance reports, tracing no ray. */
static int rc_brtdfunc_coef(rc_brdf* b, uint k, float3* c) {
  b->e.error = 0;
  *c = (float3)((float)rc_pattern_call(rc_brdf_desc(b, 1u + k), &b->e),
                (float)rc_pattern_call(rc_brdf_desc(b, 2u + k), &b->e),
                (float)rc_pattern_call(rc_brdf_desc(b, 3u + k), &b->e));
  return !b->e.error;
}

/* Whether the direct calculation must see sources on both sides. */
static inline int rc_brdf_two_sided(const rc_brdf* b) {
  return b->trans > RC_FTINY;
}

/* Radiance's dirbrdf(): the coefficient of a source sample in direction l of solid angle
 * omega (multiplied by the source's radiance by the caller). Diffuse as the material's
 * coefficients; the function part, evaluated with the direction in function coordinates, only
 * where the specular (or transmitted) share is non-zero. A compute error or a value <= FTINY
 * leaves the diffuse part alone. */
static float3 rc_brdf_direct(rc_brdf* b, global const float* A, float3 l, float omega) {
  float3 c = (float3)(0.0f);
  float ldot = dot(b->pnorm, l);
  if (fabs(ldot) <= RC_FTINY) return c;
  if (ldot < 0.0f ? b->trans <= RC_FTINY : b->trans >= 1.0f - RC_FTINY) return c;
  c = (ldot > 0.0f ? b->rdiff : b->tdiff) * (fabs(ldot) * omega * M_1_PI_F);
  if (ldot > 0.0f ? b->rspec <= RC_FTINY : b->tspec <= RC_FTINY) return c;
  global const float* x = b->x;
  float3 lf = normalize(l.x * (float3)(x[0], x[1], x[2]) + l.y * (float3)(x[3], x[4], x[5]) +
                        l.z * (float3)(x[6], x[7], x[8]));
  rc_calc_real v[5] = {(rc_calc_real)0, lf.x, lf.y, lf.z, omega};
  b->e.error = 0;
  float3 f;
  float bright;
  if (b->type == RC_OBJ_BRTDFUNC) {
    uint i0 = rc_brdf_desc(b, 7u), i1 = rc_brdf_desc(b, 8u), i2 = rc_brdf_desc(b, 9u);
    f.x = i0 == RC_NONE ? 0.0f : (float)rc_brdf_call(i0, &b->e, v);
    f.y = i1 == RC_NONE ? 0.0f : i1 == i0 ? f.x : (float)rc_brdf_call(i1, &b->e, v);
    f.z = i2 == RC_NONE ? 0.0f
          : i2 == i0    ? f.x
          : i2 == i1    ? f.y
                        : (float)rc_brdf_call(i2, &b->e, v);
    bright = rc_bright(f);
  } else {
#ifdef RADCL_HAS_PATTERN_DATA
    uint off = rc_brdf_desc(b, 2u);
    if (off != RC_NONE) { /* data: coordinates, interpolated value, then the function */
      uint n = min(rc_brdf_desc(b, 3u), (uint)RC_DATA_MAXDIM);
      rc_calc_real pt[RC_DATA_MAXDIM];
      for (uint k = 0; k < n; ++k)
        pt[k] = rc_brdf_call(rc_brdf_desc(b, 4u + k), &b->e, v);
      v[0] = rc_data_value(A, off, pt);
    }
#endif
    bright = (float)rc_brdf_call(rc_brdf_desc(b, 1u), &b->e, v);
    f = (float3)(bright);
  }
  if (b->e.error || !(bright > RC_FTINY)) return c;
  if (ldot > 0.0f) {
    if (b->type == RC_OBJ_METFUNC || b->type == RC_OBJ_METDATA) f *= b->mcolor;
    return c + f * (ldot * omega * b->rspec);
  }
  if (rc_brdf_is_trans(b->type)) f *= b->mcolor;
  return c + f * (-ldot * omega * b->tspec);
}

/* What a BRTDfunc lets through of a shadow ray of direction d: its transmission expressions
 * (patterns pcol, texture pert as at the hit). Returns 0 on a compute error (no ray). */
static int rc_brtdfunc_shadow(const rc_scene_args* S, const rc_material* m, float3 d,
                              const rc_hit* h, float3 pcol, float3 pert, float3* coef) {
  rc_brdf b;
  rc_brtdfunc_setup(S, &b, m, d, h, &pert, pcol);
  return rc_brtdfunc_coef(&b, 3u, coef);
}
