/* The BSDF and aBSDF materials at a hit (../shared/docs/radiance/scene-format.md §3.13, Radiance's
 * m_bsdf): the local frame from the normal and the up vector, the Lambertian parts with the real
 * arguments, the projected-solid-angle queries that size Radiance's jitter, aBSDF's "through" peak,
 * and the direct coefficient of a source sample. Included by direct.cl; materials/bsdf_shade.cl
 * shades.
 *
 * As Radiance, every query passes the vector towards the viewer as the BSDF's incident vector
 * (reciprocity), so `in` below is the view side and `out` the light's or the sample's.
 *
 * The function record (src/render/compile/bsdf_materials.cpp) holds, after the 25 transform floats:
 * flags (bit 0: aBSDF), the offsets in the argument buffer of the file's rc_bsdf record, its
 * components, its floats and its ints, the thickness expression (RC_NONE for aBSDF) and the up
 * vector's three expressions. */
#ifndef RC_BSDF_MATERIAL_CL
#define RC_BSDF_MATERIAL_CL

#include "materials/bsdf_eval.cl"

/* Direct modes (Radiance's dir_brdf, dir_bsdf, dir_btdf). */
#define RC_BSDF_DIR_R 1
#define RC_BSDF_DIR_RT 2
#define RC_BSDF_DIR_T 3

typedef struct rc_bsdf_hit {
  rc_bsdf_tables t;
  float3 ex, ey, ez;        /* the local frame in world space: ez = the (perturbed) front normal */
  float3 vray;              /* local: towards the viewer */
  float3 ron;               /* the surface's front normal */
  float3 pnorm;             /* ez turned to the ray's side */
  float3 rdiff, tdiff;      /* Lambertian reflection (ray's side) and transmission, RGB x pattern */
  float3 cthru, cthru_surr; /* aBSDF: the through peak's coefficient, its surround's BTDF */
  float3 pcol;
  float thick;    /* world units; 0 for aBSDF */
  float sr_vpsa0; /* square roots of the smallest and largest projected solid angles at vray */
  float sr_vpsa1;
  int front, absdf;
  int mode; /* RC_BSDF_DIR_* of the direct call under way */
} rc_bsdf_hit;

/* CIE XYZ to Radiance's RGB (its standard primaries, equal-energy white); a colour outside the
 * gamut is desaturated towards the grey of its Y until no component is negative (Radiance's
 * clipgamut in cie_rgb). */
static inline float3 rc_bsdf_rgb(float3 c) {
  float3 rgb = (float3)(2.5653128f * c.x - 1.1668496f * c.y - 0.3984632f * c.z,
                        -1.0221082f * c.x + 1.9782866f * c.y + 0.0438216f * c.z,
                        0.0747244f * c.x - 0.2519396f * c.y + 1.1772152f * c.z);
  if (!(c.y > 0.0f)) return (float3)(0.0f);
  if (rgb.x >= 0.0f && rgb.y >= 0.0f && rgb.z >= 0.0f) return rgb;
  float t = 1.0f;
  if (rgb.x < 0.0f) t = fmin(t, c.y / (c.y - rgb.x));
  if (rgb.y < 0.0f) t = fmin(t, c.y / (c.y - rgb.y));
  if (rgb.z < 0.0f) t = fmin(t, c.y / (c.y - rgb.z));
  return fmax((float3)(c.y) + t * (rgb - (float3)(c.y)), (float3)(0.0f));
}

static inline float3 rc_bsdf_local(const rc_bsdf_hit* b, float3 v) {
  return (float3)(dot(b->ex, v), dot(b->ey, v), dot(b->ez, v));
}
static inline float3 rc_bsdf_world(const rc_bsdf_hit* b, float3 v) {
  return v.x * b->ex + v.y * b->ey + v.z * b->ez;
}

/* The residual component Radiance uses for light on the `in` side: reflection (rf or rb) or
 * transmission (tf, else tb; tb, else tf). RC_NONE if none. */
