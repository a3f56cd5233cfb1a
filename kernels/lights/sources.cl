/* Light-source sampling for the direct calculation, after Radiance's srcsamp.c and srcray().
 *
 * Per shading point p: rc_source_cells() says into how many parts Radiance's -ds subdivision
 * cuts a source seen from p; rc_source_sample() gives part k (direction, distance, solid angle);
 * rc_source_radiance() what the source sends back along that direction.
 *
 * Partition: Radiance halves a flat source's sampling rectangle along its longer side, and a
 * cylinder along its axis, while the part is closer to p than its size / ds, at most 64 parts
 * (MAXSPART). Spheres and distant sources are never divided (Radiance's nopart()): a fully
 * visible uniform sphere lights a point exactly as a point source at its centre does.
 * The tree is a complete binary tree in heap order (node i, children 2i+1 lower and 2i+2 upper,
 * 63 nodes may split); node i splits when every node on its path is closer than size / ds, i.e.
 * when its key (the largest distance^2 / half-size^2 on the path) is below (2 / ds)^2. The tree
 * for a larger (2/ds)^2 only adds nodes, so the part count alone identifies the tree:
 * rc_source_sample() needs `cells`, not ds.
 *
 * dist is the distance to the sample point, as Radiance's: on a flat source, on a cylinder's
 * axis, inside a sphere. A shadow ray therefore counts as reaching the source when the first
 * thing it hits is the source's own surface. Radiance divides parts until size / distance
 * < ds / (ray weight): pass ds / weight as ds to reproduce that. */
#ifndef RADCL_RENDER_SOURCES_CL
#define RADCL_RENDER_SOURCES_CL

#include "radcl/device_types.h"
#include "lights/unit_vector.cl"

#define RC_SRC_MAXSPLIT 63 /* internal nodes of Radiance's 64-part limit */
#define RC_SRC_FTINY 1e-6f /* Radiance's FTINY */
#define RC_SRC_FAR 1e10f   /* distance of a distant source (Radiance's FHUGE) */
/* sqrt(pi)/2: Radiance partitions a disc as the square of equal area. */
#define RC_SRC_RING_EXT 0.88622693f

/* Cell of the partition in the source's parameter square [-1,1]^2: centre (x, y) and half
 * sizes (z, w). */
typedef float4 rc_src_cell;

static inline rc_src_cell rc_src_child(rc_src_cell c, uint upper, float uu, float vv) {
  /* Split along the side that is longer in the world (Radiance: du2 > dv2). */
  if (c.z * c.z * uu > c.w * c.w * vv) {
    c.z *= 0.5f;
    c.x += upper ? c.z : -c.z;
  } else {
    c.w *= 0.5f;
    c.y += upper ? c.w : -c.w;
  }
  return c;
}

/* Keys and cells of the 63 nodes that may split; the partition walks world vectors u, v (half
 * extents) from centre c. */
static inline void rc_src_tree(float3 p, float3 c, float3 u, float3 v, float* key,
                               rc_src_cell* cell) {
  float uu = dot(u, u), vv = dot(v, v);
  for (int i = 0; i < RC_SRC_MAXSPLIT; ++i) {
    rc_src_cell g = i == 0 ? (rc_src_cell)(0.0f, 0.0f, 1.0f, 1.0f)
                           : rc_src_child(cell[(i - 1) >> 1], (uint)(i - 1) & 1u, uu, vv);
    float3 q = c + g.x * u + g.y * v - p;
    float t = dot(q, q) / fmax(g.z * g.z * uu, g.w * g.w * vv);
    key[i] = i == 0 ? t : fmax(t, key[(i - 1) >> 1]);
    cell[i] = g;
  }
}

/* The n-th smallest (0-based) of a[0..len): quickselect, reorders a. */
static inline float rc_src_select(float* a, int len, int n) {
  int lo = 0, hi = len - 1;
  while (lo < hi) {
    float piv = a[(lo + hi) >> 1];
    int i = lo, j = hi;
    while (i <= j) {
      while (a[i] < piv)
        ++i;
      while (a[j] > piv)
        --j;
      if (i <= j) {
        float t = a[i];
        a[i++] = a[j];
        a[j--] = t;
      }
    }
    if (n <= j)
      hi = j;
    else if (n >= i)
      lo = i;
    else
      return a[n];
  }
  return a[n];
}

