/* mist (Radiance's m_mist and srcscatter), included by shade_material.cl after direct.cl.
 * A mist surface is no surface: a ray crossing it inward gains the mist's extinction, its
 * albedo and eccentricity where given, and its list of sources; crossing outward it loses them
 * again (the albedo and eccentricity return to the global -ma and -mg). Along every segment of a
 * ray that carries such a list, the listed sources' light is scattered into it: -ms spaces the
 * sample points (one at least, RC_MIST_MAXSAMP at most), each a shadow request to one sample of
 * the whole source. Shadow rays cross mist boundaries by the same rule (shadow_step.cl). */

/* The medium a ray (or shadow ray) travels in, as mist boundaries change it. */
typedef struct rc_mist_medium {
  float3 cext;  /* extinction per unit length */
  uint medium;  /* where its albedo comes from (rc_ray.medium) */
  float gecc;   /* eccentricity */
  uint slights; /* listed sources (rc_ray.slights) */
} rc_mist_medium;

/* Crossing the mist whose arguments start at args offset `margs` (pcol: its patterns' colour,
 * which scales the extinction) inward (`entering`) or outward. `in` is the arriving ray's medium:
 * leaving a mist whose sources the ray did not all carry means it started inside without knowing
 * it, so its own segment gains the mist first (Radiance does the same). Returns the medium
 * beyond: the extinction taken away never falls below the global -me. */
static rc_mist_medium rc_mist_cross(const rc_scene_args* S, uint margs, float3 pcol, int entering,
                                    rc_mist_medium* in) {
  global const float* a = S->args + margs;
  uint n = (uint)a[RC_MIST_NREALS];
  uint mask = as_uint(a[RC_MIST_MASK]);
  if (S->params.mist != RC_NONE) /* only the names that denote a source */
    mask &= ((global const uint*)(S->args + S->params.mist))[32];
  float3 mext = (float3)(a[0], a[1], a[2]) * pcol;
  if (!entering && mask && (in->slights & mask) != mask) {
    in->cext += mext;
    if (n > 5u) in->medium = margs + RC_MIST_ALBEDO;
    if (n > 6u) in->gecc = a[RC_MIST_GECC];
    in->slights |= mask;
  }
  rc_mist_medium out = *in;
  if (entering) {
    out.cext += mext;
    if (n > 5u) out.medium = margs + RC_MIST_ALBEDO;
    if (n > 6u) out.gecc = a[RC_MIST_GECC];
    out.slights |= mask;
  } else {
    out.cext = fmax(in->cext - mext, S->params.medium.xyz);
    if (n > 5u) out.medium = RC_MEDIUM_GLOBAL;
    if (n > 6u) out.gecc = S->params.medium.w;
    out.slights &= ~mask;
  }
  return out;
}

static inline rc_mist_medium rc_mist_of(const rc_out* o) {
  rc_mist_medium m;
  m.cext = o->cext;
  m.medium = o->medium;
  m.gecc = o->gecc;
  m.slights = o->slights;
  return m;
}

static inline void rc_mist_set(const rc_scene_args* S, rc_out* o, rc_mist_medium m) {
  o->cext = m.cext;
  o->medium = m.medium;
  o->albedo = rc_medium_albedo(S, m.medium);
  o->gecc = m.gecc;
  o->slights = m.slights;
}

/* Transmittance over optical depth e, as srcscatter's (no shortcut for thin media). */
static inline float rc_mist_tr(float e) {
  return e > 92.0f ? 0.0f : exp(-e);
}

/* The listed sources' light scattered into ray r over its segment of length t in extinction
 * cext (o holds the rest of that medium): per source and sample point, one sample of the whole
 * source (no partition, -dj jitter), weighted by the Henyey-Greenstein phase of the angle
 * between the ray and the source, the source's solid angle, cext x albedo x t / (4 pi samples)
 * and the transmittance from the ray's origin to the point. r's coefficient is the one before
 * the segment's extinction. */