static inline uint rc_bsdf_comp_of(const rc_bsdf_hit* b, int front, int reflection) {
  global const rc_bsdf* f = b->t.files;
  if (reflection) return f->comp[front ? RC_BSDF_RF : RC_BSDF_RB];
  uint c = f->comp[front ? RC_BSDF_TF : RC_BSDF_TB];
  return c != RC_NONE ? c : f->comp[front ? RC_BSDF_TB : RC_BSDF_TF];
}

/* Projected solid angle of the Klems patch ring a direction lies in (either hemisphere). */
static inline float rc_klems_psa(const rc_bsdf_tables* t, uint basis, float3 v) {
  global const int* b = t->ints + basis;
  global const float* theta = t->vals + b[2];
  float th = acos(fmin(fabs(v.z), 1.0f)) * (180.0f / M_PI_F);
  for (int r = 0; r < b[0]; ++r)
    if (th < theta[r + 1]) return t->vals[b[3] + b[5 + 2 * r]];
  return 0.0f;
}

/* Edge of the tree leaf a pair falls in (0 where the pair does not fit the component). */
static inline float rc_tree_leaf_edge(const rc_bsdf_tables* t, global const rc_bsdf_comp* c,
                                      float3 in, float3 out) {
  int swap;
  if (!rc_tree_orient(c->part, in, out, &swap)) return 0.0f;
  float4 pos = swap ? rc_tree_position(c->format, out, in) : rc_tree_position(c->format, in, out);
  float edge;
  rc_tree_find(t, c, pos, &edge);
  return edge;
}

/* Radiance's SDsizeBSDF for a pair (SDqueryMin): the smallest projected solid angle of the
 * cells the pair falls in, over the components of its kind; pi where there are none. */
static float rc_bsdf_psa_pair(const rc_bsdf_hit* b, float3 v1, float3 v2) {
  int front = v1.z > 0.0f;
  uint ci = rc_bsdf_comp_of(b, front, front == (v2.z > 0.0f));
  if (ci == RC_NONE) return M_PI_F;
  global const rc_bsdf_comp* c = b->t.comps + ci;
  if (c->format == RC_BSDF_KLEMS) {
    float a = rc_klems_psa(&b->t, c->out_basis, v1), d = rc_klems_psa(&b->t, c->in_basis, v2);
    float m = 10.0f;
    if (a > 0.0f) m = fmin(m, a);
    if (d > 0.0f) m = fmin(m, d);
    return m;
  }
  float e = rc_tree_leaf_edge(&b->t, c, v1, v2);
  return e > 0.0f ? M_PI_F * e * e : 10.0f;
}

/* SDsizeBSDF for the view vector alone (SDqueryMin + SDqueryMax), as square roots. Trees use
 * their smallest and largest leaves over the whole tree (Radiance: over the slice at v). */
static void rc_bsdf_view_psa(rc_bsdf_hit* b) {
  float lo = 10.0f, hi = 0.0f;
  int any = 0;
  for (int refl = 1; refl >= 0; --refl) {
    uint ci = rc_bsdf_comp_of(b, b->front, refl);
    if (ci == RC_NONE) continue;
    any = 1;
    global const rc_bsdf_comp* c = b->t.comps + ci;
    if (c->format == RC_BSDF_KLEMS) {
      float a = rc_klems_psa(&b->t, c->in_basis, b->vray);
      if (a > 0.0f) lo = fmin(lo, a);
      hi = fmax(hi, a);
    } else {
      lo = fmin(lo, c->min_psa);
      hi = fmax(hi, c->max_psa);
    }
  }
  if (!any) lo = hi = M_PI_F;
  if (lo > hi) lo = hi;
  b->sr_vpsa0 = sqrt(lo);
  b->sr_vpsa1 = sqrt(hi);
}

/* The view vector moved by up to half `sr` in x and y (-ss < 1 narrows it), renormalised. */
static inline float3 rc_bsdf_jitter(const rc_bsdf_hit* b, float sr, const rc_params* P,
                                    rc_rng_key key, uint dim) {
  if (P->spec.x < 1.0f) sr *= P->spec.x;
  if (sr <= RC_FTINY) return b->vray;
  float3 v = b->vray;
  v.x += sr * (0.5f - rc_sample(P, key, dim));
  v.y += sr * (0.5f - rc_sample(P, key, dim + 1u));
  return normalize(v);
}