/* Part k of the partition with `cells` parts, in depth-first (lower half first) order. */
static inline rc_src_cell rc_src_find_cell(float3 p, float3 c, float3 u, float3 v, uint k,
                                           uint cells) {
  rc_src_cell root = (rc_src_cell)(0.0f, 0.0f, 1.0f, 1.0f);
  if (cells <= 1u) return root;
  float key[RC_SRC_MAXSPLIT], tmp[RC_SRC_MAXSPLIT];
  rc_src_cell cell[RC_SRC_MAXSPLIT];
  rc_src_tree(p, c, u, v, key, cell);
  for (int i = 0; i < RC_SRC_MAXSPLIT; ++i)
    tmp[i] = key[i];
  /* The cells-1 split nodes are those with the smallest keys (ancestor-closed: keys grow
   * downwards). */
  int nsplit = min((int)cells - 1, RC_SRC_MAXSPLIT);
  float limit = rc_src_select(tmp, RC_SRC_MAXSPLIT, nsplit - 1);
  float uu = dot(u, u), vv = dot(v, v);
  uint stack[8];
  int sp = 0;
  uint seen = 0;
  stack[sp++] = 0u;
  while (sp > 0) {
    uint i = stack[--sp];
    if (i < RC_SRC_MAXSPLIT && key[i] <= limit) {
      stack[sp++] = 2u * i + 2u;
      stack[sp++] = 2u * i + 1u;
      continue;
    }
    if (seen++ == k)
      return i < RC_SRC_MAXSPLIT ? cell[i]
                                 : rc_src_child(cell[(i - 1u) >> 1], (i - 1u) & 1u, uu, vv);
  }
  return root;
}

/* All parts of a partition in the order rc_src_find_cell() numbers them, building the split
 * tree once: a hit that samples every part of a source costs one tree, not one per part. */
typedef struct rc_src_parts {
  float key[RC_SRC_MAXSPLIT];
  rc_src_cell cell[RC_SRC_MAXSPLIT];
  float limit, uu, vv;
  uint stack[8];
  int sp;
  uint cells;
} rc_src_parts;

static inline void rc_src_parts_init(rc_src_parts* it, float3 p, float3 c, float3 u, float3 v,
                                     uint cells) {
  it->cells = cells;
  it->sp = 0;
  if (cells <= 1u) return;
  float tmp[RC_SRC_MAXSPLIT];
  rc_src_tree(p, c, u, v, it->key, it->cell);
  for (int i = 0; i < RC_SRC_MAXSPLIT; ++i)
    tmp[i] = it->key[i];
  int nsplit = min((int)cells - 1, RC_SRC_MAXSPLIT);
  it->limit = rc_src_select(tmp, RC_SRC_MAXSPLIT, nsplit - 1);
  it->uu = dot(u, u);
  it->vv = dot(v, v);
  it->stack[it->sp++] = 0u;
}

static inline rc_src_cell rc_src_parts_next(rc_src_parts* it) {
  rc_src_cell root = (rc_src_cell)(0.0f, 0.0f, 1.0f, 1.0f);
  if (it->cells <= 1u) return root;
  while (it->sp > 0) {
    uint i = it->stack[--it->sp];
    if (i < RC_SRC_MAXSPLIT && it->key[i] <= it->limit) {
      it->stack[it->sp++] = 2u * i + 2u;
      it->stack[it->sp++] = 2u * i + 1u;
      continue;
    }
    return i < RC_SRC_MAXSPLIT
               ? it->cell[i]
               : rc_src_child(it->cell[(i - 1u) >> 1], (i - 1u) & 1u, it->uu, it->vv);
  }
  return root;
}

