/* BSDF data on the device (Radiance's BSDF and aBSDF materials): evaluation, sampling and
 * directional-hemispherical totals of the tables include/radcl/render/compile/bsdf_tables.h builds
 * (layout in include/radcl/bsdf_device_types.h). Vectors are unit vectors in the BSDF's local
 * frame (front = +Z, both pointing away from the surface: `in` towards the light, `out`
 * towards the viewer). Values are BSDFs in 1/sr, CIE X, Y, Z (grey data: X = Y = Z).
 *
 * Component functions act on a component's residual, its data less the Lambertian part
 * rc_bsdf_comp.lamb; they follow radcl::bsdf::f (src/bsdf/evaluate.cpp), reciprocity included.
 * File functions add the Lambertian parts and pick the component as Radiance's SDevalBSDF,
 * SDdirectHemi and SDsampBSDF do.
 *
 * Sampling draws `out` with the density f cos(theta_out) / total over solid angle: Klems by
 * the cumulative sums over outgoing patches, then uniformly in projected solid angle within
 * the patch; tensor trees by a descent that picks among the four children of each branch
 * that the incident position leaves open, in proportion to their mean values there (the slice
 * tables), then uniformly within the leaf, mapped to the hemisphere by the Shirley-Chiu map.
 * Not sampled (total 0), as in Radiance: an isotropic tree (TT3) used through reciprocity. */
#ifndef RC_BSDF_EVAL_CL
#define RC_BSDF_EVAL_CL

#include "radcl/bsdf_device_types.h"

typedef struct rc_bsdf_tables {
  global const rc_bsdf* files;
  global const rc_bsdf_comp* comps;
  global const float* vals;
  global const int* ints;
} rc_bsdf_tables;

#define RC_BSDF_ALMOST_ONE 0x1.fffffep-1f /* the largest float below 1 */

static inline int rc_bsdf_in_front(uint part) {
  return part == RC_BSDF_RF || part == RC_BSDF_TF;
}
static inline int rc_bsdf_out_front(uint part) {
  return part == RC_BSDF_RF || part == RC_BSDF_TB;
}

/* ---- Shirley-Chiu concentric map between [0,1]^2 and the unit disk (equal areas) ---- */

static inline float2 rc_bsdf_square_to_disk(float2 s) {
  float a = 2.0f * s.x - 1.0f, b = 2.0f * s.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return (float2)(0.0f);
  float r, phi;
  if (fabs(a) > fabs(b)) {
    r = a;
    phi = M_PI_4_F * (b / a);
  } else {
    r = b;
    phi = M_PI_2_F - M_PI_4_F * (a / b);
  }
  return (float2)(r * cos(phi), r * sin(phi));
}

static inline float2 rc_bsdf_disk_to_square(float x, float y) {
  float r = sqrt(x * x + y * y);
  float phi = atan2(y, x);
  if (phi < -M_PI_4_F) phi += 2.0f * M_PI_F; /* [-pi/4, 7pi/4): one quarter per side */
  float a, b;
  if (phi < M_PI_4_F) {
    a = r;
    b = a * phi / M_PI_4_F;
  } else if (phi < 3.0f * M_PI_4_F) {
    b = r;
    a = -b * (phi - M_PI_2_F) / M_PI_4_F;
  } else if (phi < 5.0f * M_PI_4_F) {
    a = -r;
    b = a * (phi - M_PI_F) / M_PI_4_F;
  } else {
    b = -r;
    a = -b * (phi - 1.5f * M_PI_F) / M_PI_4_F;
  }
  return (float2)(0.5f + 0.5f * a, 0.5f + 0.5f * b);
}

/* The unit vector over a disk point, on the front (zsign 1) or back (-1). */
static inline float3 rc_bsdf_lift(float2 d, float zsign) {
  return (float3)(d, zsign * sqrt(fmax(0.0f, 1.0f - dot(d, d))));
}

/* ---- Klems ---- */

