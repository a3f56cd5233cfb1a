/* Mixtures with a material on a side (Radiance's raymixture; include/radcl/device_types.h): a
 * tree of mixfunc nodes, up to RC_MIX_MAX_DEPTH deep, whose leaves are materials (each with the
 * patterns of its whole path) or void. OpenCL has no recursion, so the tree is walked with a
 * small stack; a leaf's share is the product of the coefficients (c or 1 - c) on its path.
 * Included by shade.cl after rc_shade_material. */

#define RC_MIX_STACK (RC_MIX_MAX_DEPTH + 2)

/* The shares of a mixture's leaves at a hit, in depth-first order (foreground first). */
typedef struct rc_mix_walk {
  uint node[RC_MIX_STACK];
  float share[RC_MIX_STACK];
  uint path[RC_MIX_STACK]; /* background turns taken: keys each leaf's random stream */
  int n;
  float passed; /* share of void leaves and of nodes whose coefficient failed */
  int shaded;   /* some leaf with a material was reached */
} rc_mix_walk;

static inline void rc_mix_push(rc_mix_walk* w, uint node, float share, uint path) {
  if (w->n >= RC_MIX_STACK) return; /* the host never nests deeper */
  w->node[w->n] = node;
  w->share[w->n] = share;
  w->path[w->n] = path;
  w->n++;
}

/* The children of node `m` with share s: a side is reached only when its coefficient exceeds
 * 1e-6 (raymixture's test). A compute error makes the node no material: its share goes on. */
static void rc_mix_expand(const rc_scene_args* S, rc_mix_walk* w, const rc_material* m, float s,
                          uint path, float3 d, const rc_hit* h) {
  float c;
  if (!rc_mix_coef(S, m->patterns, d, h, &c)) {
    w->passed += s;
    return;
  }
  /* Pushed background first so that the foreground is shaded first. */
  if (c < 1.0f - RC_FTINY) rc_mix_push(w, m->back, s * (1.0f - c), path * 2u + 1u);
  if (c > RC_FTINY) rc_mix_push(w, m->alt, s * c, path * 2u);
}

/* The next leaf with a material (returns 0 when none is left): void leaves and nodes are
 * consumed on the way. */
static int rc_mix_next(const rc_scene_args* S, rc_mix_walk* w, float3 d, const rc_hit* h,
                       uint* leaf, float* share, uint* path) {
  while (w->n > 0) {
    w->n--;
    uint idx = w->node[w->n];
    float s = w->share[w->n];
    uint p = w->path[w->n];
    if (idx == RC_NONE) {
      w->passed += s;
      continue;
    }
    rc_material m = S->materials[idx];
    if (m.type == RC_OBJ_MIXFUNC) {
      rc_mix_expand(S, w, &m, s, p, d, h);
      continue;
    }
    w->shaded = 1;
    *leaf = idx;
    *share = s;
    *path = p;
    return 1;
  }
  return 0;
}

static void rc_mix_start(const rc_scene_args* S, rc_mix_walk* w, const rc_material* root, float3 d,
                         const rc_hit* h) {
  w->n = 0;
  w->passed = 0.0f;
  w->shaded = 0;
  rc_mix_expand(S, w, root, 1.0f, 1u, d, h);
}

/* Each leaf with a share shades the hit as if alone, its coefficients and weight scaled by the
 * share, so the returned radiance is the blend. The void shares go through the surface as one
 * ray; when no leaf had a material (all void, or a compute error), the whole ray does, as
 * Radiance continues a ray that met no material. Every leaf but the first foreground draws its
 * random numbers from a stream of its own. */
static void rc_shade_mixture(const rc_scene_args* S, rc_out* o, rc_ray r, rc_hit h,
                             const rc_material* mat, const rc_surface* surf, rc_rng_key key) {
  const rc_params* P = &S->params;
  uint kind = r.flags & RC_RAY_KIND_MASK;
  /* -i: Radiance's raytirrad makes a mixture an irradiance meter whole, whatever its sides. */
  if ((P->flags & RC_PF_IRRAD_I) && (kind == RC_RAY_PRIMARY || kind == RC_RAY_TRANSMITTED) &&
      r.depth == 0 && !(rc_crtype(r.flags) & (RC_CR_AMBIENT | RC_CR_SPECULAR)) && h.pos.w >= 0.0f) {
    rc_apply_medium(S, o, &r, o->cext, h.pos.w, key);
    rc_material m = S->materials[P->irradiance_material];
    int flat = surf->type == RC_OBJ_POLYGON || surf->type == RC_OBJ_RING;
    rc_shade_normal(S, o, &m, &r, &h, h.front ? h.nrm.xyz : -h.nrm.xyz, flat, key);
    return;
  }
  float3 cext = o->cext;
  rc_mix_walk w;
  rc_mix_start(S, &w, mat, r.dir.xyz, &h);
  uint leaf, path;
  float share;
  while (rc_mix_next(S, &w, r.dir.xyz, &h, &leaf, &share, &path)) {
    rc_ray sr = r;
    sr.coef *= share;
    rc_rng_key k = key;
    if (path & (path - 1u)) /* not the all-foreground path */
      k.sample = rc_child_sample(key.sample ^ 0x6D1F3A27u, 0xB0u + (path - 3u));
    o->cext = cext;
    o->wfac = 1.0f;
    o->pcol = (float3)(1.0f);
    /* Radiance's raymixture hands each side a copy of the ray, its r->pert included: a smoothed
     * mesh's tilt; the leaf's patterns (those before the mixture among them) add theirs. */
    o->pert = h.pert.xyz;
    rc_shade_material(S, o, sr, h, S->materials[leaf], surf, k);
  }
  float pass = w.shaded ? w.passed : 1.0f;
  if (pass <= 0.0f) return;
  rc_ray pr = r;
  pr.coef *= pass;
  o->cext = cext;
  o->wfac = 1.0f;
  rc_apply_medium(S, o, &pr, o->cext, h.pos.w, key);
  if (h.pos.w >= 0.0f) rc_pass(o, &pr, &h, &S->params, key);
}

