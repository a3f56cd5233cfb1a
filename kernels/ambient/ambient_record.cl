/* Making an irradiance-cache record from one sampled hemisphere, as Radiance 5's doambient does
 * once the samples are in (docs/cache-internals.md, "Making a record"): the record's value is the
 * mean of the strata; the Hessian of the irradiance (Schwarzhaupt, Jensen & Jarosz 2012) over the
 * triangle mesh of the strata's hit points gives the two radii and the u axis, the same mesh's
 * form-factor gradient the translational gradient, the tangents of the sample directions the
 * rotational gradient, and the perimeter samples the corral bits. A program root of its own:
 * it needs nothing of the scene.
 *
 * The hemisphere's frame: x along ux, y along uy, z along the normal. Everything below works in
 * that frame, so the Hessian is only ever needed as its 2x2 tangential block. */
#include "radcl/device_types.h"
#include "radcl/luminance.h"

#define RC_AMR_FTINY 1e-6f
#define RC_AMR_MINADIV 7u
#define RC_AMR_AVGREFL 0.5f

/* Radiance's atan2a: a polynomial arctangent with values in [-pi/2, 3pi/2); the corral's sector
 * bits follow its values, so it is reproduced rather than replaced by atan2. */
static float rc_amr_atan_poly(float y, float x) {
  float q = y / x, aq = fabs(q);
  return M_PI_F / 4.0f * q - q * (aq - 1.0f) * (0.2447f + 0.0663f * aq) +
         (x < 0.0f ? M_PI_F : 0.0f);
}
static float rc_amr_atan2a(float y, float x) {
  if (x == 0.0f) return y > 0.0f ? M_PI_F / 2.0f : 1.5f * M_PI_F;
  if (fabs(y / x) > 1.01f) return M_PI_F / 2.0f - rc_amr_atan_poly(x, y);
  return rc_amr_atan_poly(y, x);
}

typedef struct rc_amr_frame {
  float3 o, x, y, z;
} rc_amr_frame;

static inline float3 rc_amr_local(const rc_amr_frame* f, float3 v) {
  return (float3)(dot(v, f->x), dot(v, f->y), dot(v, f->z));
}

/* The edge p0 -> p1 of the mesh, seen from the frame's origin with normal z: the gradient
 * (tangential part) and the tangential Hessian block (xx, xy, yy) of its share of a polygon's
 * form factor (Lambert's (1/2pi) theta n.(r0 x r1)/|r0 x r1|). With r(t) = r0 + t e and
 * Ik = integral over t in [0,1] of t^k / |r|^2m, the closed forms below are the standard
 * recurrences for those integrals. The Hessian carries Radiance's sign (minus the form factor's
 * second derivative), which makes it positive where the irradiance peaks. */
static void rc_amr_edge(float3 r0, float3 r1, float3 e, float2* grad, float3* hess) {
  float3 rc = cross(r0, e); /* = r0 x r1 */
  float dd = dot(rc, rc);
  float a0 = dot(r0, r0), a1 = dot(r1, r1), b0 = dot(e, r0), b1 = dot(e, r1), c = dot(e, e);
  if (!(dd > 0.0f) || !(c > 0.0f)) { /* a degenerate edge subtends nothing */
    *grad = (float2)(0.0f);
    *hess = (float3)(0.0f);
    return;
  }
  float sd = sqrt(dd);
  /* integral of 1/|r|^2: the angle (atan2 keeps it accurate for close samples) over |r0 x r1|. */
  float i1 = atan2(sd, dot(r0, r1)) / sd;
  /* integrals of 1/|r|^4 and t/|r|^4 */
  float i2 = (b1 / a1 - b0 / a0 + c * i1) * 0.5f / dd;
  float j2 = (0.5f * (1.0f / a0 - 1.0f / a1) - b0 * i2) / c;
  /* integrals of 1/|r|^6, t/|r|^6, t^2/|r|^6 */
  float i3 = (b1 / (a1 * a1) - b0 / (a0 * a0) + 3.0f * c * i2) * 0.25f / dd;
  float j3 = (0.25f * (1.0f / (a0 * a0) - 1.0f / (a1 * a1)) - b0 * i3) / c;
  float k3 = (i2 - a0 * i3 - 2.0f * b0 * j3) / c;
  float2 g = i2 * r0.xy + j2 * e.xy; /* integral of r/|r|^4, tangential part */
  float2 nc = (float2)(-e.y, e.x);   /* z x e */
  float nr = rc.z;                   /* z . (r0 x e) */
  *grad = (i1 * nc + 2.0f * nr * g) * (0.5f / M_PI_F);
  /* integral of r r^T/|r|^6, tangential block */
  float mxx = i3 * r0.x * r0.x + 2.0f * j3 * r0.x * e.x + k3 * e.x * e.x;
  float mxy = i3 * r0.x * r0.y + j3 * (r0.x * e.y + e.x * r0.y) + k3 * e.x * e.y;
  float myy = i3 * r0.y * r0.y + 2.0f * j3 * r0.y * e.y + k3 * e.y * e.y;
  float hxx = 2.0f * nc.x * g.x + nr * (4.0f * mxx - i2);
  float hxy = nc.x * g.y + g.x * nc.y + 4.0f * nr * mxy;
  float hyy = 2.0f * nc.y * g.y + nr * (4.0f * myy - i2);
  *hess = (float3)(hxx, hxy, hyy) * (-1.0f / M_PI_F);
}