/* Patch of a direction in a hemisphere's canonical frame (z >= 0), or -1. */
static inline int rc_klems_patch(const rc_bsdf_tables* t, uint basis, float3 d) {
  if (d.z < 0.0f) return -1;
  global const int* b = t->ints + basis;
  global const float* theta = t->vals + b[2];
  int rings = b[0];
  float th = atan2(sqrt(d.x * d.x + d.y * d.y), d.z) * (180.0f / M_PI_F);
  int r = 0;
  while (r < rings && theta[r + 1] <= th)
    ++r;
  if (r == rings) return -1;
  float phi = atan2(d.y, d.x) * (180.0f / M_PI_F);
  if (phi < 0.0f) phi += 360.0f;
  int n = b[4 + 2 * r];
  int j = (int)(phi * (float)n / 360.0f + 0.5f); /* patch j is centred on j * 360 / n */
  if (j >= n) j = 0;
  return b[5 + 2 * r] + j;
}

/* Radiance's indexing: an incident vector by the direction its light travels. */
static inline int rc_klems_in_patch(const rc_bsdf_tables* t, uint basis, float3 v, int front) {
  float z = front ? v.z : -v.z;
  return z < 0.0f ? -1 : rc_klems_patch(t, basis, (float3)(-v.x, -v.y, z));
}
static inline int rc_klems_out_patch(const rc_bsdf_tables* t, uint basis, float3 v, int front) {
  float z = front ? v.z : -v.z;
  return z < 0.0f ? -1 : rc_klems_patch(t, basis, (float3)(v.x, v.y, z));
}

static inline float3 rc_klems_eval(const rc_bsdf_tables* t, global const rc_bsdf_comp* c, float3 in,
                                   float3 out) {
  int fi = rc_bsdf_in_front(c->part), fo = rc_bsdf_out_front(c->part);
  int i = rc_klems_in_patch(t, c->in_basis, in, fi);
  int o = rc_klems_out_patch(t, c->out_basis, out, fo);
  if (i < 0 && o < 0) { /* reciprocity: the pair fits with in and out exchanged */
    i = rc_klems_in_patch(t, c->in_basis, out, fi);
    o = rc_klems_out_patch(t, c->out_basis, in, fo);
  }
  if (i < 0 || o < 0) return (float3)(0.0f);
  uint n = c->n_in * c->n_out, at = (uint)o * c->n_in + (uint)i;
  global const float* v = t->vals + c->values;
  if (!c->colour) return (float3)(v[at]);
  return (float3)(v[n + at], v[at], v[2u * n + at]);
}

/* The running sums for light from `in`: the row of its incident patch, or under reciprocity
 * the reverse row of the outgoing patch it lies in. *n gets the row's length, *rev whether it
 * is reversed; NULL when there is none. */
static inline global const float*
rc_klems_row(const rc_bsdf_tables* t, global const rc_bsdf_comp* c, float3 in, uint* n, int* rev) {
  int i = rc_klems_in_patch(t, c->in_basis, in, rc_bsdf_in_front(c->part));
  if (i >= 0) {
    *n = c->n_out;
    *rev = 0;
    return t->vals + c->cdf + (uint)i * c->n_out;
  }
  int o = rc_klems_out_patch(t, c->out_basis, in, rc_bsdf_out_front(c->part));
  if (o < 0 || c->rcdf == RC_NONE) return 0;
  *n = c->n_in;
  *rev = 1;
  return t->vals + c->rcdf + (uint)o * c->n_in;
}

static inline float rc_klems_total(const rc_bsdf_tables* t, global const rc_bsdf_comp* c,
                                   float3 in) {
  uint n;
  int rev;
  global const float* row = rc_klems_row(t, c, in, &n, &rev);
  return row ? row[n - 1u] : 0.0f;
}

static inline int rc_klems_sample(const rc_bsdf_tables* t, global const rc_bsdf_comp* c, float3 in,
                                  float3 xi, float3* out) {
  uint n;
  int rev;
  global const float* row = rc_klems_row(t, c, in, &n, &rev);
  if (!row || !(row[n - 1u] > 0.0f)) return 0;
  float u = xi.x * row[n - 1u];
  uint lo = 0u, hi = n - 1u; /* the first patch whose running sum exceeds u */
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (row[mid] > u)
      hi = mid;
    else
      lo = mid + 1u;
  }
  /* A uniform point of the patch in projected solid angle: sin^2(theta) and phi uniform. */
  global const int* b = t->ints + (rev ? c->in_basis : c->out_basis);
  global const float* theta = t->vals + b[2];
  int r = 0;
  while (r + 1 < b[0] && b[5 + 2 * (r + 1)] <= (int)lo)
    ++r;
  float s0 = sinpi(theta[r] / 180.0f), s1 = sinpi(theta[r + 1] / 180.0f);
  float s2 = mad(xi.y, s1 * s1 - s0 * s0, s0 * s0);
  float nphi = (float)b[4 + 2 * r];
  float phi = 2.0f * M_PI_F * ((float)((int)lo - b[5 + 2 * r]) - 0.5f + xi.z) / nphi;
  float st = sqrt(s2);
  float3 d = (float3)(st * cos(phi), st * sin(phi), sqrt(fmax(0.0f, 1.0f - s2)));
  /* Outgoing patches are indexed by out itself, reversed ones (incident) by -out. */
  int front = rev ? rc_bsdf_in_front(c->part) : rc_bsdf_out_front(c->part);
  *out = (float3)(rev ? -d.x : d.x, rev ? -d.y : d.y, front ? d.z : -d.z);
  return 1;
}

