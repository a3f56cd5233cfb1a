/* The shading wave: one work-item per ray of the wave, with its host-computed hit. Two passes
 * run the same code: rc_count only counts the shadow rays and spawned rays each hit makes, the
 * host turns the counts into offsets, and rc_shade writes them there. Fixed offsets keep the
 * output order independent of scheduling, so results are bit-identical across devices, thread
 * counts and wave sizes. */
#include "radcl/device_types.h"
#include "radcl/rng.h"
#include "render/sources.cl"
#include "generated.cl"

#define RC_FTINY 1e-6f
/* Radiance's perceptual brightness weights (CIE Y of its RGB primaries). */
static inline float rc_bright(float3 c) {
  return 0.265074126f * c.x + 0.670114631f * c.y + 0.064811243f * c.z;
}
static inline float rc_max3(float3 c) { return fmax(c.x, fmax(c.y, c.z)); }

typedef struct rc_scene_args {
  global const rc_surface* surfaces;
  global const rc_material* materials;
  global const float* args;
  global const rc_source* sources;
  global const float4* verts;
  rc_params params; /* a private copy: read on every sample */
} rc_scene_args;

/* Where one hit writes: counts in count mode, records in write mode. */
typedef struct rc_out {
  int write;
  uint nshadow, nspawn;
  global rc_shadow* shadows;
  global rc_ray* spawned;
  float3 immediate; /* contributions that need no shadow test (emission, ambient value) */
} rc_out;

static inline void rc_emit_shadow(rc_out* o, float3 org, float3 dir, float tmin, float tmax,
                                  float3 contrib, uint primary, uint source) {
  if (o->write) {
    rc_shadow s;
    s.org = (float4)(org, tmin);
    s.dir = (float4)(dir, tmax);
    s.contrib = (float4)(contrib, 0.0f);
    s.primary = primary;
    s.source = source;
    s.pad0 = s.pad1 = 0;
    o->shadows[o->nshadow] = s;
  }
  o->nshadow++;
}

/* A child's random-number stream: mixes the parent's sample index with the child's number. */
static inline uint rc_child_sample(uint parent, uint child) {
  uint h = (parent ^ 0x9E3779B9u) * 0x85EBCA6Bu;
  h ^= h >> 13;
  h = (h + child * 0xC2B2AE35u) * 0x27D4EB2Fu;
  return h ^ (h >> 15);
}

/* Spawns a child ray with Radiance's rayorigin() rules: the weight falls by the largest
 * coefficient (at most 1); reflections (not transmissions) count towards -lr; below -lw the ray
 * dies, or with -lr <= 0 plays Russian roulette and a survivor's coefficient is promoted. */
static inline void rc_spawn(rc_out* o, const rc_ray* parent, float3 org, float3 dir, float3 coef,
                            uint kind, float tmin, const rc_params* P, rc_rng_key key, uint dim,
                            uint ambient_depth) {
  float rw = fmin(rc_max3(coef), 1.0f);
  float weight = parent->coef.w * rw;
  if (weight <= 0.0f) return;
  uint depth = parent->depth + (kind == RC_RAY_TRANSMITTED ? 0u : 1u);
  int lr = P->lr;
  float lw = P->av.w;
  if (lr <= 0) {
    if (lr < 0 && depth > (uint)(-lr)) return;
    if (weight < lw) {
      if (rc_random(key, dim) > weight / lw) return;
      coef *= lw / weight;
      weight = lw;
    }
  } else if (weight < lw || depth > (uint)lr) {
    return;
  }
  if (o->write) {
    rc_ray r;
    r.org = (float4)(org, tmin);
    r.dir = (float4)(dir, INFINITY);
    r.coef = (float4)(parent->coef.xyz * coef, weight);
    r.primary = parent->primary;
    r.depth = depth;
    r.flags = kind;
    r.sample = rc_child_sample(parent->sample, o->nspawn);
    r.ambient_depth = ambient_depth;
    r.pad0 = r.pad1 = r.pad2 = 0;
    o->spawned[o->nspawn] = r;
  }
  o->nspawn++;
}

/* Shirley and Chiu's concentric map of the unit square onto the unit disc. */
static inline float2 rc_square_to_disk(float sx, float sy) {
  float a = 2.0f * sx - 1.0f, b = 2.0f * sy - 1.0f;
  if (a == 0.0f && b == 0.0f) return (float2)(0.0f);
  float r, phi;
  if (a * a > b * b) {
    r = a;
    phi = (M_PI_F / 4.0f) * (b / a);
  } else {
    r = b;
    phi = M_PI_F / 2.0f - (M_PI_F / 4.0f) * (a / b);
  }
  return (float2)(r * cos(phi), r * sin(phi));
}