/* aBSDF: the coefficient of light passing straight through (the peak of the transmission about
 * -vray) and the mean BTDF around it (Radiance's compute_through), times the pattern. */
static void rc_bsdf_through(rc_bsdf_hit* b) {
  b->cthru = b->cthru_surr = (float3)(0.0f);
  uint ci = rc_bsdf_comp_of(b, b->front, 0);
  if (ci == RC_NONE || rc_bright(b->pcol) <= RC_FTINY) return;
  const float off[29][2] = {
      {0, 0},         {-0.6f, 0},    {0, 0.6f},      {0, -0.6f},    {0.6f, 0},      {-0.6f, 0.6f},
      {-0.6f, -0.6f}, {0.6f, 0.6f},  {0.6f, -0.6f},  {-1.2f, 0},    {0, 1.2f},      {0, -1.2f},
      {1.2f, 0},      {-1.2f, 1.2f}, {-1.2f, -1.2f}, {1.2f, 1.2f},  {1.2f, -1.2f},  {-1.8f, 0},
      {0, 1.8f},      {0, -1.8f},    {1.8f, 0},      {-1.8f, 1.8f}, {-1.8f, -1.8f}, {1.8f, 1.8f},
      {1.8f, -1.8f},  {-2.4f, 0},    {0, 2.4f},      {0, -2.4f},    {2.4f, 0}};
  float min_psa = b->t.comps[ci].min_psa;
  float srch = sqrt(min_psa);
  float vy[29];
  float3 dir[29], col[29];
  for (int i = 0; i < 29; ++i) {
    float3 d = normalize(
        (float3)(-b->vray.x + off[i][0] * srch, -b->vray.y + off[i][1] * srch, -b->vray.z));
    float3 v = rc_bsdf_eval(&b->t, 0u, b->vray, d);
    /* insertion by brightness, descending; equal values keep their order */
    int j = i;
    for (; j > 0 && vy[j - 1] < v.y; --j) {
      vy[j] = vy[j - 1];
      dir[j] = dir[j - 1];
      col[j] = col[j - 1];
    }
    vy[j] = v.y;
    dir[j] = d;
    col[j] = v;
  }
  if (vy[0] <= RC_FTINY) return;
  float3 peak = (float3)(0.0f), surr = (float3)(0.0f);
  float ypeak = 0.0f, omsum = 0.0f, omsurr = 0.0f;
  int ns = 0;
  for (int i = 0; i < 29; ++i) {
    if (i && vy[i] == vy[i - 1]) continue; /* a duplicate sample */
    float om = rc_bsdf_psa_pair(b, b->vray, dir[i]);
    float3 c = col[i] * om;
    if (om > 1.5f * min_psa || ypeak > 8.0f * vy[i] * (float)ns) { /* not part of the peak */
      if (!i) return;
      surr += c;
      omsurr += om;
      continue;
    }
    peak += c;
    omsum += om;
    ypeak += vy[i];
    ++ns;
  }
  if (omsurr <= RC_FTINY) return;
  global const rc_bsdf* f = b->t.files;
  float tlamb = f->lamb[b->vray.z > 0.0f ? RC_BSDF_TF : RC_BSDF_TB].y; /* already / pi */
  if ((ypeak / (float)ns - tlamb) * omsum < 0.0005f) return;           /* under 0.05% transmitted */
  b->cthru = rc_bsdf_rgb(peak) * b->pcol;
  b->cthru_surr = rc_bsdf_rgb(surr / omsurr) * b->pcol;
}

/* Sets up a hit of ray direction d on `mat` (front: the side hit). 0 where the up vector is
 * along the normal (Radiance warns and leaves the ray black). */
