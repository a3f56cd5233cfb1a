/* Shading of the BRDF materials (Radiance's m_brdf.c), after materials/brdf_func.cl's setup;
 * included by shade_material.cl where its ray, ambient and direct helpers are known. */

/* Whether the -ae/-ai lists leave this hit's surface out of the ambient calculation. */
static inline int rc_brdf_dumb(const rc_scene_args* S, const rc_hit* h) {
  return h->surface < RC_SURF_IRRADIANCE &&
         (S->surfaces[h->surface].flags & RC_SURFF_NO_AMBIENT) != 0u;
}

/* plasfunc, metfunc, transfunc, plasdata, metdata, transdata (m_brdf2): n faces the ray (the
 * caller flipped a back face). No specular rays: the function only shapes direct light, and
 * the ambient gets the material colour x (1 - trans) on the ray's side and x trans beyond. */
RC_NOINLINE
static void rc_shade_brdf2(const rc_scene_args* S, rc_out* o, const rc_material* mat,
                           const rc_ray* r, const rc_hit* h, float3 n, rc_rng_key key) {
  const rc_params* P = &S->params;
  float3 d = r->dir.xyz, p = h->pos.xyz;
  float3 pert = h->front ? o->pert : -o->pert; /* flipped with the surface */
  rc_brdf b;
  rc_brdf2_setup(S, &b, mat, d, h, n, pert, o->pcol);
  int dumb = rc_brdf_dumb(S, h);
  float3 known = (float3)(0.0f);
  if (b.trans < 1.0f - RC_FTINY)
    known += rc_ambient(S, o, r, p, b.pnorm, b.mcolor * (1.0f - b.trans), dumb, key, 4096);
  if (b.trans > RC_FTINY)
    known += rc_ambient(S, o, r, p, -b.pnorm, b.mcolor * b.trans, dumb, key, 1u << 20);
  rc_direct(S, o, 0, &b RC_ANISO_ARG(0) RC_BSDF_ARG(0), r, p, b.pnorm, d, 0, r->coef.xyz,
            rc_bright(known), key);
}

/* BRTDfunc (m_brdf): a transmitted ray straight on (bent against a texture's tilt unless the
 * ray descends from an ambient one) and a mirror ray, weighted by the coefficient expressions;
 * the diffuse parts to the ambient on each side; the direct part when there is a diffuse
 * component or the red function is not the literal 0. Both sides are seen (no -bv rule). */
RC_NOINLINE
static void rc_shade_brtdfunc(const rc_scene_args* S, rc_out* o, const rc_material* mat,
                              const rc_ray* r, const rc_hit* h, rc_rng_key key) {
  const rc_params* P = &S->params;
  float3 d = r->dir.xyz, p = h->pos.xyz;
  float eps = P->spec.z;
  float3 pert = o->pert;
  int hastexture = dot(pert, pert) > RC_FTINY * RC_FTINY;
  rc_brdf b;
  rc_brtdfunc_setup(S, &b, mat, d, h, &pert, o->pcol);
  int hasrefl = rc_bright(b.rdiff) > RC_FTINY, hastrans = rc_bright(b.tdiff) > RC_FTINY;
  float3 c;
  if (rc_brtdfunc_coef(&b, 3u, &c)) {
    float3 t = d;
    if (hastexture && !(rc_crtype(r->flags) & RC_CR_AMBIENT)) {
      float3 tp = d - pert;
      if (dot(tp, tp) > 0.0f) t = normalize(tp);
    }
    rc_spawn(o, r, p, t, c, RC_RAY_TRANSMITTED, eps, P, key, 6, r->ambient_depth);
  }
  if (rc_brtdfunc_coef(&b, 0u, &c))
    rc_spawn(o, r, p, normalize(d + 2.0f * b.pdot * b.pnorm), c, RC_RAY_REFLECTED, eps, P, key, 8,
             r->ambient_depth);
  int dumb = rc_brdf_dumb(S, h);
  float3 known = (float3)(0.0f);
  if (hasrefl) known += rc_ambient(S, o, r, p, b.pnorm, b.rdiff, dumb, key, 4096);
  if (hastrans) known += rc_ambient(S, o, r, p, -b.pnorm, b.tdiff, dumb, key, 1u << 20);
  if (hasrefl || hastrans || (rc_brdf_desc(&b, 0u) & 1u))
    rc_direct(S, o, 0, &b RC_ANISO_ARG(0) RC_BSDF_ARG(0), r, p, b.pnorm, d, 0, r->coef.xyz,
              rc_bright(known), key);
}
