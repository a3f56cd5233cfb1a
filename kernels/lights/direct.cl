/* The direct calculation (Radiance's direct()), included by shade_material.cl (after rc_out).
 *
 * Every source sample with a positive potential contribution becomes a candidate shadow
 * request. With -dt 0 all of them are tested, in source order. With -dt > 0 the candidates are
 * sorted by potential (brightest first, in place in this hit's slots) and tested until the
 * next -dc-governed group of untested ones falls below -dt / weight of the running total; the
 * untested rest becomes one estimate record, which rc_accumulate scales by the hit ratio of the
 * tested ones (Radiance's per-source hit statistics are global and order-dependent, so they
 * are taken as equal). The shadow tests are answered after this kernel, so the running total
 * assumes that every tested sample reaches its source.
 *
 * Slots: a hit reserves one per candidate plus one for the estimate (count mode cannot know how
 * many will be tested), except with two candidates or fewer, which are always all tested. The
 * tested requests come first, then the estimate (source RC_NONE, slights_or_tested = number of
 * tested requests before it), then empty records (source RC_NONE, slights_or_tested 0,
 * contribution 0) that are neither traced nor added. */

struct rc_brdf;
#ifdef RADCL_HAS_FUNC_MATERIALS
#include "materials/brdf_func.cl"
#endif
struct rc_aniso;
#if defined(RADCL_HAS_PLASTIC2) || defined(RADCL_HAS_METAL2) || defined(RADCL_HAS_TRANS2) ||       \
    defined(RADCL_HAS_ASHIK2)
#define RADCL_HAS_ANISO 1
#include "materials/aniso.cl"
/* rc_direct's anisotropic material: a parameter only in the programs of scenes that have one. */
#define RC_ANISO_PARAM , const struct rc_aniso* an
#define RC_ANISO_ARG(x) , x
#else
#define RC_ANISO_PARAM
#define RC_ANISO_ARG(x)
#endif
struct rc_bsdf_hit;
#if defined(RADCL_HAS_BSDF) || defined(RADCL_HAS_ABSDF)
#define RADCL_HAS_BSDF_MATERIALS 1
#include "materials/bsdf_material.cl"
/* rc_direct's BSDF hit: a parameter only in the programs of scenes that have one. */
#define RC_BSDF_PARAM , const struct rc_bsdf_hit* bh
#define RC_BSDF_ARG(x) , x
#else
#define RC_BSDF_PARAM
#define RC_BSDF_ARG(x)
#endif

/* Potential brightness of a candidate, kept in its contrib.w until the selection is made. */
static inline int rc_shadow_before(global const rc_shadow* a, global const rc_shadow* b) {
  return a->contrib.w < b->contrib.w; /* min-heap order: the heap sort leaves them descending */
}

static inline void rc_shadow_swap(global rc_shadow* a, global rc_shadow* b) {
  rc_shadow t = *a;
  *a = *b;
  *b = t;
}

static void rc_shadow_sift(global rc_shadow* g, uint root, uint n) {
  for (;;) {
    uint c = 2u * root + 1u;
    if (c >= n) return;
    if (c + 1u < n && rc_shadow_before(g + c + 1u, g + c)) ++c;
    if (!rc_shadow_before(g + c, g + root)) return;
    rc_shadow_swap(g + root, g + c);
    root = c;
  }
}

/* Heap sort by potential, brightest first; deterministic for equal keys. */
static void rc_shadow_sort(global rc_shadow* g, uint n) {
  for (uint i = n / 2u; i-- > 0u;)
    rc_shadow_sift(g, i, n);
  for (uint end = n; end-- > 1u;) {
    rc_shadow_swap(g, g + end);
    rc_shadow_sift(g, 0u, end);
  }
}

/* How many of the n sorted candidates Radiance's threshold loop tests: at least 2 (MINSHADCNT),
 * then until the next n^dc of them add less than dt / weight of the running total. */
static uint rc_direct_ntest(global const rc_shadow* g, uint n, float known, const rc_params* P,
                            float weight) {
  /* n^dc as exp2 of log2: pow's extended precision cost 8% of a run's CPU time, its branch
   * for the default 0.5 being evaluated anyway where PoCL vectorises across work-items */
  uint check = (uint)(exp2(P->direct.w * log2((float)n)) + 0.5f);
  float thresh = P->direct.z / fmax(weight, 1e-6f);
  float running = known;
  uint sn = 0;
  for (; sn < n; ++sn) {
    if (sn >= 2u) {
      float group = 0.0f;
      uint end = min(n, sn + check);
      for (uint k = sn; k < end; ++k)
        group += g[k].contrib.w;
      if (group < thresh * running) break;
    }
    running += g[sn].contrib.w;
  }
  return sn;
}