/* ---- Tensor trees ---- */

/* The hypercube position of a pair in the tree's own orientation (radcl::bsdf::TensorTree). */
static inline float4 rc_tree_position(uint format, float3 in, float3 out) {
  if (format == RC_BSDF_TT3) {
    float p0 = (0.5f - 1e-6f) - 0.5f * sqrt(in.x * in.x + in.y * in.y);
    float a = -atan2(-in.y, -in.x); /* turns the incident light onto +x */
    float c = cos(a), s = sin(a);
    float2 q = rc_bsdf_disk_to_square(out.x * c - out.y * s, out.x * s + out.y * c);
    return (float4)(p0, q, 0.0f);
  }
  return (float4)(rc_bsdf_disk_to_square(-in.x, -in.y), rc_bsdf_disk_to_square(out.x, out.y));
}

static inline float3 rc_tree_leaf(const rc_bsdf_tables* t, global const rc_bsdf_comp* c, int k) {
  global const float* v = t->vals + t->ints[k];
  return c->colour ? (float3)(v[1], v[0], v[2]) : (float3)(v[0]);
}

/* The leaf at a hypercube position; *edge gets its edge length. */
static inline int rc_tree_find(const rc_bsdf_tables* t, global const rc_bsdf_comp* c, float4 pos,
                               float* edge) {
  int nd = c->format == RC_BSDF_TT3 ? 3 : 4;
  float p[4] = {pos.x, pos.y, pos.z, pos.w};
  for (int d = 0; d < nd; ++d)
    p[d] = clamp(p[d], 0.0f, RC_BSDF_ALMOST_ONE);
  int k = (int)c->root;
  *edge = 1.0f;
  while (t->ints[k] < 0) {
    int ch = 0;
    for (int d = 0; d < nd; ++d) {
      p[d] *= 2.0f;
      if (p[d] >= 1.0f) {
        ch |= 1 << d;
        p[d] -= 1.0f;
      }
    }
    k = t->ints[k + 3 + ch];
    *edge *= 0.5f;
  }
  return k;
}

static inline float3 rc_tree_lookup(const rc_bsdf_tables* t, global const rc_bsdf_comp* c,
                                    float4 pos) {
  float edge;
  return rc_tree_leaf(t, c, rc_tree_find(t, c, pos, &edge));
}

/* Which pair the tree sees: (in, out) or, for transmission through reciprocity, (out, in);
 * 0 when the pair does not fit the component's sides (radcl::bsdf's tree_f). */
static inline int rc_tree_orient(uint part, float3 in, float3 out, int* swap) {
  *swap = 0;
  switch (part) {
  case RC_BSDF_RF:
    return in.z >= 0.0f && out.z >= 0.0f;
  case RC_BSDF_RB:
    return in.z <= 0.0f && out.z <= 0.0f;
  case RC_BSDF_TF:
    if (out.z > 0.0f) return (*swap = in.z <= 0.0f);
    return in.z >= 0.0f;
  default: /* RC_BSDF_TB */
    if (in.z > 0.0f) return (*swap = out.z <= 0.0f);
    return out.z >= 0.0f;
  }
}

static inline float3 rc_tree_eval(const rc_bsdf_tables* t, global const rc_bsdf_comp* c, float3 in,
                                  float3 out) {
  int swap;
  if (!rc_tree_orient(c->part, in, out, &swap)) return (float3)(0.0f);
  return rc_tree_lookup(
      t, c, swap ? rc_tree_position(c->format, out, in) : rc_tree_position(c->format, in, out));
}