/* Number of parts for a partition threshold (2/ds)^2. */
static inline uint rc_src_count(float3 p, float3 c, float3 u, float3 v, float ds) {
  if (ds <= RC_SRC_FTINY) return 1u;
  float k2 = (2.0f / ds) * (2.0f / ds);
  float3 q = c - p;
  if (dot(q, q) >= k2 * fmax(dot(u, u), dot(v, v))) return 1u; /* root does not split */
  float key[RC_SRC_MAXSPLIT];
  rc_src_cell cell[RC_SRC_MAXSPLIT];
  rc_src_tree(p, c, u, v, key, cell);
  uint n = 1u;
  for (int i = 0; i < RC_SRC_MAXSPLIT; ++i)
    n += key[i] < k2;
  return n;
}

/* Centre of a flat source's sampling rectangle (a polygon's may be off its centroid). */
static inline float3 rc_src_rect_centre(global const rc_source* s) {
  if (s->nverts == 0u) return s->pos.xyz;
  return s->pos.xyz + s->su.w * s->su.xyz + s->sv.w * s->sv.xyz;
}

/* Half extents the partition measures: a disc's equal-area square, as Radiance's. */
static inline float rc_src_walk_scale(global const rc_source* s) {
  return s->nverts == 0u ? RC_SRC_RING_EXT : 1.0f;
}

static inline uint rc_source_cells(global const rc_source* s, float3 p, float ds) {
  if (s->kind == RC_SRC_DISTANT) return 1u;
  float3 c = s->pos.xyz;
  if (s->flags & RC_SRCF_GLOW) { /* Radiance's srcskip(): beyond reach of every sample */
    float srad = s->kind == RC_SRC_CYLINDER ? 0.5f * s->axis.w : s->pos.w;
    float reach = s->emit.w + srad;
    if (dot(p - c, p - c) > reach * reach) return 0u;
  }
  if (s->kind == RC_SRC_SPHERE) return 1u;
  if (s->kind == RC_SRC_FLAT) {
    if (dot(p - c, s->axis.xyz) <= 0.0f) return 0u; /* behind */
    float f = rc_src_walk_scale(s);
    return rc_src_count(p, rc_src_rect_centre(s), f * s->su.xyz, f * s->sv.xyz, ds);
  }
  /* Cylinder (Radiance's cylpart()): none from inside, one when within two radii. */
  float3 v = p - c;
  float along = dot(v, s->axis.xyz), r = s->pos.w;
  float perp2 = dot(v, v) - along * along;
  if (perp2 <= r * r) return 0u;
  if (perp2 <= 4.0f * r * r) return 1u;
  return rc_src_count(p, c, 0.5f * s->axis.w * s->axis.xyz, (float3)(0.0f), ds);
}

/* Shirley-Chiu concentric map of [-1,1]^2 onto the unit disc (area-proportional). */
static inline float2 rc_src_concentric(float2 a) {
  if (a.x == 0.0f && a.y == 0.0f) return (float2)(0.0f);
  float r, phi;
  if (fabs(a.x) > fabs(a.y)) {
    r = a.x;
    phi = M_PI_4_F * (a.y / a.x);
  } else {
    r = a.y;
    phi = M_PI_2_F - M_PI_4_F * (a.x / a.y);
  }
  return r * (float2)(cos(phi), sin(phi));
}

/* [-1,1]^2 onto the annulus ri <= r <= 1 (ri relative to the outer radius), area-proportional. */
static inline float2 rc_src_ring_map(float2 a, float ri) {
  float2 d = rc_src_concentric(a);
  float rho = length(d);
  float rad = sqrt(ri * ri + rho * rho * (1.0f - ri * ri));
  return rho > 0.0f ? d * (rad / rho) : (float2)(rad, 0.0f);
}

/* Two unit vectors perpendicular to unit e and to each other. */
static inline void rc_src_frame(float3 e, float3* a, float3* b) {
  float3 t = fabs(e.x) < 0.6f
                 ? (float3)(1.0f, 0.0f, 0.0f)
                 : (fabs(e.y) < 0.6f ? (float3)(0.0f, 1.0f, 0.0f) : (float3)(0.0f, 0.0f, 1.0f));
  *a = rc_unit(cross(t, e));
  *b = cross(e, *a);
}

/* Area and first moments (x, y) of the part of segment a->b's region inside the cell
 * [x0,x1]x[y0,y1], by Green's theorem with F = clamp(x) - x0 restricted to y0 <= y <= y1
 * (clamp is linear between the breakpoints where x crosses x0 or x1). */