/* Turns this hit's candidates g[0..n) into tested requests, the estimate and empty records. */
static void rc_direct_select(global rc_shadow* g, uint n, float known, const rc_params* P,
                             float weight) {
  rc_shadow_sort(g, n);
  uint nt = rc_direct_ntest(g, n, known, P, weight);
  float3 rest = (float3)(0.0f);
  for (uint k = nt; k < n; ++k)
    rest += g[k].contrib.xyz;
  for (uint k = 0; k < nt; ++k)
    g[k].contrib.w = 0.0f;
  rc_shadow e = g[0];
  e.contrib = (float4)(rest, 0.0f);
  e.source = RC_NONE;
  e.slights_or_tested = nt;
  g[nt] = e;
  e.contrib = (float4)(0.0f);
  e.slights_or_tested = 0u;
  for (uint k = nt + 1u; k <= n; ++k)
    g[k] = e;
}

/* The selection for at most two candidates, which are all tested: in the order the heap sort
 * leaves two (equal ones swapped), no estimate record. */
static void rc_direct_select_all(global rc_shadow* g, uint n) {
  if (n == 2u && !rc_shadow_before(g + 1, g)) rc_shadow_swap(g, g + 1);
  for (uint k = 0; k < n; ++k)
    g[k].contrib.w = 0.0f;
}

#ifdef RADCL_HAS_PATTERNS
/* The colour the patterns of a source's material give the point its shadow ray (from p along
 * l) meets at distance dist: Radiance traces that ray and shades the source's surface, patterns
 * included (brightdata distributions on light and illum). The shadow ray's T continues its
 * parent's: dist0 (the ray tree up to p) plus dist; its Ts is dist. Virtual sources and distant
 * ones are not modulated (docs/materials.md). */
RC_NOINLINE
static float3 rc_source_pattern(const rc_scene_args* S, global const rc_source* src, float3 p,
                                float3 l, float dist, float dist0) {
  float3 pcol = (float3)(1.0f);
  if (src->surface == RC_NONE || (src->flags & RC_SRCF_VIRTUAL) || src->kind == RC_SRC_DISTANT)
    return pcol;
  uint mi = S->surfaces[src->surface].material;
  if (mi == RC_NONE) return pcol;
  rc_material m = S->materials[mi];
  if (!m.npatterns || m.type == RC_OBJ_MIXFUNC) return pcol;
  rc_hit h;
  float3 q = p + l * dist;
  h.pos = (float4)(q, dist);
  float3 n = src->axis.xyz;
  if (src->kind == RC_SRC_SPHERE) {
    n = normalize(q - src->pos.xyz);
  } else if (src->kind == RC_SRC_CYLINDER) {
    float3 v = q - src->pos.xyz;
    n = normalize(v - dot(v, src->axis.xyz) * src->axis.xyz);
  }
  h.nrm = (float4)(n, 0.0f);
  h.uv = (float4)(0.0f, 0.0f, dist0, 0.0f);
  h.surface = src->surface;
  h.prim = 0u;
  h.source = RC_NONE;
  h.front = dot(l, n) < 0.0f;
  float3 pert = (float3)(0.0f);
  rc_apply_patterns(S, &m, l, &h, &pcol, &pert);
  return pcol;
}
#endif

/* Direct contributions of every source sample (`known`: brightness of what the ray's own value
 * already holds, Radiance's r->rcol, for the threshold), for a normal material m, a BRDF
 * material b, an anisotropic one an or a BSDF bh (the others null). */
