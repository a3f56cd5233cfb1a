/* rcontrib (RADCL_CONTRIB): where a ray's value comes from a tracked modifier, its
 * contribution goes to a bin of that modifier instead of into the primary's sum. A ray that
 * meets a tracked surface adds its coefficient (-V-) or its coefficient times its radiance
 * (-V+); a shadow ray that reaches a tracked source adds its request's. Radiance's
 * trace_contrib with raycontrib(); the tables are render/compile/contrib_tables.h's. Included
 * by shade.cl after shade_material.cl. */

#define RC_CONTRIB_BAD 0xFFFFFFFEu /* a bin beyond the modifier's count: the host warns */

static inline uint rc_contrib_word(const rc_scene_args* S, uint i) {
  return as_uint(S->args[S->params.contrib + i]);
}

/* The bin of modifier `mod` for a ray of direction d meeting h, as a flat index into a
 * record's bins, RC_NONE for a negative bin (ignored, as Radiance does) or RC_CONTRIB_BAD. */
static uint rc_contrib_bin(const rc_scene_args* S, uint mod, float3 d, const rc_hit* h) {
  uint m = 29u + 3u * mod;
  uint first = rc_contrib_word(S, m), nbins = rc_contrib_word(S, m + 1u);
  uint fn = rc_contrib_word(S, m + 2u);
  float v = 0.0f;
#ifdef RADCL_HAS_PATTERNS
  if (fn != RC_NONE) {
    rc_calc_env e;
    rc_pattern_ray(S->args + S->params.contrib, d, h, &e);
    e.args = S->args;
    e.ray.nargs = 0;
    e.ray.arg_base = 0;
    e.error = 0;
    v = (float)rc_pattern_call(fn, &e);
  }
#endif
  if (!(v > -0.5f)) return RC_NONE;
  if (v + 0.5f >= (float)nbins) return RC_CONTRIB_BAD;
  return first + (uint)(v + 0.5f);
}

/* A ray's own contribution (rgb, w: its bin's bits) where its hit is on a tracked surface.
 * Radiance zeroes the coefficient of a light-type hit that the direct calculation counts
 * (badcomponent), and of a source -dv- hides (srcignore); an illum met by a ray not aimed at
 * it passes it on with its coefficient intact. */
static float4 rc_contrib_hit(const rc_scene_args* S, const rc_ray* r, rc_hit h) {
  const float4 none = (float4)(0.0f, 0.0f, 0.0f, as_float(RC_NONE));
  if (h.surface == RC_NONE || h.surface == RC_SURF_IRRADIANCE) return none;
  uint mod = rc_contrib_word(S, rc_contrib_word(S, 26u) + h.surface);
  if (mod == RC_NONE) return none;
  rc_surface surf = S->surfaces[h.surface];
  if (surf.material == RC_NONE) return none;
#ifdef RADCL_HAS_ANTIMATTER
  if (surf.clip & r->clip) return none;
#endif
  rc_material mat = S->materials[surf.material];
  h.uv.z = r->dist0; /* as rc_shade_ray gives the patterns */
  h.uv.w = 0.0f;
  int distant = h.pos.w < 0.0f;
  if (mat.type == RC_OBJ_LIGHT || mat.type == RC_OBJ_GLOW || mat.type == RC_OBJ_SPOTLIGHT ||
      mat.type == RC_OBJ_ILLUM) {
    global const float* a = S->args + mat.args;
    int glow = mat.type == RC_OBJ_GLOW && a[3] >= -RC_FTINY;
    int back = !distant && !h.front;
    if ((rc_crtype(r->flags) & (RC_CR_AMBIENT | RC_CR_SPECULAR)) &&
        !(back || (glow && (distant || h.pos.w > a[3]))))
      return none; /* badcomponent */
    if (mat.type != RC_OBJ_ILLUM && !(S->params.flags & RC_PF_DV) &&
        !(glow && (distant || r->dist0 + h.pos.w > a[3])))
      return none; /* srcignore */
  }
  float3 v = r->coef.xyz;
#ifndef RADCL_CONTRIB_COEF
  /* -V+: the host allows only emitting modifiers here. */
  float3 pcol = (float3)(1.0f), pert = (float3)(0.0f);
#ifdef RADCL_HAS_PATTERNS
  if (mat.npatterns) rc_apply_patterns(S, &mat, r->dir.xyz, &h, &pcol, &pert);
#endif
  v *= rc_light_emission(S, &mat, r, &h) * pcol;
#endif
  return (float4)(v, as_float(rc_contrib_bin(S, mod, r->dir.xyz, &h)));
}

/* Per packed shadow request: what it adds (rgb, w: its bin's bits) if it reached a source of a
 * tracked modifier. A virtual source's request is seen by its real source: the bin takes the
 * direction after the mirrors' reflections (a prism's redirection is not followed). */
kernel void rc_accumulate_contrib(global const rc_shadow* shadows, global const uchar* blocked,
                                  uint n, RC_SCENE_PARAMS, global float4* out) {
  uint k = get_global_id(0);
  if (k >= n) return;
  RC_SCENE_INIT
  const float4 none = (float4)(0.0f, 0.0f, 0.0f, as_float(RC_NONE));
  rc_shadow s = shadows[k];
  if (s.source == RC_NONE || blocked[k]) {
    out[k] = none;
    return;
  }
  uint src = s.source;
  float3 d = s.dir.xyz;
  int is_virtual = 0;
  while (S.sources[src].flags & RC_SRCF_VIRTUAL) {
    rc_mirror m = S.mirrors[S.sources[src].mirror];
    if (m.redirect == 0u) d -= 2.0f * dot(d, m.plane.xyz) * m.plane.xyz;
    src = S.sources[src].parent;
    is_virtual = 1;
  }
  uint mod = src < rc_contrib_word(&S, 28u)
                 ? rc_contrib_word(&S, rc_contrib_word(&S, 27u) + src)
                 : RC_NONE;
  if (mod == RC_NONE) {
    out[k] = none;
    return;
  }
  global const rc_source* so = S.sources + src;
  rc_hit h;
  h.uv = (float4)(0.0f, 0.0f, s.dist0, s.sdist0);
  h.pert = (float4)(0.0f);
  h.surface = so->surface;
  h.prim = 0u;
  h.source = src;
  if (so->kind == RC_SRC_DISTANT) {
    h.pos = (float4)(0.0f, 0.0f, 0.0f, -1.0f);
    h.nrm = (float4)(-d, 0.0f);
    h.front = 1u;
  } else {
    float dist = is_virtual ? length(so->pos.xyz - s.org.xyz) : s.dir.w;
    float3 q = is_virtual ? so->pos.xyz : s.org.xyz + s.dir.xyz * dist;
    float3 nn = so->axis.xyz;
    if (so->kind == RC_SRC_SPHERE) {
      nn = normalize(q - so->pos.xyz);
    } else if (so->kind == RC_SRC_CYLINDER) {
      float3 v = q - so->pos.xyz;
      nn = normalize(v - dot(v, so->axis.xyz) * so->axis.xyz);
    }
    h.pos = (float4)(q, dist);
    h.nrm = (float4)(nn, 0.0f);
    h.front = dot(d, nn) < 0.0f;
  }
  out[k] = (float4)(s.contrib.xyz, as_float(rc_contrib_bin(&S, mod, d, &h)));
}