static inline float3 rc_src_edge_moments(float2 a, float2 b, float x0, float x1, float y0,
                                         float y1) {
  float3 m = (float3)(0.0f);
  float dy = b.y - a.y;
  if (dy == 0.0f) return m;
  float ta = (y0 - a.y) / dy, tb = (y1 - a.y) / dy;
  float tlo = fmax(0.0f, fmin(ta, tb)), thi = fmin(1.0f, fmax(ta, tb));
  if (tlo >= thi) return m;
  float ts[4];
  int n = 0;
  ts[n++] = tlo;
  float dx = b.x - a.x;
  if (dx != 0.0f) {
    float t0 = (x0 - a.x) / dx, t1 = (x1 - a.x) / dx;
    float tm = fmin(t0, t1), tM = fmax(t0, t1);
    if (tm > tlo && tm < thi) ts[n++] = tm;
    if (tM > tlo && tM < thi) ts[n++] = tM;
  }
  ts[n++] = thi;
  for (int i = 0; i + 1 < n; ++i) {
    float2 p = a + ts[i] * (b - a), q = a + ts[i + 1] * (b - a);
    float ca = clamp(p.x, x0, x1), cb = clamp(q.x, x0, x1);
    float fa = ca - x0, fb = cb - x0, h = q.y - p.y;
    m.x += 0.5f * (fa + fb) * h;
    m.y += 0.5f * h * ((ca * ca + ca * cb + cb * cb) * (1.0f / 3.0f) - x0 * x0);
    m.z += h * (1.0f / 6.0f) * (2.0f * fa * p.y + fa * q.y + fb * p.y + 2.0f * fb * q.y);
  }
  return m;
}

/* Polygon vertex in the rectangle's parameters (s, t): v = centre + s su + t sv. */
static inline float2 rc_src_param(float4 v, float3 o, float3 du, float3 dv) {
  float3 d = v.xyz - o;
  return (float2)(dot(d, du), dot(d, dv));
}

/* Radiance's polygon sample: the part of the polygon inside the cell, its area (in parameter
 * units) and centroid; *inside tells whether parameter point q lies in the polygon. */
static inline float3 rc_src_polygon_cell(global const rc_source* s, global const float4* verts,
                                         rc_src_cell g, float2 q, int* inside) {
  float3 n = s->axis.xyz, su = s->su.xyz, sv = s->sv.xyz, o = rc_src_rect_centre(s);
  float det = dot(cross(su, sv), n);
  float3 du = cross(sv, n) / det, dv = cross(n, su) / det;
  global const float4* v = verts + s->verts;
  uint nv = s->nverts;
  float3 m = (float3)(0.0f);
  int cross_count = 0;
  float2 a = rc_src_param(v[nv - 1u], o, du, dv);
  for (uint i = 0; i < nv; ++i) {
    float2 b = rc_src_param(v[i], o, du, dv);
    m += rc_src_edge_moments(a, b, g.x - g.z, g.x + g.z, g.y - g.w, g.y + g.w);
    if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y))
      ++cross_count;
    a = b;
  }
  *inside = cross_count & 1;
  return m;
}

