/* Shading of BSDF and aBSDF hits (Radiance's m_bsdf) after materials/bsdf_material.cl's setup;
 * included by shade_material.cl where its ray, ambient and direct helpers are known.
 *
 * A BSDF with a thickness is a proxy: view rays, shadow rays and rays reaching its hidden side
 * pass through to the geometry it stands for; transmitted samples and the transmitted direct
 * and ambient parts start that far behind it. aBSDF sends view rays straight through with its
 * through component. The Lambertian parts go to the ambient and the direct calculation; the
 * residual components are sampled (one ray each, or -ss x weight of them) unless their total
 * is within -st, when it joins the ambient coefficient instead. */

/* Samples the residual component `ci` (reflection: refl) Radiance's sample_sdcomp way. */
static void rc_bsdf_sample_comp(const rc_bsdf_hit* b, rc_out* o, const rc_ray* r, float3 p, uint ci,
                                int refl, int hasthru, const rc_params* P, rc_rng_key key, uint dim,
                                uint spawn_dim) {
  if (o->super) return; /* the -as pass writes only its super-samples */
  uint target = 1u;
  if (P->spec.x > 1.5f) {
    int nt = (int)(P->spec.x * r->coef.w + 0.5f);
    target = nt > 1 ? (uint)nt : 1u;
  }
  float3 org = refl || b->thick == 0.0f ? p : p - b->thick * b->ron;
  for (uint n = 0; n < target; ++n) {
    uint dn = dim + 8u * n;
    float x = rc_sample(P, key, dn);
    if (target == 1u) {
      if (P->spec.x < 1.0f) x = 0.5f + P->spec.x * (x - 0.5f);
    } else {
      x = ((float)n + x) / (float)target;
    }
    float3 vin = rc_bsdf_jitter(b, b->sr_vpsa0, P, key, dn + 1u);
    float3 xi = (float3)(fmin(x, RC_BSDF_ALMOST_ONE), rc_sample(P, key, dn + 3u),
                         rc_sample(P, key, dn + 4u));
    float3 out;
    float pdf;
    if (!rc_bsdf_comp_sample(&b->t, ci, vin, xi, &out, &pdf)) break;
    float total = rc_bsdf_comp_total(&b->t, ci, vin);
    if (total <= RC_FTINY) break;
    if (hasthru) { /* the through peak was sent already: no sample near it */
      float dx = vin.x + out.x, dy = vin.y + out.y;
      if (dx * dx + dy * dy <= b->sr_vpsa0 * b->sr_vpsa0) continue;
    }
    float3 v = rc_bsdf_comp_eval(&b->t, ci, vin, out); /* the colour at the sample */
    float3 coef = v.y > 0.0f ? rc_bsdf_rgb(v * (total / v.y)) : (float3)(total);
    coef /= (float)target;
    if (!refl) coef *= b->pcol;
    uint depth;
    float weight = rc_child_weight(o, r, &coef, RC_RAY_SPECULAR, P, key, spawn_dim + n, &depth);
    if (weight <= 0.0f) continue;
    rc_emit_ray(o, r, org, normalize(rc_bsdf_world(b, out)), coef, RC_RAY_SPECULAR, P->spec.z,
                weight, depth, r->ambient_depth);
  }
}

/* Reflection (refl) or transmission of the residual: sampled, or returned as a coefficient for
 * the ambient when within -st (Radiance's sample_sdf). */
