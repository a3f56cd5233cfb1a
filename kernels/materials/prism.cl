/* prism1 and prism2 (../shared/docs/radiance/scene-format.md §3.10; Radiance's m_direct):
 * light-redirecting surfaces whose function file gives, for a ray's direction, a coefficient and a
 * new direction (prism1 one such pair, prism2 two). A ray meeting one goes on as one or two
 * transmitted rays; a shadow ray aimed at one of its virtual sources
 * (src/render/lights/virtual_sources.cpp) goes on in the redirection toward the source imaged. The
 * record (rc_material::func) holds the expressions after its transform: x[25] flags, x[26 + 4 k ..]
 * coefficient and direction of redirection k. Included by shade_material.cl. */
#ifndef RADCL_MATERIALS_PRISM_CL
#define RADCL_MATERIALS_PRISM_CL

/* Redirection k (0 or 1) of material mat for a ray of direction d meeting h; `toward` is the
 * unit direction (world) to the source a shadow ray is aimed at, 0 for other rays (DxA, DyA,
 * DzA). Returns the coefficient and sets *dir to the new unit direction (world); 0 on a compute
 * error or a zero direction (Radiance warns and adds nothing). */
static float rc_redirect(const rc_scene_args* S, const rc_material* mat, const rc_hit* h, float3 d,
                         float3 toward, uint k, float3* dir) {
  rc_pattern pt = S->patterns[mat->func];
  rc_calc_env e;
  rc_pattern_env(S, &pt, d, h, &e);
  global const float* x = S->args + pt.xform;
  if (any(toward != (float3)(0.0f))) { /* the function space's rotation of `toward` */
    float3 tf = toward.x * (float3)(x[0], x[1], x[2]) + toward.y * (float3)(x[3], x[4], x[5]) +
                toward.z * (float3)(x[6], x[7], x[8]);
    tf = normalize(tf);
    e.ray.v[RC_CALC_DXA] = tf.x;
    e.ray.v[RC_CALC_DYA] = tf.y;
    e.ray.v[RC_CALC_DZA] = tf.z;
  }
  uint base = 26u + 4u * k;
  float coef = (float)rc_pattern_call(as_uint(x[base]), &e);
  float3 df = (float3)((float)rc_pattern_call(as_uint(x[base + 1u]), &e),
                       (float)rc_pattern_call(as_uint(x[base + 2u]), &e),
                       (float)rc_pattern_call(as_uint(x[base + 3u]), &e));
  float3 w = df.x * (float3)(x[13], x[14], x[15]) + df.y * (float3)(x[16], x[17], x[18]) +
             df.z * (float3)(x[19], x[20], x[21]);
  float len = length(w);
  if (e.error || !isfinite(coef) || !(len > 0.0f) || !isfinite(len)) return 0.0f;
  *dir = w / len;
  return coef;
}

/* A ray (not aimed at one of its sources) meeting a prism, on either side: its redirections
 * as transmitted rays weighted by their coefficients (no pattern colour, as m_direct). */
static void rc_shade_prism(const rc_scene_args* S, rc_out* o, const rc_material* mat,
                           const rc_ray* r, const rc_hit* h, rc_rng_key key) {
  uint n = mat->type == RC_OBJ_PRISM2 ? 2u : 1u;
  for (uint k = 0; k < n; ++k) {
    float3 dir;
    float c = rc_redirect(S, mat, h, r->dir.xyz, (float3)(0.0f), k, &dir);
    if (c > 0.0f)
      rc_spawn(o, r, h->pos.xyz, dir, (float3)(c), RC_RAY_TRANSMITTED, S->params.spec.z, &S->params,
               key, 8u + k, r->ambient_depth);
  }
}

#endif /* RADCL_MATERIALS_PRISM_CL */
