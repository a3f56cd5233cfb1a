/* Shading of the anisotropic materials (Radiance's m_aniso and m_ashikhmin) after
 * materials/aniso.cl's setup; included by shade_material.cl where its ray, ambient, direct and
 * Gaussian-sampling helpers are known. */

/* Ashikhmin-Shirley's specular rays: half vectors drawn from the lobe of powers au, av (one ray,
 * or -ss x weight of them each with its share of the coefficient), up to 10 tries each, a
 * direction below the surface rejected. */
RC_NOINLINE
static void rc_ashik_sample(rc_out* o, const rc_ray* r, float3 p, float3 ron, const rc_aniso* m,
                            const rc_params* P, rc_rng_key key, uint dim, uint spawn_dim) {
  if (o->super) return; /* the -as pass writes only its super-samples */
  float3 d = r->dir.xyz, coef = m->scolor;
  uint depth;
  float weight = rc_child_weight(o, r, &coef, RC_RAY_SPECULAR, P, key, spawn_dim, &depth);
  if (weight <= 0.0f) return;
  uint target = rc_spec_target(P, r, weight);
  if (target > 1u) {
    coef /= (float)target;
    weight /= (float)target;
    dim = RC_MULTISPEC_DIM;
  }
  float su = sqrt(m->au + 1.0f), sv = sqrt(m->av + 1.0f);
  uint taken = 0u;
  for (uint t = 0; taken < target && t < 10u * target; ++t) {
    float u1 = rc_sample(P, key, dim + 2u * t), u2 = rc_sample(P, key, dim + 2u * t + 1u);
    float phi = 2.0f * M_PI_F * u1;
    float cp = sv * cos(phi), sp = su * sin(phi);
    float k = rsqrt(cp * cp + sp * sp);
    cp *= k;
    sp *= k;
    float ct = pow(u2, 1.0f / (m->au * cp * cp + m->av * sp * sp + 1.0f));
    if (ct <= RC_FTINY) continue;
    float st = sqrt(fmax(1.0f - ct * ct, 0.0f));
    float3 h = st * (cp * m->u + sp * m->v) + ct * m->pnorm;
    float3 dir = d - 2.0f * dot(h, d) * h;
    if (dot(dir, ron) <= RC_FTINY) continue;
    rc_emit_ray(o, r, p, normalize(dir), coef, RC_RAY_SPECULAR, P->spec.z, weight, depth,
                r->ambient_depth);
    ++taken;
  }
}

/* plastic2, metal2, trans2, ashik2 at a hit; n faces the ray (the caller flipped a back face). */
RC_NOINLINE
static void rc_shade_aniso(const rc_scene_args* S, rc_out* o, const rc_material* mat,
                           const rc_ray* r, const rc_hit* h, float3 n, int flat, rc_rng_key key) {
  const rc_params* P = &S->params;
  float3 d = r->dir.xyz, p = h->pos.xyz;
  float3 pert = h->front ? o->pert : -o->pert; /* flipped with the surface */
  rc_aniso m;
  rc_aniso_setup(S, &m, mat, h, d, n, pert, o->pcol, flat);
  /* Specular rays first (they are not known to the -dt threshold, as for plastic). */
  if (m.ashik) {
    if (m.refl && !m.rblt) rc_ashik_sample(o, r, p, n, &m, P, key, 10, 9);
  } else {
    if (m.refl && !m.rblt)
      rc_gauss_sample_uv(o, r, p, m.pnorm, m.pnorm, m.u, m.v, m.au, m.av, m.scolor, 1, P, key, 10,
                         9);
    if (m.tran && !m.tblt)
      rc_gauss_sample_uv(o, r, p, m.pnorm, m.prdir, m.u, m.v, m.au, m.av, m.mcolor * m.tspec, 0, P,
                         key, 40, 60);
  }
  int dumb = h->surface < RC_SURF_IRRADIANCE &&
             (S->surfaces[h->surface].flags & RC_SURFF_NO_AMBIENT) != 0u;
  float3 known = (float3)(0.0f);
  /* The diffuse part to the ambient, with the specular one when it is too weak to sample. */
  if (m.ashik ? rc_bright(m.mcolor) > RC_FTINY : m.rdiff > RC_FTINY) {
    float3 acoef = m.ashik ? m.mcolor : m.mcolor * m.rdiff;
    if (m.rblt) acoef += m.scolor;
    known += rc_ambient(S, o, r, p, m.pnorm, acoef, dumb, key, 4096);
  }
  if (m.tdiff > RC_FTINY)
    known += rc_ambient(S, o, r, p, -m.pnorm, m.mcolor * (m.tblt ? m.trans : m.tdiff), dumb, key,
                        1u << 20);
  rc_direct(S, o, 0, 0 RC_ANISO_ARG(&m) RC_BSDF_ARG(0), r, p, m.pnorm, d, flat, r->coef.xyz,
            rc_bright(known), key);
}