static int rc_bsdf_setup(const rc_scene_args* S, rc_bsdf_hit* b, const rc_material* mat,
                         const rc_hit* h, float3 d, float3 pcol, float3 pert) {
  rc_pattern pt = S->patterns[mat->func];
  rc_calc_env e;
  rc_pattern_env(S, &pt, d, h, &e);
  global const float* x = S->args + pt.xform;
  b->absdf = (as_uint(x[25]) & 1u) != 0u;
  b->t.files = (global const rc_bsdf*)(S->args + as_uint(x[26]));
  b->t.comps = (global const rc_bsdf_comp*)(S->args + as_uint(x[27]));
  b->t.vals = S->args + as_uint(x[28]);
  b->t.ints = (global const int*)(S->args + as_uint(x[29]));
  uint tid = as_uint(x[30]);
  b->thick = 0.0f;
  if (tid != RC_NONE) {
    float th = (float)rc_pattern_call(tid, &e) / x[12];
    if (fabs(th) > RC_FTINY && isfinite(th)) b->thick = th;
  }
  float3 uf = (float3)((float)rc_pattern_call(as_uint(x[31]), &e),
                       (float)rc_pattern_call(as_uint(x[32]), &e),
                       (float)rc_pattern_call(as_uint(x[33]), &e));
  float3 up = uf.x * (float3)(x[13], x[14], x[15]) + uf.y * (float3)(x[16], x[17], x[18]) +
              uf.z * (float3)(x[19], x[20], x[21]);
  b->front = h->front;
  b->pcol = pcol;
  b->ron = h->nrm.xyz;
  b->ez = rc_has_texture(pert) ? normalize(b->ron + pert) : b->ron;
  float3 ex = cross(up, b->ez);
  float len = length(ex);
  if (!(len > 0.0f) || !isfinite(len) || e.error) return 0;
  b->ex = ex / len;
  b->ey = cross(b->ez, b->ex);
  b->vray = rc_bsdf_local(b, -d);
  b->pnorm = b->front ? b->ez : -b->ez;
  b->cthru = b->cthru_surr = (float3)(0.0f);
  b->mode = RC_BSDF_DIR_RT;
  return 1;
}

/* The Lambertian parts with the real arguments added, times the pattern (mat's arguments). */
static void rc_bsdf_diffuse(const rc_scene_args* S, rc_bsdf_hit* b, const rc_material* mat) {
  global const float* a = S->args + mat->args;
  uint na = mat->nargs;
  global const rc_bsdf* f = b->t.files;
  float3 rd = rc_bsdf_rgb(f->lamb[b->front ? RC_BSDF_RF : RC_BSDF_RB].xyz) * M_PI_F;
  float3 td = rc_bsdf_rgb(f->lamb[b->front ? RC_BSDF_TF : RC_BSDF_TB].xyz) * M_PI_F;
  if (b->front && na >= 3u) rd += (float3)(a[0], a[1], a[2]);
  if (!b->front && na >= 6u) rd += (float3)(a[3], a[4], a[5]);
  if (na >= 9u) td += (float3)(a[6], a[7], a[8]);
  b->rdiff = rd * b->pcol;
  b->tdiff = td * b->pcol;
}

/* The BSDF's non-Lambertian value (RGB, 1/sr) towards a source in local direction vsrc of
 * solid angle omega, averaged over about 4 x -ss x weight jittered view vectors (Radiance's
 * direct_specular_OK); 0 when there is nothing to add. */