/* A stratum's relative brightness, Radiance's normalised Y. */
static inline float rc_amr_y(global const rc_amb_sample* s, uint k, float scale, float floor_) {
  return rc_bright(s[k].val.xyz) * scale + floor_;
}

/* The weight of a mesh triangle: the relative brightness of its farthest vertex (ties go to
 * the first listed, then the second, as Radiance's back_ambval). */
static float rc_amr_back(global const rc_amb_sample* s, uint k0, uint k1, uint k2, float scale,
                         float floor_) {
  float d0 = s[k0].val.w, d1 = s[k1].val.w, d2 = s[k2].val.w;
  uint k = d0 <= d1 ? (d0 <= d2 ? k0 : k2) : (d1 <= d2 ? k1 : k2);
  return rc_amr_y(s, k, scale, floor_);
}

/* Triangles of cell (i, j): A = (i,j) (i,j+1) (i+1,j) and B = (i+1,j+1) (i+1,j) (i,j+1), both
 * counter-clockwise seen from above the hemisphere. */
static inline float rc_amr_tri_a(global const rc_amb_sample* s, uint ns, uint i, uint j, float sc,
                                 float fl) {
  return rc_amr_back(s, i * ns + j, i * ns + j + 1u, (i + 1u) * ns + j, sc, fl);
}
static inline float rc_amr_tri_b(global const rc_amb_sample* s, uint ns, uint i, uint j, float sc,
                                 float fl) {
  return rc_amr_back(s, (i + 1u) * ns + j + 1u, (i + 1u) * ns + j, i * ns + j + 1u, sc, fl);
}

/* Adds edge k0 -> k1 times w to the sums. */
static void rc_amr_add_edge(const rc_amr_frame* f, global const rc_amb_sample* s, uint k0, uint k1,
                            float w, float2* grad, float3* hess) {
  if (w == 0.0f) return;
  float3 p0 = s[k0].pnt.xyz, p1 = s[k1].pnt.xyz;
  float2 g;
  float3 h;
  rc_amr_edge(rc_amr_local(f, p0 - f->o), rc_amr_local(f, p1 - f->o), rc_amr_local(f, p1 - p0), &g,
              &h);
  *grad += w * g;
  *hess += w * h;
}

/* Cell (i, j)'s share of the sum over the mesh's triangles of weight x (the triangle's edges'
 * terms), added to grad and hess. The sum is gathered per edge: an inner edge is shared by two
 * triangles that run it in opposite directions, so it counts once with the difference of their
 * weights (an edge between equal weights costs nothing); cell (i, j) owns the edges leaving
 * (i, j) along its row and column and its A triangle's diagonal. */
