/* Patterns and textures (../shared/docs/radiance/scene-format.md §4): the ray variables of
 * ../shared/docs/radiance/calc-language.md §5.1 in each pattern's function coordinates, then its
 * generated expressions through the scene's dispatcher rc_pattern_call(). A compute error leaves
 * the colour (or normal) unchanged, as Radiance does after its warning. */

#ifdef RADCL_HAS_PATTERN_DATA
#include "patterns/pattern_data.cl"
#endif
#ifdef RADCL_HAS_TEXT
#include "patterns/text.cl"
#endif

/* Point, direction, normal and distances of a hit mapped into a pattern's function space. */
static void rc_pattern_ray(global const float* x, float3 d, const rc_hit* h, rc_calc_env* e) {
  float3 r0 = (float3)(x[0], x[1], x[2]), r1 = (float3)(x[3], x[4], x[5]);
  float3 r2 = (float3)(x[6], x[7], x[8]), tr = (float3)(x[9], x[10], x[11]);
  float sc = x[12];
  int distant = h->pos.w < 0.0f;
  float3 nw = distant ? -d : h->nrm.xyz;
  float3 p = distant ? (float3)(0.0f) : h->pos.x * r0 + h->pos.y * r1 + h->pos.z * r2 + tr;
  float3 df = normalize(d.x * r0 + d.y * r1 + d.z * r2);
  float3 nf = normalize(nw.x * r0 + nw.y * r1 + nw.z * r2);
  float t = distant ? 1e10f : h->pos.w;
  for (int i = 0; i < RC_CALC_SLOT_CAPACITY; ++i)
    e->ray.v[i] = 0.0f;
  e->ray.v[RC_CALC_DX] = df.x;
  e->ray.v[RC_CALC_DY] = df.y;
  e->ray.v[RC_CALC_DZ] = df.z;
  e->ray.v[RC_CALC_NX] = nf.x;
  e->ray.v[RC_CALC_NY] = nf.y;
  e->ray.v[RC_CALC_NZ] = nf.z;
  if (!distant) {
    e->ray.v[RC_CALC_PX] = p.x;
    e->ray.v[RC_CALC_PY] = p.y;
    e->ray.v[RC_CALC_PZ] = p.z;
  }
  /* T: the whole ray tree's length to here (Radiance's raydist over the parent chain); Ts: this
   * segment and the shadow segments before it. The kernels put what lies before the segment
   * in the hit's uv.z and uv.w (device_types.h). */
  e->ray.v[RC_CALC_T] = (h->uv.z + t) * sc;
  e->ray.v[RC_CALC_TS] = (h->uv.w + t) * sc;
  e->ray.v[RC_CALC_RDOT] = clamp(-dot(d, nw), -1.0f, 1.0f);
  e->ray.v[RC_CALC_S] = sc;
  e->ray.v[RC_CALC_TX] = x[22];
  e->ray.v[RC_CALC_TY] = x[23];
  e->ray.v[RC_CALC_TZ] = x[24];
  float3 iv = r0 / sc, jv = r1 / sc, kv = r2 / sc;
  e->ray.v[RC_CALC_IX] = iv.x;
  e->ray.v[RC_CALC_IY] = iv.y;
  e->ray.v[RC_CALC_IZ] = iv.z;
  e->ray.v[RC_CALC_JX] = jv.x;
  e->ray.v[RC_CALC_JY] = jv.y;
  e->ray.v[RC_CALC_JZ] = jv.z;
  e->ray.v[RC_CALC_KX] = kv.x;
  e->ray.v[RC_CALC_KY] = kv.y;
  e->ray.v[RC_CALC_KZ] = kv.z;
}

/* The calc environment of pattern `pt` for a ray of direction d meeting h. */
static void rc_pattern_env(const rc_scene_args* S, const rc_pattern* pt, float3 d, const rc_hit* h,
                           rc_calc_env* e) {
  rc_pattern_ray(S->args + pt->xform, d, h, e);
  e->args = S->args;
  e->ray.nargs = (int)pt->nargs;
  e->ray.arg_base = (int)pt->args;
  e->error = 0;
}

static inline int rc_is_mix_coef(uint type) {
  return type == RC_OBJ_MIXFUNC || type == RC_OBJ_MIXDATA || type == RC_OBJ_MIXPICT ||
         type == RC_OBJ_MIXTEXT;
}

/* A mixture's coefficient at the hit (record `idx`), clamped to [0, 1] as Radiance's
 * raymixture does; returns 0 on a compute error, after which Radiance treats the mixture as no
 * material (and changes no pattern colour). */
static int rc_mix_coef(const rc_scene_args* S, uint idx, float3 d, const rc_hit* h, float* c) {
  rc_pattern pt = S->patterns[idx];
#ifdef RADCL_HAS_TEXT
  if (pt.type == RC_OBJ_MIXTEXT) { /* mixtext: foreground inside the text */
    *c = rc_text_hit(S, S->args + pt.xform, h) ? 1.0f : 0.0f;
    return 1;
  }
#endif
  rc_calc_env e;
  rc_pattern_env(S, &pt, d, h, &e);
  float v;
#ifdef RADCL_HAS_PATTERN_DATA
  if (pt.type == RC_OBJ_MIXDATA || pt.type == RC_OBJ_MIXPICT)
    v = (float)rc_data_coef(S, &pt, &e);
  else
#endif
    v = (float)rc_pattern_call(pt.func[0], &e);
  if (e.error) return 0;
  *c = clamp(v, 0.0f, 1.0f);
  return 1;
}