static float3 rc_bsdf_direct_spec(const rc_bsdf_hit* b, float3 vsrc, float omega, float weight,
                                  const rc_params* P, rc_rng_key key, uint dim) {
  int sf = vsrc.z > 0.0f, vf = b->vray.z > 0.0f;
  if (rc_bsdf_comp_of(b, vf, sf == vf) == RC_NONE) return (float3)(0.0f); /* all diffuse */
  global const rc_bsdf* f = b->t.files;
  uint part = sf == vf ? (vf ? RC_BSDF_RF : RC_BSDF_RB) : (vf ? RC_BSDF_TF : RC_BSDF_TB);
  float3 dxyz = f->lamb[part].xyz; /* the Lambertian part, discounted below */
  float diffy = dxyz.y > RC_FTINY ? dxyz.y : 0.0f;
  if (sf != vf && rc_bright(b->cthru) > RC_FTINY) { /* near the through peak: its surround */
    uint ci = rc_bsdf_comp_of(b, b->front, 0);
    float mp = b->t.comps[ci].min_psa;
    float dx = vsrc.x + b->vray.x, dy = vsrc.y + b->vray.y;
    float tom = omega * fabs(vsrc.z);
    if (dx * dx + dy * dy <= (2.5f * 4.0f / M_PI_F) * (tom + mp + 2.0f * sqrt(tom * mp)))
      return b->cthru_surr;
  }
  float tomega = rc_bsdf_psa_pair(b, b->vray, vsrc);
  float tsr = sqrt(tomega);
  int nsamp = 1;
  if (tsr > 0.0f) {
    nsamp = min((int)(4.0f * P->spec.x * weight + 0.5f), 64); /* rc_direct leaves 128 dims */
    nsamp += !nsamp;
  }
  float3 sum = (float3)(0.0f);
  int cnt = 0;
  for (int i = 0; i < nsamp; ++i) {
    float3 vj = rc_bsdf_jitter(b, tsr, P, key, dim + 2u * (uint)i);
    float3 v = rc_bsdf_eval(&b->t, 0u, vj, vsrc);
    if (v.y - diffy <= RC_FTINY) continue;                        /* no specular part */
    if (rc_bsdf_psa_pair(b, vj, vsrc) < 0.12f * tomega) continue; /* finer cell: not safe */
    sum += rc_bsdf_rgb(v);
    ++cnt;
  }
  if (!cnt) return (float3)(0.0f);
  sum /= (float)cnt;
  if (diffy > RC_FTINY) sum = fmax(sum - rc_bsdf_rgb(dxyz), (float3)(0.0f));
  return sum;
}

/* Direct coefficient of a source sample in world direction l of solid angle omega, in the mode
 * of the call (reflection, both, or transmission only). */
static float3 rc_bsdf_direct(const rc_bsdf_hit* b, float3 l, float omega, float weight,
                             const rc_params* P, rc_rng_key key, uint dim) {
  float3 c = (float3)(0.0f);
  float ldot = dot(b->pnorm, l);
  if (fabs(ldot) <= RC_FTINY) return c;
  if (ldot < 0.0f ? b->mode == RC_BSDF_DIR_R : b->mode == RC_BSDF_DIR_T) return c;
  if (ldot > 0.0f && rc_bright(b->rdiff) > RC_FTINY) c += b->rdiff * (ldot * omega * M_1_PI_F);
  if (ldot < 0.0f && rc_bright(b->tdiff) > RC_FTINY) c -= b->tdiff * (ldot * omega * M_1_PI_F);
  float3 s = rc_bsdf_direct_spec(b, rc_bsdf_local(b, l), omega, weight, P, key, dim);
  if (ldot < 0.0f) s *= b->pcol; /* the pattern on transmission only */
  return c + s * (fabs(ldot) * omega);
}

/* A shadow ray (direction d) meeting `mat` at h: BSDF with a thickness lets it through (the
 * proxied geometry decides), without one blocks it; aBSDF passes it scaled by its through
 * component. 0: blocked. */
static int rc_bsdf_shadow(const rc_scene_args* S, const rc_material* mat, const rc_hit* h, float3 d,
                          float3 pcol, float3 pert, float3* coef) {
  rc_bsdf_hit b;
  int ok = rc_bsdf_setup(S, &b, mat, h, d, pcol, pert);
  *coef = (float3)(1.0f);
  if (!b.absdf) return b.thick != 0.0f;
  if (!ok) return 0;
  rc_bsdf_view_psa(&b);
  rc_bsdf_through(&b);
  *coef = b.cthru;
  return rc_max3(b.cthru) > 0.0f;
}

#endif /* RC_BSDF_MATERIAL_CL */
