/* Indirect light without the cache: stratified cosine-weighted hemisphere samples (and the
 * cache lookup that answers instead where records cover the point). Included by shade.cl after
 * hit_output.cl. */

/* sin and cos of t, |t| <= pi/4, by their Taylor series to float accuracy (terms left out
 * are below 2e-9): no argument reduction, which was 3% of a run on PoCL. */
static inline float2 rc_sincos_quarter(float t) {
  float t2 = t * t;
  float s =
      t *
      (1.0f + t2 * (-1.0f / 6.0f + t2 * (1.0f / 120.0f + t2 * (-1.0f / 5040.0f + t2 / 362880.0f))));
  float c =
      1.0f + t2 * (-0.5f + t2 * (1.0f / 24.0f +
                                 t2 * (-1.0f / 720.0f + t2 * (1.0f / 40320.0f - t2 / 3628800.0f))));
  return (float2)(s, c);
}

/* Shirley and Chiu's concentric map of the unit square onto the unit disc. */
static inline float2 rc_square_to_disk(float sx, float sy) {
  float a = 2.0f * sx - 1.0f, b = 2.0f * sy - 1.0f;
  if (a == 0.0f && b == 0.0f) return (float2)(0.0f);
  if (a * a > b * b) { /* phi = pi/4 (b/a) */
    float2 sc = rc_sincos_quarter((M_PI_F / 4.0f) * (b / a));
    return (float2)(a * sc.y, a * sc.x);
  }
  /* phi = pi/2 - pi/4 (a/b): cos phi = sin(pi/4 (a/b)), sin phi = cos(pi/4 (a/b)) */
  float2 sc = rc_sincos_quarter((M_PI_F / 4.0f) * (a / b));
  return (float2)(b * sc.x, b * sc.y);
}

/* One stratified cosine-weighted direction in division (i, j) of an ns x ns hemisphere. Unit
 * to float rounding (d.x^2 + d.y^2 + z^2 = 1 in the orthonormal frame ux, uy, n) without
 * rescaling: its square root and division were a fifth of the hemisphere's time on PoCL, and
 * the geometry measures every ray's direction again in double. */