/* The mean Y of node k over its picked dimensions at the fixed position p (relative to the node,
 * in [0,1)), from its slice table (rev: the reverse one). */
static inline float rc_tree_slice(const rc_bsdf_tables* t, int k, float2 p, int nfixed, int rev) {
  int h = -t->ints[k];
  if (h <= 0) return t->vals[t->ints[k]];
  int side = 1 << h;
  int i = min((int)(p.x * (float)side), side - 1);
  if (nfixed == 2) i = i * side + min((int)(p.y * (float)side), side - 1);
  return t->vals[t->ints[k + 1 + rev] + i];
}

/* The tree's slice for light from `in`: how the descent runs. 0 when there is none. */
typedef struct rc_tree_walk {
  float2 p;     /* fixed coordinates */
  int nfixed;   /* 1 (TT3) or 2 */
  int fixed[2]; /* fixed dimensions */
  int pick[2];  /* dimensions the descent picks */
  int rev;      /* reverse slice tables: TT4 through reciprocity */
  float zsign;  /* side of the sampled vectors */
  float angle;  /* TT3: the turn of the outgoing vector */
} rc_tree_walk;

static inline int rc_tree_walk_for(global const rc_bsdf_comp* c, float3 in, rc_tree_walk* w) {
  int fi = rc_bsdf_in_front(c->part), fo = rc_bsdf_out_front(c->part);
  int reverse = fi ? in.z < 0.0f : in.z > 0.0f; /* in lies on the component's out side */
  if (reverse && (fi == fo || c->format == RC_BSDF_TT3)) return 0;
  w->rev = reverse;
  w->zsign = (reverse ? fi : fo) ? 1.0f : -1.0f;
  w->angle = 0.0f;
  if (c->format == RC_BSDF_TT3) {
    w->nfixed = 1;
    w->p = (float2)((0.5f - 1e-6f) - 0.5f * sqrt(in.x * in.x + in.y * in.y), 0.0f);
    w->fixed[0] = w->fixed[1] = 0;
    w->pick[0] = 1;
    w->pick[1] = 2;
    w->angle = atan2(-in.y, -in.x);
    return 1;
  }
  w->nfixed = 2;
  /* Forward: fixed dimensions 0-1 hold in (negated); reverse: 2-3 hold in as tree-out. */
  w->p = reverse ? rc_bsdf_disk_to_square(in.x, in.y) : rc_bsdf_disk_to_square(-in.x, -in.y);
  w->fixed[0] = reverse ? 2 : 0;
  w->fixed[1] = reverse ? 3 : 1;
  w->pick[0] = reverse ? 0 : 2;
  w->pick[1] = reverse ? 1 : 3;
  return 1;
}

static inline float rc_tree_total(const rc_bsdf_tables* t, global const rc_bsdf_comp* c,
                                  float3 in) {
  rc_tree_walk w;
  if (!rc_tree_walk_for(c, in, &w)) return 0.0f;
  float2 p = clamp(w.p, 0.0f, RC_BSDF_ALMOST_ONE);
  return M_PI_F * rc_tree_slice(t, (int)c->root, p, w.nfixed, w.rev);
}