static inline int rc_src_sample_flat(global const rc_source* s, global const float4* verts,
                                     float3 p, rc_src_cell g, float dj, float2 xi, float3* pt,
                                     float* area) {
  float3 n = s->axis.xyz;
  if (dot(p - s->pos.xyz, n) <= 0.0f) return 0; /* behind */
  float3 c = rc_src_rect_centre(s);
  float2 q = g.xy + dj * (2.0f * xi - 1.0f) * g.zw;
  if (s->nverts == 0u) {
    /* Ring: the square mapped onto the disc or annulus (area-proportional, so a jittered point
     * is uniform over the cell's image). Without jitter the image's centroid (2x2 Gauss
     * points) rather than the image of the cell centre keeps the quadrature second order. */
    float ri = s->su.w / s->pos.w;
    float2 d = rc_src_ring_map(q, ri);
    if (dj < 1.0f) {
      float2 o = g.zw * 0.57735027f;
      float2 m = 0.25f * (rc_src_ring_map(g.xy + o, ri) + rc_src_ring_map(g.xy - o, ri) +
                          rc_src_ring_map(g.xy + (float2)(o.x, -o.y), ri) +
                          rc_src_ring_map(g.xy + (float2)(-o.x, o.y), ri));
      d += (1.0f - dj) * (m - rc_src_ring_map(g.xy, ri));
    }
    *pt = c + d.x * s->su.xyz + d.y * s->sv.xyz;
    *area = s->axis.w * g.z * g.w;
    return 1;
  }
  int inside;
  float3 m = rc_src_polygon_cell(s, verts, g, q, &inside);
  float cell_area = 4.0f * g.z * g.w;
  if (m.x <= 1e-6f * cell_area) return 0; /* cell misses the polygon */
  /* A cell the polygon only partly covers: keep a jittered point that falls on the polygon,
   * else use the centroid of the covered part. */
  if (m.x < (1.0f - 1e-4f) * cell_area && (dj <= 0.0f || !inside)) q = m.yz / m.x;
  *pt = c + q.x * s->su.xyz + q.y * s->sv.xyz;
  *area = m.x * length(cross(s->su.xyz, s->sv.xyz));
  return 1;
}

/* The k-th of `cells` samples of source s from point p with surface normal n (n = 0: no
 * horizon test, e.g. for translucent materials). Sets the unit direction towards the sample,
 * its distance and the solid angle it stands for; 0 if unusable. A spotlight's focus
 * adjustment of the solid angle (Radiance's d^2/(d+focus)^2) is applied here; its cone test is
 * in rc_source_radiance(). */
static inline int rc_source_sample_part(global const rc_source* s, global const float4* verts,
                                        float3 p, float3 n, rc_src_cell g, uint cells, float dj,
                                        float2 xi, float3* dir, float* dist, float* omega) {
  if (cells == 0u) return 0;
  float3 l;
  float d, om;
  if (s->kind == RC_SRC_DISTANT) {
    /* Uniform over the source's cone, shrunk by dj; without jitter, its centre. */
    float3 e = s->pos.xyz;
    l = e;
    if (dj > 0.0f) {
      float3 a, b;
      rc_src_frame(e, &a, &b);
      float2 w = rc_src_concentric(dj * (2.0f * xi - 1.0f));
      float rho2 = dot(w, w), one_minus_cos = s->axis.w * (0.5f * M_1_PI_F);
      float cost = 1.0f - rho2 * one_minus_cos;
      float sint = sqrt(fmax(0.0f, 1.0f - cost * cost));
      float2 cs = rho2 > 0.0f ? w * rsqrt(rho2) : (float2)(1.0f, 0.0f);
      l = rc_unit(cost * e + sint * (cs.x * a + cs.y * b));
    }
    d = RC_SRC_FAR;
    om = s->axis.w / (float)cells;
  } else if (s->kind == RC_SRC_SPHERE) {
    /* One sample: the projected disc, jittered by dj; a uniform sphere lights a point above
     * its horizon as a point source of solid angle pi r^2 / d^2 at its centre. */
    float3 v = s->pos.xyz - p;
    float r = s->pos.w, dc2 = dot(v, v);
    if (dc2 <= r * r) return 0; /* inside */
    float3 e = v * rsqrt(dc2), a, b;
    rc_src_frame(e, &a, &b);
    float2 w = r * rc_src_concentric(dj * (2.0f * xi - 1.0f));
    float3 q = v + w.x * a + w.y * b;
    d = length(q);
    l = q / d;
    om = M_PI_F * r * r / dc2 / (float)cells;
  } else if (s->kind == RC_SRC_FLAT) {
    float3 pt;
    float area;
    if (!rc_src_sample_flat(s, verts, p, g, dj, xi, &pt, &area)) return 0;
    float3 q = pt - p;
    d = length(q);
    if (d <= 0.0f) return 0;
    l = q / d;
    float coss = -dot(s->axis.xyz, l);
    /* Radiance drops samples whose projected share is tiny (grazing or behind). */
    if (coss * (area / s->axis.w) <= 1e-4f) return 0;
    om = area * coss / (d * d);
  } else { /* cylinder: part of the axis, jittered along it and across its silhouette */
    float3 c = s->pos.xyz, ax = s->axis.xyz, v = p - c;
    float len = s->axis.w, r = s->pos.w, along = dot(v, ax);
    if (dot(v, v) - along * along <= r * r) return 0; /* inside */
    float su = g.x + dj * (2.0f * xi.x - 1.0f) * g.z;
    float3 across = normalize(cross(ax, v));
    float3 q = c + (0.5f * len * su) * ax + (dj * (2.0f * xi.y - 1.0f) * r) * across - p;
    d = length(q);
    if (d <= 0.0f) return 0;
    l = q / d;
    float ca = dot(l, ax), sint = sqrt(fmax(0.0f, 1.0f - ca * ca));
    if (sint * g.z <= 1e-4f) return 0;
    om = 2.0f * r * len * g.z * sint / (d * d);
  }
  if (dot(n, n) > 0.0f && dot(l, n) <= 0.0f) return 0; /* below the surface's horizon */
  if ((s->flags & RC_SRCF_SPOT) && s->kind != RC_SRC_DISTANT) {
    float df = d + s->spot_focus;
    om *= (d * d) / (df * df);
  }
  if (!(om > 0.0f)) return 0;
  *dir = l;
  *dist = d;
  *omega = om;
  return 1;
}