/* Indirect diffuse light without a cache (-aa 0): Radiance's stratified hemisphere of n x n
 * cosine-weighted samples, n = sqrt(-ad x weight), each carrying acoef / n^2; with no bounce
 * left, the ambient value -av instead. (-as super-sampling is not done: it only moves samples
 * towards high-variance divisions.) */
static void rc_ambient(rc_out* o, const rc_ray* r, float3 p, float3 n, float3 acoef,
                       const rc_params* P, rc_rng_key key) {
  if (rc_bright(acoef) <= RC_FTINY) return;
  if (r->ambient_depth >= P->ab || P->ad == 0) {
    o->immediate += P->av.xyz * acoef * r->coef.xyz;
    return;
  }
  /* Radiance caps the weight so that samples do not all fall below -lw. */
  float wt = r->coef.w;
  float lim = 0.8f * rc_max3(acoef) * r->coef.w / ((float)P->ad * P->av.w);
  if (wt > lim) wt = lim;
  uint ns = (uint)(sqrt((float)P->ad * wt) + 0.5f);
  if (ns < 1u) ns = 1u;
  float3 c = acoef / (float)(ns * ns);
  float3 ux = normalize(fabs(n.x) < 0.6f ? cross(n, (float3)(1, 0, 0))
                                        : cross(n, (float3)(0, 1, 0)));
  float3 uy = cross(n, ux);
  uint dim = 4096;
  for (uint i = 0; i < ns; ++i)
    for (uint j = 0; j < ns; ++j, dim += 3) {
      float2 d = rc_square_to_disk((j + rc_random(key, dim)) / ns, (i + rc_random(key, dim + 1)) / ns);
      float z = sqrt(fmax(0.0f, 1.0f - d.x * d.x - d.y * d.y));
      float3 dir = normalize(d.x * ux + d.y * uy + z * n);
      rc_spawn(o, r, p, dir, c, RC_RAY_AMBIENT, P->spec.z, P, key, dim + 2,
               r->ambient_depth + 1u);
    }
}

/* Visible emission of a light-type material toward the ray (scene-format.md §3.6). */
static float3 rc_light_emission(const rc_scene_args* S, const rc_material* m, const rc_ray* r,
                                const rc_hit* h, uint kind) {
  global const float* a = S->args + m->args;
  float3 rad = (float3)(a[0], a[1], a[2]);
  int distant = h->pos.w < 0.0f;
  if (!distant && !h->front) return (float3)(0.0f); /* only the front side emits */
  if (kind == RC_RAY_PRIMARY && !(S->params.flags & RC_PF_DV)) return (float3)(0.0f);
  if (kind == RC_RAY_AMBIENT || kind == RC_RAY_SPECULAR) {
    /* Counted by the direct calculation already, except a glow beyond its radius of
     * influence, or a glow that is no direct source at all. */
    if (m->type != RC_OBJ_GLOW) return (float3)(0.0f);
    float rmax = a[3];
    if (rmax > RC_FTINY && !distant && h->pos.w <= rmax) return (float3)(0.0f);
  }
  if (m->type == RC_OBJ_SPOTLIGHT) {
    float3 sd = normalize((float3)(a[4], a[5], a[6]));
    if (dot(-r->dir.xyz, sd) < cos(radians(a[3]) * 0.5f)) return (float3)(0.0f);
  }
  return rad;
}

/* Direct contributions of every source sample as shadow requests (Radiance's direct() with
 * every sample tested: -dt 0 behaviour). */
static void rc_direct(const rc_scene_args* S, rc_out* o, const rc_ward_iso* m, const rc_ray* r,
                      float3 p, float3 n, float3 d, int flat, float3 coef, rc_rng_key key) {
  const rc_params* P = &S->params;
  float eps = P->spec.z;
  uint dim = 64;
  for (uint s = 0; s < P->nsources; ++s) {
    global const rc_source* src = S->sources + s;
    /* Radiance subdivides less for rays that matter less: -ds scales with 1/weight. */
    uint cells = rc_source_cells(src, p, P->direct.x / fmax(r->coef.w, 1e-6f));
    for (uint k = 0; k < cells; ++k, dim += 2) {
      float2 xi = (float2)(rc_random(key, dim), rc_random(key, dim + 1));
      float3 l;
      float dist, omega;
      if (!rc_source_sample(src, S->verts, p, n, k, cells, P->direct.y, xi, &l, &dist, &omega))
        continue;
      float3 ls = rc_source_radiance(src, l, dist);
      if (rc_max3(ls) <= 0.0f) continue;
      float3 c = rc_ward_iso_direct(m, ls, l, omega, n, d, flat) * coef;
      if (rc_max3(c) <= 0.0f) continue;
      rc_emit_shadow(o, p, l, eps, dist, c, r->primary, s);
    }
  }
}