static inline float3 rc_hemi_dir(float3 n, float3 ux, float3 uy, uint i, uint j, uint ns, float s0,
                                 float s1) {
  float2 d = rc_square_to_disk((j + s0) / ns, (i + s1) / ns);
  float z = sqrt(fmax(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return d.x * ux + d.y * uy + z * n;
}

/* Indirect diffuse light without a cache (-aa 0): Radiance's stratified hemisphere of n x n
 * cosine-weighted samples, n = sqrt(-ad x weight), each carrying acoef / n^2; with no bounce
 * left, or on a surface the -ae/-ai lists leave out (`dumb`), the ambient value -av instead.
 * When Radiance would super-sample (-as; every division sampled, more than 7 x 7 of them, a
 * budget above 8), the samples are marked for the host, which gathers their values, spreads
 * the budget over the divisions by their neighbour differences and asks for the extra samples
 * in a second pass over this ray (o->super).
 * Returns what it adds to the ray's own value now (the ambient value, without the ray's
 * coefficient); sampled light comes later. */
RC_NOINLINE
static float3 rc_ambient(const rc_scene_args* S, rc_out* o, const rc_ray* r, float3 p, float3 n,
                         float3 acoef, int dumb, rc_rng_key key, uint dim) {
  const rc_params* P = &S->params;
  if (rc_bright(acoef) <= RC_FTINY) return (float3)(0.0f);
  if (r->ambient_depth >= P->ab || P->ad == 0 || dumb) {
    o->immediate += P->av.xyz * acoef * r->coef.xyz;
    return P->av.xyz * acoef;
  }
#ifdef RADCL_HAS_AMBCACHE
  /* Records that cover the point answer it (Radiance's multambient); a miss the host will not
   * make a record for is sampled as with -aa 0. */
  if (P->amb.z > 0.0f || P->amb.w > 0.0f) {
    float3 acol;
    float wsum = rc_amb_lookup(S, p, n, r->ambient_depth, r->coef.w, o->blocked, &acol);
    if (wsum > RC_FTINY) {
      float3 v = acol / wsum * acoef;
      o->immediate += v * r->coef.xyz;
      return v;
    }
    /* While the host builds the cache, a miss becomes a record request; the ray's value is
     * then incomplete and the host shades it again once records cover the point. */
    if (P->amb.w > 0.0f) {
      /* No record can be made where every sample ray would fall below -lw or past -lr (the
       * host's sample_hemispheres): Radiance's makeambient fails there and takes -av. */
      if (0.5f * r->coef.w < P->av.w || (P->lr > 0 && (int)r->depth + 1 > P->lr)) {
        o->immediate += P->av.xyz * acoef * r->coef.xyz;
        return P->av.xyz * acoef;
      }
      if (!o->super)
        rc_emit_ray(o, r, p, n, acoef, RC_RAY_AMBMISS, 0.0f, r->coef.w, r->depth, r->ambient_depth);
      o->doomed = 1;
      return (float3)(0.0f);
    }
  }
#endif
  /* Radiance caps the weight so that samples do not all fall below -lw. */
  float wt = r->coef.w;
  float lim = 0.8f * rc_max3(acoef) * r->coef.w / ((float)P->ad * P->av.w);
  if (wt > lim) wt = lim;
  uint ns = (uint)(sqrt((float)P->ad * wt) + 0.5f);
  if (ns < 1u) ns = 1u;
  float3 c = acoef / (float)(ns * ns);
  float3 ux = rc_unit(fabs(n.x) < 0.6f ? cross(n, (float3)(1, 0, 0)) : cross(n, (float3)(0, 1, 0)));
  float3 uy = cross(n, ux);
  uint which = o->nhemi++;
  if (o->super) {
    if (which != o->super[0]) return (float3)(0.0f);
    global const uint* counts = o->super + 1;
    for (uint cell = 0; cell < ns * ns; ++cell) {
      uint i = cell / ns, j = cell % ns;
      rc_rng_key k = key;
      k.sample = rc_child_sample(key.sample ^ 0x5EED5A3Bu, (which << 20) + cell);
      for (uint m = 1; m <= counts[cell]; ++m) {
        float3 dir =
            rc_hemi_dir(n, ux, uy, i, j, ns, rc_random(k, 3u * m), rc_random(k, 3u * m + 1u));
        uint depth;
        float3 cc = c;
        float weight = rc_child_weight(o, r, &cc, RC_RAY_AMBIENT, P, k, 3u * m + 2u, &depth);
        if (weight <= 0.0f) break; /* Radiance stops this division's super-samples */
        /* Child numbers apart from the first pass's keep the random streams apart. */
        o->child = 0x80000000u | (((which * 65536u + cell) * 8192u + m) & 0x7FFFFFFFu);
        rc_emit_ray(o, r, p, dir, cc, RC_RAY_AMBIENT, P->spec.z, weight, depth,
                    r->ambient_depth + 1u);
        if (o->write) o->spawned[o->nspawn - 1u].cell = RC_CELL_FLAG | (which << 29) | cell;
      }
    }
    return (float3)(0.0f);
  }
  uint start = o->nspawn;
  rc_rng_stream rs = rc_stream(key);
  for (uint i = 0; i < ns; ++i)
    for (uint j = 0; j < ns; ++j, dim += 3) {
      float s0 = rc_stream_random(&rs, dim), s1 = rc_stream_random(&rs, dim + 1);
      float3 dir = rc_hemi_dir(n, ux, uy, i, j, ns, s0, s1);
      rc_spawn_s(o, r, p, dir, c, RC_RAY_AMBIENT, P->spec.z, P, &rs, dim + 2,
                 r->ambient_depth + 1u);
    }
  float budget = (float)P->as * wt + 0.5f;
  uint nsamp = o->nspawn - start;
  bool more =
      P->as > 0u && nsamp == ns * ns && ns * ns > 49u && ns * ns <= 65536u && budget >= 9.0f;
  /* -oe: a primary's first hemispheres keep their divisions apart as well, with no budget, so
   * the host has the spread of their values (the sensor's standard error). */
  bool spread =
      (P->flags & RC_PF_SPREAD) && r->ambient_depth == 0u && nsamp > 1u && nsamp <= 65536u;
  if (more || spread) {
    o->cells = 1u;
    uint b = more ? min((uint)budget, RC_CELL_MAX_BUDGET) : 0u;
    if (o->write)
      for (uint k = 0; k < nsamp; ++k)
        o->spawned[start + k].cell = RC_CELL_FLAG | (which << 29) | (b << 16) | k;
  }
  return (float3)(0.0f);
}