static void rc_amr_cell_sums(const rc_amr_frame* f, global const rc_amb_sample* s, uint ns, uint i,
                             uint j, float sc, float fl, float2* grad, float3* hess) {
  float ta = 0.0f, tb = 0.0f;
  if (i + 1u < ns && j + 1u < ns) {
    ta = rc_amr_tri_a(s, ns, i, j, sc, fl);
    tb = rc_amr_tri_b(s, ns, i, j, sc, fl);
    /* diagonal (i,j+1) -> (i+1,j): forward in A, backward in B */
    rc_amr_add_edge(f, s, i * ns + j + 1u, (i + 1u) * ns + j, ta - tb, grad, hess);
  }
  if (j + 1u < ns) { /* row edge (i,j) -> (i,j+1): forward in A(i,j), back in B(i-1,j) */
    float w = i + 1u < ns ? ta : 0.0f;
    if (i > 0u) w -= rc_amr_tri_b(s, ns, i - 1u, j, sc, fl);
    rc_amr_add_edge(f, s, i * ns + j, i * ns + j + 1u, w, grad, hess);
  }
  if (i + 1u < ns) { /* column edge (i,j) -> (i+1,j): forward in B(i,j-1), back in A(i,j) */
    float w = j + 1u < ns ? -ta : 0.0f;
    if (j > 0u) w += rc_amr_tri_b(s, ns, i, j - 1u, sc, fl);
    rc_amr_add_edge(f, s, i * ns + j, (i + 1u) * ns + j, w, grad, hess);
  }
}

/* Stratum k's term of the rotational gradient's sum: Y tan(theta) towards the sample. A sample
 * met in the tangent plane itself (a direction on the disc's rim, z rounded to 0) has no finite
 * tangent: it would make the gradient NaN. */
static float2 rc_amr_tangent_term(const rc_amr_frame* f, global const rc_amb_sample* s, uint k,
                                  float sc, float fl) {
  float3 v = rc_amr_local(f, s[k].pnt.xyz - f->o);
  return v.z > 1e-6f * length(v) ? v.xy * (rc_amr_y(s, k, sc, fl) / v.z) : (float2)(0.0f);
}

/* Radii and axes from the tangential Hessian (Radiance's eigenvectors): radius (4/|lambda|)^1/4
 * per eigenvalue, the smaller one first; u0 (local xy) is the axis of the larger eigenvalue. Both
 * radii are the maximum where an eigenvalue vanishes. Unlike Radiance, the axes are the true
 * eigenvectors also for a negative eigenvalue and when the off-diagonal term is tiny (see
 * docs/cache-internals.md). */
static void rc_amr_axes(float3 h, float maxarad, float2* u0, float2* ra) {
  const float tiny = RC_AMR_FTINY * RC_AMR_FTINY;
  float mid = 0.5f * (h.x + h.z), hdif = 0.5f * (h.x - h.z);
  float disc = hdif * hdif + h.y * h.y;
  bool dbl = disc <= tiny;
  float sq = dbl ? 0.0f : sqrt(disc);
  float lo = mid - sq, hi = mid + sq; /* signed eigenvalues */
  *u0 = (float2)(1.0f, 0.0f);
  if (fabs(lo) <= tiny || fabs(hi) <= tiny) {
    *ra = (float2)(maxarad);
    return;
  }
  float big = fabs(lo) > fabs(hi) ? lo : hi, small = fabs(lo) > fabs(hi) ? hi : lo;
  *ra = (float2)(sqrt(sqrt(4.0f / fabs(big))), sqrt(sqrt(4.0f / fabs(small))));
  if (dbl) return;
  /* eigenvector of `small` (the long axis), from the better-conditioned row */
  float2 c1 = (float2)(h.y, small - h.x), c2 = (float2)(small - h.z, h.y);
  float2 v = dot(c1, c1) >= dot(c2, c2) ? c1 : c2;
  float vv = dot(v, v);
  if (!(vv > 0.0f)) return;
  v *= rsqrt(vv);
  if ((fabs(v.x) >= fabs(v.y) ? v.x : v.y) < 0.0f) v = -v; /* larger component positive */
  *u0 = (float2)(v.y, -v.x);                               /* so that z x u0 = v */
}

/* Radiance's ambcorral: sectors (32 of pi/16 around the normal, from u0) in which a perimeter
 * sample met something inside the record's ellipse (radii r0, r1 already times -aa). */