/* plastic, metal and the irradiance meter. */
static void rc_shade_normal(const rc_scene_args* S, rc_out* o, const rc_material* mat,
                            const rc_ray* r, const rc_hit* h, float3 n, int flat,
                            rc_rng_key key) {
  const rc_params* P = &S->params;
  global const float* a = S->args + mat->args;
  float3 d = r->dir.xyz;
  float3 p = h->pos.xyz;
  float cos1 = -dot(d, n);
  float3 color = (float3)(a[0], a[1], a[2]);
  rc_ward_iso m;
#ifdef RADCL_HAS_METAL
  if (mat->type == RC_OBJ_METAL)
    m = rc_metal_setup(color, a[3], a[4], cos1);
  else
#endif
    m = rc_plastic_setup(color, a[3], a[4], cos1);
  float3 coef = r->coef.xyz;

  rc_direct(S, o, &m, r, p, n, d, flat, coef, key);

  /* Ambient: the diffuse part, plus rough specular too weak to sample (Radiance folds it into
   * the ambient coefficient). */
  float3 acoef = m.diffuse;
  int rough = m.alpha2 > RC_PURE_SPECULAR_ALPHA2;
  if (rough && rc_max3(m.specular) <= P->spec.y) acoef += m.specular;
  rc_ambient(o, r, p, n, acoef, P, key);

  float eps = P->spec.z;
  if (!rough) {
    if (rc_max3(m.specular) > RC_FTINY)
      rc_spawn(o, r, p, d + 2.0f * cos1 * n, m.specular, RC_RAY_REFLECTED, eps, P, key, 8,
               r->ambient_depth);
  } else if (rc_max3(m.specular) > P->spec.y) {
    /* Importance-sample the Gaussian lobe (scene-format.md §3.1 step 8), up to 10 tries. */
    float3 u = normalize(fabs(n.x) < 0.6f ? cross((float3)(1, 0, 0), n)
                                         : cross((float3)(0, 1, 0), n));
    float3 v = cross(n, u);
    float alpha = sqrt(m.alpha2);
    for (uint t = 0; t < 10; ++t) {
      float u1 = rc_random(key, 10 + 2 * t), u2 = rc_random(key, 11 + 2 * t);
      if (P->spec.x < 1.0f) u2 = 1.0f - P->spec.x * u2; /* -ss < 1: partial jitter */
      float phi = 2.0f * M_PI_F * u1;
      float tand = alpha * sqrt(-log(fmax(u2, 1e-30f)));
      float3 hv = n + tand * (cos(phi) * u + sin(phi) * v);
      float3 dir = d - 2.0f * dot(hv, d) / (1.0f + tand * tand) * hv;
      if (dot(dir, n) <= 0.0f) continue;
      rc_spawn(o, r, p, normalize(dir), m.specular, RC_RAY_SPECULAR, eps, P, key, 9,
               r->ambient_depth);
      break;
    }
  }
}