static inline int rc_tree_sample(const rc_bsdf_tables* t, global const rc_bsdf_comp* c, float3 in,
                                 float3 xi, float3* out) {
  rc_tree_walk w;
  if (!rc_tree_walk_for(c, in, &w)) return 0;
  float2 p = clamp(w.p, 0.0f, RC_BSDF_ALMOST_ONE);
  float u = xi.y, v = xi.z; /* warped at each level to pick the children, then placed */
  float2 cell = (float2)(0.0f);
  float size = 1.0f;
  int k = (int)c->root;
  while (t->ints[k] < 0) {
    int base = 0; /* the fixed dimensions' halves, as a lookup takes them */
    p *= 2.0f;
    if (p.x >= 1.0f) {
      base |= 1 << w.fixed[0];
      p.x -= 1.0f;
    }
    if (w.nfixed == 2 && p.y >= 1.0f) {
      base |= 1 << w.fixed[1];
      p.y -= 1.0f;
    }
    float m[4];
    for (int q = 0; q < 4; ++q) {
      int ch = base | (q & 1) << w.pick[0] | (q >> 1) << w.pick[1];
      m[q] = rc_tree_slice(t, t->ints[k + 3 + ch], p, w.nfixed, w.rev);
    }
    /* First pick dimension: the lower half (a = 0) or the upper; then the second, given a. */
    float lo = m[0] + m[2], hi = m[1] + m[3], sum = lo + hi;
    if (!(sum > 0.0f)) return 0;
    int a = !(lo > 0.0f) || (hi > 0.0f && u * sum >= lo);
    u = a ? (u * sum - lo) / hi : u * sum / lo;
    float ma = m[a], mb = m[a + 2];
    int b = !(ma > 0.0f) || (mb > 0.0f && v * (ma + mb) >= ma);
    v = b ? (v * (ma + mb) - ma) / mb : v * (ma + mb) / ma;
    u = fmin(u, RC_BSDF_ALMOST_ONE);
    v = fmin(v, RC_BSDF_ALMOST_ONE);
    size *= 0.5f;
    cell += (float2)((float)a, (float)b) * size;
    k = t->ints[k + 3 + (base | a << w.pick[0] | b << w.pick[1])];
  }
  float2 d = rc_bsdf_square_to_disk(cell + (float2)(u, v) * size);
  if (w.rev) { /* the tree's incident vector: dimensions 0-1 hold (-x, -y) */
    *out = rc_bsdf_lift(-d, w.zsign);
    return 1;
  }
  float ca = cos(w.angle), sa = sin(w.angle); /* undo the TT3 turn (0 for TT4) */
  *out = rc_bsdf_lift((float2)(d.x * ca - d.y * sa, d.x * sa + d.y * ca), w.zsign);
  return 1;
}

/* ---- Components ---- */

/* The residual BSDF of component `comp` for a pair (0 where it does not fit its sides). */
static inline float3 rc_bsdf_comp_eval(const rc_bsdf_tables* t, uint comp, float3 in, float3 out) {
  global const rc_bsdf_comp* c = t->comps + comp;
  return c->format == RC_BSDF_KLEMS ? rc_klems_eval(t, c, in, out) : rc_tree_eval(t, c, in, out);
}

/* The residual's directional-hemispherical total (CIE Y) for light from `in`. */
static inline float rc_bsdf_comp_total(const rc_bsdf_tables* t, uint comp, float3 in) {
  global const rc_bsdf_comp* c = t->comps + comp;
  return c->format == RC_BSDF_KLEMS ? rc_klems_total(t, c, in) : rc_tree_total(t, c, in);
}

/* The density over solid angle with which rc_bsdf_comp_sample draws `out`. */
static inline float rc_bsdf_comp_pdf(const rc_bsdf_tables* t, uint comp, float3 in, float3 out) {
  float total = rc_bsdf_comp_total(t, comp, in);
  return total > 0.0f ? rc_bsdf_comp_eval(t, comp, in, out).y * fabs(out.z) / total : 0.0f;
}

/* Draws `out` for light from `in` with three uniform numbers in [0,1) (Klems: xi.x picks the
 * patch; xi.y and xi.z place the point); *pdf gets its density over solid angle. 0 when the
 * residual scatters nothing from `in`. */
static inline int rc_bsdf_comp_sample(const rc_bsdf_tables* t, uint comp, float3 in, float3 xi,
                                      float3* out, float* pdf) {
  global const rc_bsdf_comp* c = t->comps + comp;
  int ok = c->format == RC_BSDF_KLEMS ? rc_klems_sample(t, c, in, xi, out)
                                      : rc_tree_sample(t, c, in, xi, out);
  *pdf = ok ? rc_bsdf_comp_pdf(t, comp, in, *out) : 0.0f;
  return ok && *pdf > 0.0f;
}

/* ---- Files: Lambertian parts plus the component Radiance picks ---- */

/* The part of a pair by the sides of in and out (front: z > 0), and its component: for
 * transmission without data for in's side, the other side's (reciprocity). */
static inline uint rc_bsdf_part(global const rc_bsdf* f, int in_front, int out_front, uint* comp) {
  uint part = in_front == out_front ? (in_front ? RC_BSDF_RF : RC_BSDF_RB)
                                    : (in_front ? RC_BSDF_TF : RC_BSDF_TB);
  *comp = f->comp[part];
  if (*comp == RC_NONE && part >= RC_BSDF_TF) *comp = f->comp[part ^ 1u];
  return part;
}