/* The walk vectors a source's partition uses: half extents u, v from centre c (flat sources:
 * their sampling rectangle; cylinders: half the axis). 0 for sources that are never split. */
static inline int rc_source_walk(global const rc_source* s, float3* c, float3* u, float3* v) {
  if (s->kind == RC_SRC_FLAT) {
    float f = rc_src_walk_scale(s);
    *c = rc_src_rect_centre(s);
    *u = f * s->su.xyz;
    *v = f * s->sv.xyz;
    return 1;
  }
  if (s->kind == RC_SRC_CYLINDER) {
    *c = s->pos.xyz;
    *u = 0.5f * s->axis.w * s->axis.xyz;
    *v = (float3)(0.0f);
    return 1;
  }
  return 0;
}

/* Prepares the parts of source s seen from p, to be taken in turn with rc_src_parts_next(). */
static inline void rc_source_parts(global const rc_source* s, float3 p, uint cells,
                                   rc_src_parts* it) {
  float3 c, u, v;
  if (!rc_source_walk(s, &c, &u, &v)) cells = 1u;
  rc_src_parts_init(it, p, c, u, v, cells);
}

/* The k-th of `cells` samples (rebuilds the partition: for one sample; loops over all parts
 * use rc_source_parts()). */
static inline int rc_source_sample(global const rc_source* s, global const float4* verts, float3 p,
                                   float3 n, uint k, uint cells, float dj, float2 xi, float3* dir,
                                   float* dist, float* omega) {
  if (cells == 0u || k >= cells) return 0;
  float3 c, u, v;
  rc_src_cell g = (rc_src_cell)(0.0f, 0.0f, 1.0f, 1.0f);
  if (rc_source_walk(s, &c, &u, &v)) g = rc_src_find_cell(p, c, u, v, k, cells);
  return rc_source_sample_part(s, verts, p, n, g, cells, dj, xi, dir, dist, omega);
}

/* Radiance sent from source s back along -dir_from_p by a sample at distance dist: only the
 * front of a flat source emits, a spotlight only inside its cone, a glow only within its
 * radius. */
static inline float3 rc_source_radiance(global const rc_source* s, float3 dir_from_p, float dist) {
  if (s->kind == RC_SRC_FLAT && dot(dir_from_p, s->axis.xyz) >= 0.0f) return (float3)(0.0f);
  if ((s->flags & RC_SRCF_GLOW) && dist > s->emit.w) return (float3)(0.0f);
  if ((s->flags & RC_SRCF_SPOT) && -dot(dir_from_p, s->spot.xyz) < s->spot.w) return (float3)(0.0f);
  return s->emit.xyz;
}

#endif /* RADCL_RENDER_SOURCES_CL */
