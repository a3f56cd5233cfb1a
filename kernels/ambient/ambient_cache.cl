/* Irradiance-cache lookups (Radiance's sumambient and extambient,
 * ../shared/docs/radiance/ambient-file.md §3): every record whose disc region holds the point
 * passes Radiance's level, direction, behind and elliptical-radius tests, is extrapolated with its
 * gradients and weighted by the product of the two hat functions. The records sit under a BVH of
 * their regions (built on the host with Embree's builder, src/ambient/cache.cpp), walked without a
 * stack: an inner node's first child follows it, `skip` jumps past its subtree.
 *
 * Differences from Radiance: every accepted record is summed (Radiance's octree stops early
 * in a node whose children already weigh 0.05), the maximum angle is narrowed for low-weight
 * rays whenever the ray's weight is below 0.6 (Radiance looks at the first record of each
 * octree node). The corral bits' light-leak test is the host's (ambient/leaks.h): the
 * records whose test ray it found blocked at this hit come in `blocked` ([count, index...]). */

/* Radiance's tfunc(x0, x, 0): a hat falling from 1 at 0 to 0 at x0. */
static inline float rc_amb_hat(float x0, float x) {
  return 1.0f - x / x0;
}

static int rc_amb_leaks(global const uint* blocked, uint k) {
  if (!blocked) return 0;
  for (uint i = 1u; i <= blocked[0]; ++i)
    if (blocked[i] == k) return 1;
  return 0;
}

/* Sum of the weighted, extrapolated values at p (normal n, ambient level al, ray weight rw)
 * into *acol; returns the sum of weights (0: no record applies). */
static float rc_amb_lookup(const rc_scene_args* S, float3 p, float3 n, uint al, float rw,
                           global const uint* blocked, float3* acol) {
  const float aa = S->params.amb.x, minarad = S->params.amb.y;
  const uint nnodes = (uint)S->params.amb.z;
  float maxangle = 10.0f * M_PI_F / 180.0f + aa;
  /* Radiance's pow(rw, 0.13), as exp2 of log2: pow's extended precision was 6% of a run. */
  if (rw < 0.6f) maxangle = (maxangle - M_PI_F / 2.0f) * exp2(0.13f * log2(rw)) + M_PI_F / 2.0f;
  /* The widest angle between n and an accepted record's normal (d > 0, 2 - 2d < maxangle^2):
   * the nodes whose normal cones cannot come that near n are skipped. */
  const float ct = fmax(1.0f - 0.5f * maxangle * maxangle, 0.0f), st = sqrt(1.0f - ct * ct);
  float wsum = 0.0f;
  float3 sum = (float3)(0.0f);
  uint i = 0u;
  while (i < nnodes) {
    global const rc_amb_node* nd = S->amb_nodes + i;
    if (any(p < nd->lo.xyz) || any(p > nd->hi.xyz)) {
      i = nd->skip;
      continue;
    }
    const float nc = nd->bin < 2u ? n.x : (nd->bin < 4u ? n.y : n.z);
    if ((nd->bin & 1u ? -nc : nc) < ct * nd->lo.w - st * nd->hi.w - 1e-6f) {
      i = nd->skip;
      continue;
    }
    if (nd->count == 0u) {
      ++i;
      continue;
    }
    for (uint k = nd->first; k < nd->first + nd->count; ++k) {
      global const rc_amb_record* a = S->amb_records + k;
      uint lvl = (uint)a->val.w;
      if (lvl > al || (lvl == al && a->pos.w < 0.9f * rw)) continue;
      float3 an = a->nrm.xyz;
      float d = dot(an, n);
      if (d <= 0.0f) continue;
      /* Unit normals met exactly (a record made at this very point) can give d a rounding
       * above 1: a negative dr2 would make the weight NaN and lose every record here. */
      float dr2 = fmax(2.0f - 2.0f * d, 0.0f);
      if (dr2 >= maxangle * maxangle) continue;
      float3 ck = p - a->pos.xyz;
      d = dot(ck, an);
      if (d < -minarad * aa - 0.001f) continue;
      d /= a->nrm.w;
      float dt2 = d * d;
      if (dt2 >= aa * aa) continue;
      float3 u = a->udir.xyz, v = cross(an, u);
      float cu = dot(ck, u), cv = dot(ck, v);
      dt2 += (cu / a->nrm.w) * (cu / a->nrm.w) + (cv / a->udir.w) * (cv / a->udir.w);
      if (dt2 >= aa * aa) continue;
      if (rc_amb_leaks(blocked, k)) continue; /* a light leak: Radiance's plugaleak */
      /* extambient: first-order change with position and with the normal's rotation. */
      float e = 1.0f + dot(ck, a->grad.x * u + a->grad.y * v) +
                dot(cross(an, n), a->grad.z * u + a->grad.w * v);
      if (!(e > 0.05f)) continue; /* also a non-finite gradient: never poison the sum */
      e = fmin(e, 20.0f);
      float w = rc_amb_hat(maxangle, sqrt(dr2)) * rc_amb_hat(aa, sqrt(dt2));
      sum += a->val.xyz * (e * w);
      wsum += w;
    }
    i = nd->skip;
  }
  *acol = sum;
  return wsum;
}