static inline float3 rc_bsdf_eval(const rc_bsdf_tables* t, uint file, float3 in, float3 out) {
  global const rc_bsdf* f = t->files + file;
  uint comp, part = rc_bsdf_part(f, in.z > 0.0f, out.z > 0.0f, &comp);
  float3 v = f->lamb[part].xyz;
  return comp == RC_NONE ? v : v + rc_bsdf_comp_eval(t, comp, in, out);
}

/* Directional-hemispherical reflectance (reflection != 0) or transmittance, CIE Y. */
static inline float rc_bsdf_total(const rc_bsdf_tables* t, uint file, float3 in, int reflection) {
  global const rc_bsdf* f = t->files + file;
  int front = in.z > 0.0f;
  uint comp, part = rc_bsdf_part(f, front, reflection ? front : !front, &comp);
  float total = M_PI_F * f->lamb[part].y;
  return comp == RC_NONE ? total : total + rc_bsdf_comp_total(t, comp, in);
}

/* The totals of light from `in` (w: Lambertian reflection, residual reflection, Lambertian
 * transmission, residual transmission) and the components (reflection, transmission). */
static inline float rc_bsdf_weights(const rc_bsdf_tables* t, uint file, float3 in, float* w,
                                    uint* comp) {
  global const rc_bsdf* f = t->files + file;
  int front = in.z > 0.0f;
  for (int s = 0; s < 2; ++s) { /* s = 0: reflection, 1: transmission */
    uint part = rc_bsdf_part(f, front, s ? !front : front, &comp[s]);
    w[2 * s] = M_PI_F * f->lamb[part].y;
    w[2 * s + 1] = comp[s] == RC_NONE ? 0.0f : rc_bsdf_comp_total(t, comp[s], in);
  }
  return w[0] + w[1] + w[2] + w[3];
}

/* The mixture's density at out: each part's share times its density, where a residual that is
 * sampled at all (w > 0) has the density f cos / w. */
static inline float rc_bsdf_mix_pdf(const rc_bsdf_tables* t, const float* w, const uint* comp,
                                    float all, float3 in, float3 out) {
  int s = (in.z > 0.0f) != (out.z > 0.0f);
  float f = w[2 * s] * M_1_PI_F;
  if (w[2 * s + 1] > 0.0f) f += rc_bsdf_comp_eval(t, comp[s], in, out).y;
  return f * fabs(out.z) / all;
}

/* The density over solid angle with which rc_bsdf_sample draws `out`. */
static inline float rc_bsdf_pdf(const rc_bsdf_tables* t, uint file, float3 in, float3 out) {
  float w[4];
  uint comp[2];
  float all = rc_bsdf_weights(t, file, in, w, comp);
  return all > 1e-6f ? rc_bsdf_mix_pdf(t, w, comp, all, in, out) : 0.0f;
}

/* Draws `out` among the Lambertian reflection and transmission and the two residuals in
 * proportion to their totals (SDsampBSDF), with three uniform numbers in [0,1); *pdf gets the
 * density over solid angle. 0 when nothing is scattered (all totals at most 1e-6). */
static inline int rc_bsdf_sample(const rc_bsdf_tables* t, uint file, float3 in, float3 xi,
                                 float3* out, float* pdf) {
  float w[4];
  uint comp[2];
  float all = rc_bsdf_weights(t, file, in, w, comp);
  *pdf = 0.0f;
  if (!(all > 1e-6f)) return 0;
  float u = xi.x * all;
  int k = 0;
  while (k < 3 && u >= w[k]) {
    u -= w[k];
    ++k;
  }
  while (!(w[k] > 0.0f)) /* past the end by rounding: the last part with a share */
    --k;
  xi.x = clamp(u / w[k], 0.0f, RC_BSDF_ALMOST_ONE);
  if (k & 1) {
    float p;
    if (!rc_bsdf_comp_sample(t, comp[k >> 1], in, xi, out, &p)) return 0;
  } else { /* Lambertian: cosine-weighted on its side */
    int out_front = (in.z > 0.0f) != (k == 2);
    *out = rc_bsdf_lift(rc_bsdf_square_to_disk(xi.yz), out_front ? 1.0f : -1.0f);
  }
  *pdf = rc_bsdf_mix_pdf(t, w, comp, all, in, *out);
  return *pdf > 0.0f;
}

#endif /* RC_BSDF_EVAL_CL */