static uint rc_amr_corral(const rc_amr_frame* f, global const rc_amb_sample* s, uint ns, float2 u0,
                          float r0, float r1, float minarad, float aa) {
  if (ns < 8u) return 0u;
  const float max_d = 1.0f / (minarad * aa + 0.001f);
  const float ang_res = 0.5f * M_PI_F / (float)ns;
  const float ang_step = ang_res / ((float)(int)(16.0f / M_PI_F * ang_res) + 1.01f);
  /* the mean reciprocal distance overhead (the middle half of the strata per axis) */
  float avg_d = 0.0f;
  for (uint i = ns >> 2; i < ns * 3u / 4u; ++i)
    for (uint j = ns >> 2; j < ns * 3u / 4u; ++j)
      avg_d += s[i * ns + j].val.w;
  avg_d *= 4.0f / (float)(ns * ns);
  if (avg_d * r0 >= 1.0f || avg_d >= max_d) return 0u;
  float2 u1 = (float2)(-u0.y, u0.x);
  uint flags = 0u;
  for (uint i = 0; i < ns; ++i)
    for (uint j = 0; j < ns; j += (i == 0u || i == ns - 1u) ? 1u : ns - 1u) {
      global const rc_amb_sample* a = s + i * ns + j;
      float d = a->val.w;
      if (d <= RC_AMR_FTINY || d >= max_d) continue; /* too far or too near */
      float3 v = rc_amr_local(f, a->pnt.xyz - f->o);
      float u = dot(v.xy, u0), w = dot(v.xy, u1);
      if ((r0 * r0 * u * u + r1 * r1 * w * w) * d * d <= u * u + w * w) continue;
      float ang = rc_amr_atan2a(w, u);
      for (float t = ang - ang_res; t <= ang + ang_res; t += ang_step) {
        int bit = (int)(16.0f / M_PI_F * (t < 0.0f ? t + 2.0f * M_PI_F : t));
        flags |= 1u << min(max(bit, 0), 31);
      }
    }
  return flags;
}

/* Relative brightness: Y = 0.99 L / mean + 0.01 (scale sc, floor fl). A black hemisphere
 * falls back on the geometric Hessian (Y = 1 everywhere), with no gradients (its corral bits are
 * made: below). Returns whether the hemisphere is lit. */
static bool rc_amr_scale(float3 sum, uint ns, float* sc, float* fl) {
  float bs = RC_AMR_AVGREFL * rc_bright(sum); /* Radiance's bright(rcol) */
  bool lit = bs > RC_AMR_FTINY;
  *sc = lit ? 0.99f * (float)(ns * ns) / rc_bright(sum) : RC_AMR_AVGREFL * bs;
  *fl = lit ? 0.01f : 1.0f;
  return lit;
}

/* The record of one complete hemisphere of ns >= 7 strata whose values sum to `sum`, from the
 * mesh's sums g (gradient) and h (Hessian) and the rotational sum t; returns the status. */
static int rc_amr_full(const rc_amb_hemi* hp, global const rc_amb_sample* s, float3 sum, float2 g,
                       float3 h, float2 t, rc_amb_record* rec, uint* corral) {
  const uint ns = hp->ns;
  const float n2 = (float)(ns * ns);
  const float minarad = hp->nrm.w, maxarad = hp->ux.w, aa = hp->uy.w, wt = hp->pos.w;
  rc_amr_frame f = {hp->pos.xyz, hp->ux.xyz, hp->uy.xyz, hp->nrm.xyz};
  float sc, fl;
  bool lit = rc_amr_scale(sum, ns, &sc, &fl);
  float2 u0, ra;
  rc_amr_axes(h, maxarad, &u0, &ra);
  float2 u1 = (float2)(-u0.y, u0.x);
  float2 pg = (float2)(0.0f), dg = (float2)(0.0f);
  if (lit) {
    pg = (float2)(dot(g, u0), dot(g, u1));
    /* rotational gradient: the sum of Y tan(theta) towards each sample, turned by 90 degrees */
    dg = (float2)(-dot(u1, t), dot(u0, t)) / n2;
    /* radii no larger than the gradient allows */
    if (ra.x * fabs(pg.x) > 1.0f) ra.x = 1.0f / fabs(pg.x);
    if (ra.y * fabs(pg.y) > 1.0f) ra.y = 1.0f / fabs(pg.y);
    if (ra.x > ra.y) ra.x = ra.y;
  }
  if (ra.x < minarad) {
    ra.x = minarad;
    if (ra.y < minarad) ra.y = minarad;
  }
  ra *= 1.0f / sqrt(wt);
  if (ra.y > 2.0f * ra.x) ra.y = 2.0f * ra.x;
  if (ra.y > maxarad) {
    ra.y = maxarad;
    if (ra.x > maxarad) ra.x = maxarad;
  }
  /* Black hemispheres get corral bits too (Radiance gives them none), so that a dark record
   * does not reach through a wall into a lit room any more than a lit one into a dark box. */
  *corral = rc_amr_corral(&f, s, ns, u0, ra.x * aa, ra.y * aa, minarad, aa);
  if (lit) {
    /* extrapolation by the gradient stays within a factor of 2 inside the ellipse */
    float e = pg.x * pg.x * ra.x * ra.x + pg.y * pg.y * ra.y * ra.y;
    if (e > 1.0f) pg *= rsqrt(e);
  }
  float3 u3 = u0.x * f.x + u0.y * f.y;
  rec->nrm.w = ra.x;
  rec->udir = (float4)(u3, ra.y);
  rec->grad = (float4)(pg, dg);
  /* makeambient keeps no record of zero radius (possible only with -ar 0) */
  return ra.x > RC_AMR_FTINY ? RC_AMB_RECORD : RC_AMB_VALUE_ONLY;
}