/* One pattern or texture: multiplies *pcol by its colour or adds its normal perturbation
 * (world space) to *pert. */
static void rc_apply_pattern(const rc_scene_args* S, const rc_pattern* ptp, float3 d,
                             const rc_hit* h, float3* pcol, float3* pert) {
  rc_pattern pt = *ptp;
  global const float* x = S->args + pt.xform;
#ifdef RADCL_HAS_TEXT
  if (pt.type == RC_OBJ_BRIGHTTEXT || pt.type == RC_OBJ_COLORTEXT) {
    rc_apply_text(S, x, h, pcol);
    return;
  }
#endif
  rc_calc_env e;
  rc_pattern_env(S, &pt, d, h, &e);
#ifdef RADCL_HAS_PATTERN_DATA
  if (pt.type == RC_OBJ_BRIGHTDATA || pt.type == RC_OBJ_COLORDATA || pt.type == RC_OBJ_TEXDATA ||
      pt.type == RC_OBJ_COLORPICT) {
    rc_apply_data(S, &pt, x, &e, pcol, pert);
    return;
  }
#endif
  if (pt.type == RC_OBJ_BRIGHTFUNC) {
    float v = (float)rc_pattern_call(pt.func[0], &e);
    if (!e.error) *pcol *= v;
  } else if (pt.type == RC_OBJ_COLORFUNC) {
    float3 c =
        (float3)((float)rc_pattern_call(pt.func[0], &e), (float)rc_pattern_call(pt.func[1], &e),
                 (float)rc_pattern_call(pt.func[2], &e));
    if (!e.error) *pcol *= c;
  } else if (pt.type == RC_OBJ_TEXFUNC) {
    float3 v =
        (float3)((float)rc_pattern_call(pt.func[0], &e), (float)rc_pattern_call(pt.func[1], &e),
                 (float)rc_pattern_call(pt.func[2], &e));
    float3 f0 = (float3)(x[13], x[14], x[15]), f1 = (float3)(x[16], x[17], x[18]);
    float3 f2 = (float3)(x[19], x[20], x[21]);
    if (!e.error) *pert += v.x * f0 + v.y * f1 + v.z * f2;
  }
}

/* Applies the material's pattern list for a ray of direction d meeting h: multiplies *pcol by
 * the patterns' colours and adds their normal perturbations (world space) to *pert. A
 * pattern-only mixture (device_types.h) collects each side's colour factor and perturbation
 * in a frame of its own; at its end they are blended by its coefficient c into the frame
 * below, as Radiance's raymixture mixes the sides' r->pcol and r->pert (a side whose share is
 * within 1e-6 of nothing is not evaluated there, which leaves it unchanged). */
#define RC_BLEND_FRAMES (2 * RC_MIX_MAX_DEPTH + 1)
RC_NOINLINE
static void rc_apply_patterns(const rc_scene_args* S, const rc_material* m, float3 d,
                              const rc_hit* h, float3* pcol, float3* pert) {
  float3 col[RC_BLEND_FRAMES], per[RC_BLEND_FRAMES];
  float coef[RC_BLEND_FRAMES];
  int top = 0;
  col[0] = *pcol;
  per[0] = *pert;
  for (uint k = 0; k < m->npatterns; ++k) {
    rc_pattern pt = S->patterns[m->patterns + k];
    if (rc_is_mix_coef(pt.type) || pt.type == RC_PATTERN_MIX_BACK) {
      if (top + 1 >= RC_BLEND_FRAMES) return; /* the host never nests deeper */
      float c = -1.0f;                        /* a compute error: the blend changes nothing */
      if (pt.type != RC_PATTERN_MIX_BACK && !rc_mix_coef(S, m->patterns + k, d, h, &c)) c = -1.0f;
      ++top;
      col[top] = (float3)(1.0f);
      per[top] = (float3)(0.0f);
      coef[top] = c;
      continue;
    }
    if (pt.type == RC_PATTERN_MIX_END) {
      if (top < 2) return;
      float c = coef[top - 1];
      float3 fc = col[top - 1], fp = per[top - 1], bc = col[top], bp = per[top];
      top -= 2;
      if (c < 0.0f) continue;
      if (c <= RC_FTINY) {
        fc = (float3)(1.0f);
        fp = (float3)(0.0f);
      }
      if (c >= 1.0f - RC_FTINY) {
        bc = (float3)(1.0f);
        bp = (float3)(0.0f);
      }
      col[top] *= c * fc + (1.0f - c) * bc;
      per[top] += c * fp + (1.0f - c) * bp;
      continue;
    }
    rc_apply_pattern(S, &pt, d, h, &col[top], &per[top]);
  }
  *pcol = col[0];
  *pert = per[0];
}