/* What one leaf of a mixture lets through of a shadow ray: a clear material's straight
 * transmission (a dielectric's only where it does not bend the ray, since a shadow ray cannot
 * split; BRTDfunc's transmission expressions), an illum's alternate's (all of it without one),
 * else nothing (as shadow rays meet opaque materials elsewhere). */
static float3 rc_shadow_leaf(const rc_scene_args* S, uint idx, float3 d, const rc_hit* h) {
  rc_material m = S->materials[idx];
  if (m.type == RC_OBJ_ILLUM) {
    if (m.alt == RC_NONE) return (float3)(1.0f);
    m = S->materials[m.alt];
  }
  /* The shadow ray's own r->pert: a smoothed mesh's tilt, then the leaf's patterns. */
  float3 pcol = (float3)(1.0f), pert = h->pert.xyz;
  if (m.npatterns) rc_apply_patterns(S, &m, d, h, &pcol, &pert);
  int back_pass = !h->front && !(S->params.flags & RC_PF_BV);
  float3 n = h->front ? h->nrm.xyz : -h->nrm.xyz;
  global const float* a = S->args + m.args;
  switch (m.type) {
#ifdef RADCL_HAS_TRANS
  case RC_OBJ_TRANS: {
    if (back_pass) return (float3)(1.0f);
    float3 pn; /* m_normal's Fresnel term takes the tilted normal's cosine */
    float cos1 = rc_raynormal(n, h->front ? pert : -pert, d, -dot(d, n), &pn);
    rc_ward_iso w = rc_trans_setup((float3)(a[0], a[1], a[2]) * pcol, a, cos1);
    return rc_trans_pure(&w) ? w.tcolor * w.tspec : (float3)(0.0f);
  }
#endif
#ifdef RADCL_HAS_GLASS
  case RC_OBJ_GLASS: {
    if (back_pass) return (float3)(1.0f);
    rc_glass g = rc_glass_hit(a, m.nargs, d, n, h->front ? pert : -pert); /* goes on straight */
    return g.hastrans ? g.trans * pcol : (float3)(0.0f);
  }
#endif
#ifdef RADCL_HAS_FUNC_MATERIALS
  case RC_OBJ_BRTDFUNC: { /* its transmission expressions (none on a compute error) */
    float3 c;
    return rc_brtdfunc_shadow(S, &m, d, h, pcol, pert, &c) ? c : (float3)(0.0f);
  }
#endif
#if defined(RADCL_HAS_DIELECTRIC) || defined(RADCL_HAS_INTERFACE)
  case RC_OBJ_DIELECTRIC:
  case RC_OBJ_INTERFACE: {
    rc_refraction f = rc_refract_tex(m.type, a, d, h->nrm.xyz, pert);
    return f.trans > 0.0f && all(f.tdir == d) ? (float3)(f.trans) : (float3)(0.0f);
  }
#endif
  default:
    return (float3)(0.0f);
  }
}

/* A shadow ray through a mixture: its leaves' transmissions weighted by their shares, void
 * shares passing whole (all of it when no leaf had a material). */
static float3 rc_shadow_mix(const rc_scene_args* S, const rc_material* m, float3 d,
                            const rc_hit* h) {
  rc_mix_walk w;
  rc_mix_start(S, &w, m, d, h);
  uint leaf, path;
  float share;
  float3 t = (float3)(0.0f);
  while (rc_mix_next(S, &w, d, h, &leaf, &share, &path))
    t += share * rc_shadow_leaf(S, leaf, d, h);
  return t + (float3)(w.shaded ? w.passed : 1.0f);
}

/* r->pert once a mixture is shaded (raymixture blends its sides' by the coefficient): each
 * leaf's by its share; void shares, and all of it when no leaf had a material, keep the hit's
 * own. */
static float3 rc_mix_pert(const rc_scene_args* S, const rc_material* m, float3 d, const rc_hit* h) {
  rc_mix_walk w;
  rc_mix_start(S, &w, m, d, h);
  uint leaf, path;
  float share;
  float3 p = (float3)(0.0f);
  while (rc_mix_next(S, &w, d, h, &leaf, &share, &path))
    p += share * rc_material_pert(S, S->materials[leaf], d, h);
  return p + (w.shaded ? w.passed : 1.0f) * h->pert.xyz;
}