/* One work-group of RC_AMR_GROUP items per hemisphere. The mesh's and the rotational
 * gradient's sums (thousands of edges, each with an arctangent: one item alone is latency-bound
 * on a GPU) are split over the items by strata and added up in a fixed tree, so a record does
 * not depend on the device; the value's sum and the rest are the first item's. */
kernel __attribute__((reqd_work_group_size(RC_AMR_GROUP, 1, 1))) void
rc_make_record(global const rc_amb_hemi* hemis, global const rc_amb_sample* samples, uint nhemi,
               global rc_amb_record* recs, global rc_amb_made* made) {
  local float4 part_h[RC_AMR_GROUP], part_g[RC_AMR_GROUP];
  local float4 value; /* the strata's sum; w: how many succeeded */
  const uint k = get_group_id(0), lid = get_local_id(0);
  if (k >= nhemi) return; /* the whole group */
  rc_amb_hemi hp = hemis[k];
  global const rc_amb_sample* s = samples + hp.first;
  const uint n2 = hp.ns * hp.ns;
  if (lid == 0u) {
    float3 sum = (float3)(0.0f);
    float3 lost = (float3)(0.0f); /* compensated sum: Radiance adds in double */
    uint ok = 0u;
    for (uint q = 0; q < n2; ++q)
      if (s[q].val.w >= 0.0f) {
        float3 y = s[q].val.xyz - lost, t = sum + y;
        lost = (t - sum) - y;
        sum = t;
        ++ok;
      }
    value = (float4)(sum, (float)ok);
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  const float3 sum = value.xyz;
  const uint ok = (uint)value.w;
  const bool full = ok == n2 && hp.ns >= RC_AMR_MINADIV; /* the same for every item */
  if (full) {
    rc_amr_frame f = {hp.pos.xyz, hp.ux.xyz, hp.uy.xyz, hp.nrm.xyz};
    float sc, fl;
    const bool lit = rc_amr_scale(sum, hp.ns, &sc, &fl);
    float2 g = (float2)(0.0f), t = (float2)(0.0f);
    float3 h = (float3)(0.0f);
    for (uint q = lid; q < n2; q += RC_AMR_GROUP) {
      rc_amr_cell_sums(&f, s, hp.ns, q / hp.ns, q % hp.ns, sc, fl, &g, &h);
      if (lit) t += rc_amr_tangent_term(&f, s, q, sc, fl);
    }
    part_h[lid] = (float4)(h, 0.0f);
    part_g[lid] = (float4)(g, t);
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint w = RC_AMR_GROUP / 2u; w > 0u; w >>= 1) {
      if (lid < w) {
        part_h[lid] += part_h[lid + w];
        part_g[lid] += part_g[lid + w];
      }
      barrier(CLK_LOCAL_MEM_FENCE);
    }
  }
  if (lid != 0u) return;
  rc_amb_record rec;
  rec.pos = hp.pos;
  rec.nrm = (float4)(hp.nrm.xyz, 0.0f);
  rec.udir = (float4)(hp.ux.xyz, 0.0f);
  rec.val = (float4)(sum, (float)hp.level);
  rec.grad = (float4)(0.0f);
  uint corral = 0u;
  int status = RC_AMB_FAILED;
  if (ok == 0u)
    status = RC_AMB_FAILED;
  else if (!full)
    status = RC_AMB_VALUE_ONLY; /* Radiance's soft failure: the value alone */
  else
    status = rc_amr_full(&hp, s, sum, part_g[0].xy, part_h[0].xyz, part_g[0].zw, &rec, &corral);
  recs[k] = rec;
  rc_amb_made m;
  m.corral = corral;
  m.status = status;
  m.pad0 = m.pad1 = 0u;
  made[k] = m;
}