RC_NOINLINE
static void rc_mist_scatter(const rc_scene_args* S, rc_out* o, const rc_ray* r, float3 cext,
                            float t, rc_rng_key key) {
  const rc_params* P = &S->params;
  if (o->super || o->doomed || P->mist == RC_NONE) return;
  if (rc_max3(o->albedo) <= RC_FTINY || o->gecc >= 1.0f - RC_FTINY) return;
  float ms = P->albedo.w;
  uint ns = 1u;
  if (ms > RC_FTINY) ns = clamp((uint)(fmin(t / ms, 1e6f) + 0.5f), 1u, (uint)RC_MIST_MAXSAMP);
  global const uint* table = (global const uint*)(S->args + P->mist);
  float3 d = r->dir.xyz;
  float g = o->gecc;
  float3 k = r->coef.xyz * cext * o->albedo * (t / (4.0f * M_PI_F * (float)ns));
  for (uint b = 0; b < 32u; ++b) {
    if (!(o->slights & (1u << b))) continue;
    uint sn = table[b];
    if (sn >= P->nsources) continue; /* a name that matched no source */
    global const rc_source* src = S->sources + sn;
    for (uint j = 0; j < ns; ++j) {
      uint dim = (3u << 24) + 4u * (b * (uint)RC_MIST_MAXSAMP + j);
      float tt = t * ((float)j + rc_sample(P, key, dim)) / (float)ns;
      float3 ve =
          (float3)(rc_mist_tr(cext.x * tt), rc_mist_tr(cext.y * tt), rc_mist_tr(cext.z * tt));
      if (rc_max3(ve) <= RC_FTINY) break; /* too far in */
      float3 q = r->org.xyz + d * tt;
      rc_src_parts parts;
      rc_source_parts(src, q, 1u, &parts);
      rc_src_cell cell = rc_src_parts_next(&parts);
      float3 l;
      float dist, omega;
      if (!rc_source_sample_part(src, S->verts, q, (float3)(0.0f), cell, 1u, P->direct.y,
                                 rc_sample2(P, key, dim + 2u), &l, &dist, &omega))
        continue;
      float3 ls = rc_source_radiance(src, l, dist);
#ifdef RADCL_HAS_PATTERNS
      ls *= rc_source_pattern(S, src, q, l, dist, r->dist0 + tt);
#endif
      if (src->flags & RC_SRCF_VIRTUAL)
        ls *= rc_virtual_path(S->sources, S->mirrors, S->verts, src, q, l);
      if (rc_max3(ls) <= 0.0f) continue;
      float ph = 1.0f;
      if (g > RC_FTINY) {
        float x = 1.0f + g * g - 2.0f * g * dot(d, l);
        ph = (1.0f - g * g) / (x * sqrt(x));
      }
      float3 c = k * ls * ve * (ph * omega);
      if (rc_max3(c) > 0.0f) /* in mid-air: nothing to step off */
        rc_emit_shadow_from(o, (float4)(q, 0.0f), l, dist, c, r, sn, r->dist0 + tt);
    }
  }
}

static inline void rc_apply_medium(const rc_scene_args* S, rc_out* o, rc_ray* r, float3 cext,
                                   float t, rc_rng_key key);
static inline void rc_pass(rc_out* o, const rc_ray* r, const rc_hit* h, const rc_params* P,
                           rc_rng_key key);

/* A ray meets a mist surface: its own segment in the medium it arrived in (as corrected by
 * rc_mist_cross), then on through in the medium beyond. */
RC_NOINLINE
static void rc_shade_mist(const rc_scene_args* S, rc_out* o, rc_ray* r, const rc_hit* h,
                          const rc_material* m, rc_rng_key key) {
  rc_mist_medium in = rc_mist_of(o);
  rc_mist_medium out = rc_mist_cross(S, m->args, o->pcol, h->front, &in);
  rc_mist_set(S, o, in);
  rc_apply_medium(S, o, r, in.cext, h->pos.w, key);
  if (h->pos.w < 0.0f) return;
  rc_mist_set(S, o, out);
  rc_pass(o, r, h, &S->params, key);
}