static void rc_shade_ray(const rc_scene_args* S, rc_out* o, rc_ray r, rc_hit h) {
  const rc_params* P = &S->params;
  uint kind = r.flags & RC_RAY_KIND_MASK;
  rc_rng_key key = rc_make_key(r.primary, r.sample, r.depth, P->seed);
  float3 coef = r.coef.xyz;
  if (h.surface == RC_NONE) return; /* nothing hit: black */

  if (h.surface == RC_SURF_IRRADIANCE) { /* -I measurement point */
    rc_material m = S->materials[P->irradiance_material];
    rc_shade_normal(S, o, &m, &r, &h, h.nrm.xyz, 0, key);
    return;
  }
  rc_surface surf = S->surfaces[h.surface];
  if (surf.material == RC_NONE) return;
  rc_material mat = S->materials[surf.material];

  /* illum: a source for shadow rays aimed at it, otherwise its alternate material (or
   * nothing: the ray passes through). */
  if (mat.type == RC_OBJ_ILLUM) {
    if (mat.alt == RC_NONE) {
      if (h.pos.w >= 0.0f)
        rc_spawn(o, &r, h.pos.xyz, r.dir.xyz, (float3)(1.0f), kind, P->spec.z, P, key, 7,
                 r.ambient_depth);
      return;
    }
    mat = S->materials[mat.alt];
  }
  if (mat.type == RC_OBJ_LIGHT || mat.type == RC_OBJ_GLOW || mat.type == RC_OBJ_SPOTLIGHT ||
      mat.type == RC_OBJ_ILLUM) {
    o->immediate += rc_light_emission(S, &mat, &r, &h, kind) * coef;
    return;
  }
  if (h.pos.w < 0.0f) return; /* a distant source with a non-emitting material */

  float3 n = h.nrm.xyz;
  if (!h.front) {
    if (!(P->flags & RC_PF_BV)) { /* back faces invisible: continue through */
      rc_spawn(o, &r, h.pos.xyz, r.dir.xyz, (float3)(1.0f), kind, P->spec.z, P, key, 7,
                 r.ambient_depth);
      return;
    }
    n = -n;
  }
  int flat = surf.type == RC_OBJ_POLYGON || surf.type == RC_OBJ_RING;

  /* -i: primary rays (and their pure transmissions) meet diffuse irradiance meters. */
  if ((P->flags & RC_PF_IRRAD_I) && (kind == RC_RAY_PRIMARY || kind == RC_RAY_TRANSMITTED) &&
      r.depth == 0) {
    rc_material m = S->materials[P->irradiance_material];
    rc_shade_normal(S, o, &m, &r, &h, n, flat, key);
    return;
  }

  switch (mat.type) {
  case RC_OBJ_PLASTIC:
  case RC_OBJ_METAL:
    rc_shade_normal(S, o, &mat, &r, &h, n, flat, key);
    break;
#ifdef RADCL_HAS_MIRROR
  case RC_OBJ_MIRROR: {
    if (!h.front) break; /* the back of a mirror is black */
    global const float* a = S->args + mat.args;
    float3 c = (float3)(a[0], a[1], a[2]);
    float cos1 = -dot(r.dir.xyz, n);
    rc_spawn(o, &r, h.pos.xyz, r.dir.xyz + 2.0f * cos1 * n, c, RC_RAY_REFLECTED, P->spec.z, P,
             key, 8, r.ambient_depth);
    break;
  }
#endif
  default:
    break;
  }
}

#define RC_SCENE_PARAMS                                                                        \
  global const rc_surface *surfaces, global const rc_material *materials,                      \
      global const float *args, global const rc_source *sources, global const float4 *verts,   \
      global const rc_params *params

#define RC_SCENE_INIT                                                                          \
  rc_scene_args S;                                                                             \
  S.surfaces = surfaces;                                                                       \
  S.materials = materials;                                                                     \
  S.args = args;                                                                               \
  S.sources = sources;                                                                         \
  S.verts = verts;                                                                             \
  S.params = *params;

kernel void rc_count(global const rc_ray* rays, global const rc_hit* hits, uint n,
                     RC_SCENE_PARAMS, global uint* nshadow, global uint* nspawn) {
  uint i = get_global_id(0);
  if (i >= n) return;
  RC_SCENE_INIT
  rc_out o;
  o.write = 0;
  o.nshadow = o.nspawn = 0;
  o.immediate = (float3)(0.0f);
  rc_shade_ray(&S, &o, rays[i], hits[i]);
  nshadow[i] = o.nshadow;
  nspawn[i] = o.nspawn;
}

kernel void rc_shade(global const rc_ray* rays, global const rc_hit* hits, uint n,
                     RC_SCENE_PARAMS, global const uint* shadow_offset,
                     global const uint* spawn_offset, global rc_shadow* shadows,
                     global rc_ray* spawned, global float4* immediate) {
  uint i = get_global_id(0);
  if (i >= n) return;
  RC_SCENE_INIT
  rc_out o;
  o.write = 1;
  o.nshadow = o.nspawn = 0;
  o.shadows = shadows + shadow_offset[i];
  o.spawned = spawned + spawn_offset[i];
  o.immediate = (float3)(0.0f);
  rc_shade_ray(&S, &o, rays[i], hits[i]);
  immediate[i] = (float4)(o.immediate, 0.0f);
}

/* Per ray of the wave: its immediate contribution plus its unblocked shadow contributions, in
 * a fixed order. */
kernel void rc_accumulate(global const float4* immediate, global const uint* shadow_offset,
                          global const rc_shadow* shadows, global const uchar* blocked, uint n,
                          uint nshadows, global float4* total) {
  uint i = get_global_id(0);
  if (i >= n) return;
  uint end = i + 1 < n ? shadow_offset[i + 1] : nshadows;
  float3 sum = immediate[i].xyz;
  for (uint k = shadow_offset[i]; k < end; ++k)
    if (!blocked[k]) sum += shadows[k].contrib.xyz;
  total[i] = (float4)(sum, 0.0f);
}