static float3 rc_bsdf_sample_side(const rc_bsdf_hit* b, rc_out* o, const rc_ray* r, float3 p,
                                  int refl, const rc_params* P, rc_rng_key key, uint dim,
                                  uint spawn_dim) {
  uint ci = rc_bsdf_comp_of(b, b->front, refl);
  if (ci == RC_NONE) return (float3)(0.0f);
  int hasthru = !refl && !(rc_crtype(r->flags) & (RC_CR_SPECULAR | RC_CR_AMBIENT)) &&
                rc_bright(b->cthru) > RC_FTINY;
  float tb = 0.0f;
  if (hasthru) { /* the view ray goes straight on, scaled (unless -lw stops it) */
    float3 c = b->cthru;
    uint depth;
    float w = rc_child_weight(o, r, &c, RC_RAY_TRANSMITTED, P, key, 6, &depth);
    if (w > 0.0f) {
      tb = rc_bright(b->cthru);
      if (!o->super)
        rc_emit_ray(o, r, p, r->dir.xyz, c, RC_RAY_TRANSMITTED, P->spec.z, w, depth,
                    r->ambient_depth);
    } else {
      hasthru = 0;
    }
  }
  float tot = 0.0f;
  if (b->t.comps[ci].max_hemi - tb > RC_FTINY) {
    float3 vj = rc_bsdf_jitter(b, b->sr_vpsa1, P, key, dim);
    tot = fmax(rc_bsdf_comp_total(&b->t, ci, vj) - tb, 0.0f);
  }
  if (tot <= P->spec.y + RC_FTINY) /* below the sampling threshold */
    return tot > RC_FTINY ? (refl ? (float3)(tot) : b->pcol * tot) : (float3)(0.0f);
  rc_bsdf_sample_comp(b, o, r, p, ci, refl, hasthru, P, key, dim + 2u, spawn_dim);
  return (float3)(0.0f);
}

/* BSDF and aBSDF at a hit seen from its ray's side (back faces already ruled by -bv). */
RC_NOINLINE
static void rc_shade_bsdf(const rc_scene_args* S, rc_out* o, const rc_material* mat,
                          const rc_ray* r, const rc_hit* h, rc_rng_key key) {
  const rc_params* P = &S->params;
  float3 p = h->pos.xyz, d = r->dir.xyz;
  float3 pert = h->front ? o->pert : -o->pert;
  rc_bsdf_hit b;
  int ok = rc_bsdf_setup(S, &b, mat, h, d, o->pcol, o->pert);
  /* A proxy hides itself from view rays and from rays meeting its hidden side. */
  if (b.thick != 0.0f && (!(rc_crtype(r->flags) & (RC_CR_SPECULAR | RC_CR_AMBIENT)) ||
                          (b.thick > 0.0f) != (h->front != 0))) {
    rc_pass(o, r, h, P, key);
    return;
  }
  if (!ok) return;
  (void)pert;
  rc_bsdf_diffuse(S, &b, mat);
  rc_bsdf_view_psa(&b);
  if (b.absdf) rc_bsdf_through(&b);
  float3 runsamp = rc_bsdf_sample_side(&b, o, r, p, 1, P, key, 10, 9);
  float3 tunsamp = rc_bsdf_sample_side(&b, o, r, p, 0, P, key, 40, 60);
  int dumb = h->surface < RC_SURF_IRRADIANCE &&
             (S->surfaces[h->surface].flags & RC_SURFF_NO_AMBIENT) != 0u;
  float3 known = rc_ambient(S, o, r, p, b.pnorm, b.rdiff + runsamp, dumb, key, 4096);
  float3 pt = p;
  if (b.thick != 0.0f) pt = h->front ? p - b.thick * b.ron : p + b.thick * b.ron;
  known += rc_ambient(S, o, r, pt, -b.pnorm, b.tdiff + tunsamp, dumb, key, 1u << 20);
  global const rc_bsdf* f = b.t.files;
  int transmits = rc_bright(b.tdiff) > RC_FTINY || f->comp[RC_BSDF_TF] != RC_NONE ||
                  f->comp[RC_BSDF_TB] != RC_NONE;
  if (!transmits || b.thick != 0.0f) {
    b.mode = RC_BSDF_DIR_R;
    rc_direct(S, o, 0, 0 RC_ANISO_ARG(0) RC_BSDF_ARG(&b), r, p, b.pnorm, d, 0, r->coef.xyz,
              rc_bright(known), key);
  }
  if (transmits) {
    b.mode = b.thick != 0.0f ? RC_BSDF_DIR_T : RC_BSDF_DIR_RT;
    rc_direct(S, o, 0, 0 RC_ANISO_ARG(0) RC_BSDF_ARG(&b), r, p - b.thick * b.ron, b.pnorm, d, 0,
              r->coef.xyz, rc_bright(known), key);
  }
}