RC_NOINLINE
static void rc_direct(const rc_scene_args* S, rc_out* o, const rc_ward_iso* m,
                      struct rc_brdf* b RC_ANISO_PARAM RC_BSDF_PARAM, const rc_ray* r, float3 p,
                      float3 n, float3 d, int flat, float3 coef, float known, rc_rng_key key) {
  if (o->super) return;  /* the -as pass writes only super-samples */
  if (o->doomed) return; /* a miss: this value will be dropped (rc_out) */
  const rc_params* P = &S->params;
  float eps = P->spec.z;
  uint dim = 64;
  uint first = o->nshadow;
  int select = P->direct.z > 0.0f;
  /* Translucent surfaces see sources on both sides: no horizon test. */
  int two_sided;
#ifdef RADCL_HAS_BSDF_MATERIALS
  if (bh)
    two_sided = bh->mode != RC_BSDF_DIR_R;
  else
#endif
#ifdef RADCL_HAS_FUNC_MATERIALS
      if (b)
    two_sided = rc_brdf_two_sided(b);
  else
#endif
#ifdef RADCL_HAS_ANISO
      if (an)
    two_sided = an->trans > RC_FTINY;
  else
#endif
    two_sided = m->trans > RC_FTINY;
  float3 hn = two_sided ? (float3)(0.0f) : n;
  for (uint s = 0; s < P->nsources; ++s) {
    global const rc_source* src = S->sources + s;
    /* Radiance subdivides less for rays that matter less: -ds scales with 1/weight, the
     * shadow ray's, which rayorigin() lowers by the medium's estimated extinction (wfac). */
    uint cells = rc_source_cells(src, p, P->direct.x / fmax(r->coef.w * o->wfac, 1e-6f));
    rc_src_parts parts;
    rc_source_parts(src, p, cells, &parts);
    for (uint k = 0; k < cells; ++k, dim += 2) {
      rc_src_cell g = rc_src_parts_next(&parts);
      /* A distant source without jitter is aimed at its centre: no numbers to draw. */
      float2 xi = (P->direct.y > 0.0f || src->kind != RC_SRC_DISTANT) ? rc_sample2(P, key, dim)
                                                                      : (float2)(0.0f);
      float3 l;
      float dist, omega;
      if (!rc_source_sample_part(src, S->verts, p, hn, g, cells, P->direct.y, xi, &l, &dist,
                                 &omega))
        continue;
      float3 ls = rc_source_radiance(src, l, dist);
#ifdef RADCL_HAS_PATTERNS
      ls *= rc_source_pattern(S, src, p, l, dist, o->dist);
#endif
      if (src->flags & RC_SRCF_VIRTUAL)
        ls *= rc_virtual_path(S->sources, S->mirrors, S->verts, src, p, l);
      if (rc_max3(ls) <= 0.0f) continue;
#ifdef RADCL_CONTRIB_COEF
      /* rcontrib -V-: the coefficient alone, without the source's radiance (a mirror's
       * reflectance on the way stays: Radiance's shadow ray reflects there). */
      ls = (src->flags & RC_SRCF_VIRTUAL)
               ? rc_virtual_path(S->sources, S->mirrors, S->verts, src, p, l)
               : (float3)(1.0f);
#endif
      float3 v;
#ifdef RADCL_HAS_BSDF_MATERIALS
      if (bh)
        v = ls * rc_bsdf_direct(bh, l, omega, r->coef.w, P, key, (1u << 25) + 128u * dim);
      else
#endif
#ifdef RADCL_HAS_FUNC_MATERIALS
          if (b)
        v = ls * rc_brdf_direct(b, S->args, l, omega);
      else
#endif
#ifdef RADCL_HAS_ANISO
          if (an)
        v = ls * rc_aniso_direct(an, l, omega);
      else
#endif
        v = rc_ward_iso_direct(m, ls, l, omega, n, d, flat);
      float3 c = v * coef;
      if (rc_max3(c) <= 0.0f) continue;
      rc_emit_shadow(o, p, l, eps, dist, c, r, s);
      if (select && o->write) o->shadows[o->nshadow - 1u].contrib.w = rc_bright(v);
    }
  }
  uint nc = o->nshadow - first;
  if (!select || nc == 0u) return;
  /* Two or fewer are all tested (MINSHADCNT): no estimate, whose slot would only carry 0 (a
   * scene lit by the sun alone wrote, copied and read twice the records it traced). */
  if (nc <= 2u) {
    if (o->write) rc_direct_select_all(o->shadows + first, nc);
    return;
  }
  rc_out_reserve(o, 1u, 0u);
  if (o->write) rc_direct_select(o->shadows + first, nc, known, P, r->coef.w);
  o->nshadow++; /* the estimate's slot */
}
