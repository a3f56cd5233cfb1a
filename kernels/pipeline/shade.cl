/* The shading wave: one work-item per ray of the wave, with its host-computed hit. rc_shade
 * writes each hit's shadow requests and spawned rays into fixed slots per ray (the host packs
 * them in ray order); the few hits that need more room than their slots are shaded again with
 * exact offsets. Its count mode runs the same code and only counts (the -as super-sample pass
 * sizes its output with it). Records depend only on the ray, never on where they are written, so
 * results are bit-identical across runs, thread counts, wave sizes and slot sizes.
 * Its parts: hit_output.cl (where a hit writes), hemisphere.cl (indirect samples),
 * direct.cl (source samples), shade_material.cl (materials), shadow_step.cl (shadow rays
 * through transmitting surfaces), this file (the ray's dispatch and the kernels). */
#include "radcl/device_types.h"
#include "radcl/luminance.h"
#include "radcl/rng.h"
#include "lights/sources.cl"
#include "lights/virtual.cl"

/* The scene's material modules, after the shared types they use. */
#include "generated.cl"

#define RC_FTINY 1e-6f
/* Radiance's r->crtype: the ambient/specular nature of any ancestor survives pure
 * transmission (a sky seen through glass by an ambient ray is still not counted twice). Kept
 * in rc_ray.flags above the kind. */
#define RC_CR_AMBIENT 8u
#define RC_CR_SPECULAR 16u
static inline uint rc_crtype(uint flags) {
  uint kind = flags & RC_RAY_KIND_MASK;
  return (flags & ~RC_RAY_KIND_MASK) | (kind == RC_RAY_AMBIENT ? RC_CR_AMBIENT : 0u) |
         (kind == RC_RAY_SPECULAR ? RC_CR_SPECULAR : 0u);
}
/* The extinction (per unit length) of the medium a ray travels in; zero means none. */
static inline float3 rc_ray_medium(const rc_ray* r) {
  return (float3)(r->cext_r, r->cext_g, r->cext_b);
}
/* Transmittance over a path of length t (t < 0: to infinity), as Radiance's
 * rayparticipate() without scattering. */
static inline float rc_ext1(float c, float t) {
  if (c <= 0.0f) return 1.0f;
  float e = t < 0.0f ? INFINITY : c * t;
  return e <= RC_FTINY ? 1.0f : (e > 92.0f ? 0.0f : exp(-e));
}
static inline float3 rc_ext(float3 c, float t) {
  return (float3)(rc_ext1(c.x, t), rc_ext1(c.y, t), rc_ext1(c.z, t));
}
/* Radiance's perceptual brightness weights (CIE Y of its RGB primaries). */
/* Random numbers for sampling decisions: with -u- (RC_PF_LOWDISC) first-hit samples follow a
 * low-discrepancy sequence over the primary ids, as Radiance's -u- does; deeper ones and -u+
 * use independent numbers. */
static inline float rc_sample(const rc_params* P, rc_rng_key key, uint dim) {
  return ((P->flags & RC_PF_LOWDISC) && key.depth == 0u) ? rc_random_ld(key, dim)
                                                         : rc_random(key, dim);
}

/* rc_sample for dimensions dim and dim + 1 (dim even), one block of the generator for both. */
static inline float2 rc_sample2(const rc_params* P, rc_rng_key key, uint dim) {
  float a, b;
  if ((P->flags & RC_PF_LOWDISC) && key.depth == 0u)
    rc_random_ld_pair(key, dim, &a, &b);
  else
    rc_random_pair(key, dim, &a, &b);
  return (float2)(a, b);
}

static inline float rc_max3(float3 c) {
  return fmax(c.x, fmax(c.y, c.z));
}

typedef struct rc_scene_args {
  global const rc_surface* surfaces;
  global const rc_material* materials;
  global const float* args;
  global const rc_source* sources;
  global const float4* verts;
  global const rc_mirror* mirrors;
  global const rc_pattern* patterns;
  global const rc_amb_record* amb_records;
  global const rc_amb_node* amb_nodes;
  global const uint* amb_blocked; /* per-hit lists of records whose leak test failed */
  rc_params params;               /* a private copy: read on every sample */
} rc_scene_args;

/* The scattering albedo of a ray's medium from where it comes (rc_ray.medium). */
static inline float3 rc_medium_albedo(const rc_scene_args* S, uint medium) {
#ifdef RADCL_HAS_MEDIUM
  if (medium == RC_MEDIUM_GLOBAL) return S->params.albedo.xyz;
  if (medium == RC_MEDIUM_CLEAR) return (float3)(0.0f);
  global const float* a = S->args + medium;
  return (float3)(a[0], a[1], a[2]);
#else
  return (float3)(0.0f);
#endif
}
/* What a shadow ray in medium (cext, medium) loses per unit length: what is absorbed; the
 * scattered part is not counted as lost on the way to a source (Radiance's rayparticipate). */
static inline float3 rc_shadow_ext(const rc_scene_args* S, float3 cext, uint medium) {
#ifdef RADCL_HAS_MEDIUM
  return cext * ((float3)(1.0f) - rc_medium_albedo(S, medium));
#else
  return cext;
#endif
}

#ifdef RADCL_HAS_AMBCACHE
#include "ambient/ambient_cache.cl"
#endif

#ifdef RADCL_HAS_PATTERNS
#include "patterns/patterns.cl"
#endif

/* In this order: each part uses the ones before it. */
#include "pipeline/hit_output.cl"

#include "pipeline/hemisphere.cl"

#include "materials/shade_material.cl"

/* r->pert once a ray is shaded with material m at h (Radiance's, which rtrace's -on shows):
 * the hit's own (a smoothed mesh's), plus the patterns of the material rc_shade_material
 * shades it with (a mirror's or illum's alternate where it stands in). World space, in h's
 * frame (before any flip of the material's own). */
static float3 rc_material_pert(const rc_scene_args* S, rc_material m, float3 d, const rc_hit* h) {
  float3 pcol = (float3)(1.0f), pert = h->pert.xyz;
#ifdef RADCL_HAS_MIRROR
  if (m.type == RC_OBJ_MIRROR && m.alt != RC_NONE) { /* a primary sees the alternate */
    if (m.alt == RC_ALT_VOID) return pert;
    m = S->materials[m.alt];
  }
#endif
  if (m.type == RC_OBJ_ILLUM && m.alt != RC_NONE) m = S->materials[m.alt];
#ifdef RADCL_HAS_PATTERNS
  if (m.npatterns) rc_apply_patterns(S, &m, d, h, &pcol, &pert);
#endif
  return pert;
}

#ifdef RADCL_HAS_MIXFUNC
#include "patterns/mixture.cl"
#endif

static void rc_shade_ray(const rc_scene_args* S, rc_out* o, rc_ray r, rc_hit h) {
  const rc_params* P = &S->params;
  rc_rng_key key = rc_make_key(r.primary, r.sample, r.depth, P->seed);
  o->cext = rc_ray_medium(&r);
  o->newclip = r.clip;
#ifdef RADCL_HAS_MEDIUM
  o->medium = r.medium;
  o->albedo = rc_medium_albedo(S, r.medium);
  o->gecc = r.gecc;
  o->slights = r.slights;
  o->av = P->av.xyz;
  if (h.surface == RC_NONE) { /* nothing hit: what the medium scatters into the ray */
    rc_apply_medium(S, o, &r, o->cext, -1.0f, key);
    return;
  }
#endif
  if (h.surface == RC_NONE) return; /* nothing hit: black */
  /* Patterns read T from the hit (patterns.cl); children start where this ray ends. */
  h.uv.z = r.dist0;
  h.uv.w = 0.0f;
  o->dist = r.dist0 + fmax(h.pos.w, 0.0f);
  o->ng = h.surface == RC_SURF_IRRADIANCE ? (float3)(0.0f) : h.nrm.xyz; /* a meter: no surface */
  /* A smoothed mesh's own tilt (Radiance's o_mesh sets r->pert); patterns add theirs. */
  o->pert = h.pert.xyz;
  /* The host writes a hit's list of leaking records into nrm.w's bits (1 + its offset). */
  uint leaks = as_uint(h.nrm.w);
  if (leaks != 0u) o->blocked = S->amb_blocked + (leaks - 1u);

  if (h.surface == RC_SURF_IRRADIANCE) { /* -I measurement point */
    rc_material m = S->materials[P->irradiance_material];
    rc_shade_normal(S, o, &m, &r, &h, h.nrm.xyz, 0, key);
    return;
  }
  rc_surface surf = S->surfaces[h.surface];
  int invisible = surf.material == RC_NONE; /* void modifier: Radiance does not see it */
#ifdef RADCL_HAS_ANTIMATTER
  o->slots = surf.slots;
  o->side = h.front ? 1 : -1;
  invisible |= (surf.clip & r.clip) != 0u; /* clipped by an antimatter the ray is inside */
#endif
  if (invisible) {
    rc_apply_medium(S, o, &r, o->cext, h.pos.w, key);
    if (h.pos.w >= 0.0f) rc_pass(o, &r, &h, P, key);
    return;
  }
  rc_material mat = S->materials[surf.material];
#ifdef RADCL_HAS_ANTIMATTER
  if (mat.type == RC_OBJ_ANTIMATTER) {
    global const float* a = S->args + mat.args;
    o->newclip = rc_antimatter_clip(a, r.clip, h.front);
    if (h.pos.w < 0.0f) return;
    if (!rc_antimatter_shades(&mat, a, r.inside)) {
      rc_apply_medium(S, o, &r, o->cext, h.pos.w, key);
      rc_pass(o, &r, &h, P, key);
      return;
    }
    /* Leaving the removed part of a clipped object: the boundary is mod1's, facing the ray. */
    mat = S->materials[mat.alt];
    h.nrm = -h.nrm;
    h.pert = -h.pert; /* Radiance's flipsurface turns the perturbation too */
    o->pert = -o->pert;
    h.front = !h.front;
  }
#endif

#ifdef RADCL_HAS_MIXFUNC
  if (mat.type == RC_OBJ_MIXFUNC) {
    rc_shade_mixture(S, o, r, h, &mat, &surf, key);
    return;
  }
#endif
  rc_shade_material(S, o, r, h, mat, &surf, key);
}

#define RC_SCENE_PARAMS                                                                            \
  global const rc_surface *surfaces, global const rc_material *materials,                          \
      global const float *args, global const rc_source *sources, global const float4 *verts,       \
      global const rc_mirror *mirrors, global const rc_params *params,                             \
      global const rc_pattern *patterns, global const rc_amb_record *amb_records,                  \
      global const rc_amb_node *amb_nodes, global const uint *amb_blocked

#define RC_SCENE_INIT                                                                              \
  rc_scene_args S;                                                                                 \
  S.surfaces = surfaces;                                                                           \
  S.materials = materials;                                                                         \
  S.args = args;                                                                                   \
  S.sources = sources;                                                                             \
  S.verts = verts;                                                                                 \
  S.mirrors = mirrors;                                                                             \
  S.patterns = patterns;                                                                           \
  S.amb_records = amb_records;                                                                     \
  S.amb_nodes = amb_nodes;                                                                         \
  S.amb_blocked = amb_blocked;                                                                     \
  S.params = *params;

#ifdef RADCL_CONTRIB
#include "pipeline/contrib.cl"
#endif

/* Writes each ray's records from its offsets. Exact mode (caps of ~0u): the offsets come from
 * a count. Slot mode: every ray has room for cap_shadow and cap_spawn records; the counts
 * are written for every ray, with the top bit of nshadow set where the records did not fit.
 * Count mode (caps of 0): only the counts are written, nothing else (a wave's slot sizes, the
 * -as pass's exact room). One kernel does all three, so its code is compiled once. Slot mode
 * also writes cells[i]: whether ray i marked hemisphere samples for the -as tally (even where
 * its records did not fit). With retally, ray i's tally is tallies[i] (the device's copy of a
 * generation has the tallies its kernel gave; the host's -as tally has changed some since), so
 * its children carry the right one. */
kernel void rc_shade(global const rc_ray* rays, global const rc_hit* hits, uint n, RC_SCENE_PARAMS,
                     global const uint* shadow_offset, global const uint* spawn_offset,
                     global rc_shadow* shadows, global rc_ray* spawned, global float4* immediate,
                     uint super_mode, global const uint* super_offset,
                     global const uint* super_data, uint cap_shadow, uint cap_spawn,
                     global uint* nshadow, global uint* nspawn, global uchar* cells, uint retally,
                     global const uint* tallies) {
  uint i = get_global_id(0);
  if (i >= n) return;
  RC_SCENE_INIT
  const int counting = cap_shadow == 0u && cap_spawn == 0u;
  const int slots = !counting && cap_shadow != 0xFFFFFFFFu;
  rc_out o;
  rc_out_init(&o, !counting);
  if (super_mode) o.super = super_data + super_offset[i];
  if (!counting) {
    o.cap_shadow = cap_shadow;
    o.cap_spawn = cap_spawn;
    o.shadows = shadows + (slots ? (ulong)i * cap_shadow : shadow_offset[i]);
    o.spawned = spawned + (slots ? (ulong)i * cap_spawn : spawn_offset[i]);
  }
  rc_ray ray = rays[i];
  if (retally) ray.tally = tallies[i];
  rc_shade_ray(&S, &o, ray, hits[i]);
  if (counting) {
    nshadow[i] = o.nshadow;
    nspawn[i] = o.nspawn;
    return;
  }
#ifdef RADCL_CONTRIB
  immediate[i] = rc_contrib_hit(&S, &ray, hits[i]);
#else
  immediate[i] = (float4)(o.immediate, 0.0f);
#endif
  if (slots) {
    nshadow[i] = o.nshadow | (o.write ? 0u : 0x80000000u);
    nspawn[i] = o.nspawn;
    cells[i] = (uchar)o.cells;
  }
}

/* rtrace's -on: per primary ray i, the perturbation r->pert of its first hit once shaded, as
 * rc_shade_ray leaves it (a mixture blends its leaves', as raymixture does), in the frame of
 * the hit's normal as the host gave it (an antimatter boundary's flip undone). */
kernel void rc_hit_pert(global const rc_ray* rays, global const rc_hit* hits, uint n,
                        RC_SCENE_PARAMS, global float4* pert) {
  uint i = get_global_id(0);
  if (i >= n) return;
  RC_SCENE_INIT
  rc_ray r = rays[i];
  rc_hit h = hits[i];
  h.uv.z = r.dist0; /* as rc_shade_ray gives the patterns */
  h.uv.w = 0.0f;
  float3 p = h.pert.xyz;
  if (h.surface != RC_NONE && h.surface != RC_SURF_IRRADIANCE &&
      S.surfaces[h.surface].material != RC_NONE) {
    rc_surface surf = S.surfaces[h.surface];
    rc_material mat = S.materials[surf.material];
    float flip = 1.0f;
    int shaded = 1;
#ifdef RADCL_HAS_ANTIMATTER
    shaded = (surf.clip & r.clip) == 0u;
    if (shaded && mat.type == RC_OBJ_ANTIMATTER) {
      shaded = rc_antimatter_shades(&mat, S.args + mat.args, r.inside);
      if (shaded) { /* mod1's material, the surface flipped */
        mat = S.materials[mat.alt];
        h.nrm = -h.nrm;
        h.pert = -h.pert;
        h.front = !h.front;
        flip = -1.0f;
      }
    }
#endif
    if (shaded) {
#ifdef RADCL_HAS_MIXFUNC
      if (mat.type == RC_OBJ_MIXFUNC)
        p = flip * rc_mix_pert(&S, &mat, r.dir.xyz, &h);
      else
#endif
        p = flip * rc_material_pert(&S, mat, r.dir.xyz, &h);
    }
  }
  pert[i] = (float4)(p, 0.0f);
}

/* Per ray of the wave: its immediate contribution plus its unblocked shadow contributions and
 * direct estimates, in a fixed order, read from the packed requests (traced ones carry their
 * contribution on arrival); blocked[k] comes from the host's shadow steps. */
kernel void rc_accumulate(global const float4* immediate, global const uint* shadow_offset,
                          global const rc_shadow* shadows, global const uchar* blocked, uint n,
                          uint nshadows, global float4* total) {
  uint i = get_global_id(0);
  if (i >= n) return;
  uint end = i + 1 < n ? shadow_offset[i + 1] : nshadows;
  float3 sum = immediate[i].xyz;
  for (uint k = shadow_offset[i]; k < end; ++k) {
    float3 c = shadows[k].contrib.xyz;
    if (shadows[k].source != RC_NONE) {
      if (!blocked[k]) sum += c;
      continue;
    }
    /* The estimate for untested samples (direct.cl), at the tested ones' hit ratio: its
     * slights_or_tested is the count of tested requests before it. */
    uint nt = shadows[k].slights_or_tested, hits = 0;
    for (uint j = k - nt; j < k; ++j)
      hits += !blocked[j];
    if (nt > 0u) sum += c * ((float)hits / (float)nt);
  }
  total[i] = (float4)(sum, 0.0f);
}

/* Each ray's records from its fixed slots into their packed places (offsets from the counts):
 * the shadow requests always (they stay on the device for their steps and the sums), the
 * children where the device is not the host's memory (only they cross to the host, not every
 * slot). Rays whose records did not fit (top bit of their count) are shaded again. */
kernel void rc_pack(global const rc_shadow* slot_shadows, global const rc_ray* slot_spawned,
                    global const uint* nshadow, global const uint* nspawn,
                    global const uint* shadow_offset, global const uint* spawn_offset, uint n,
                    uint cap_shadow, uint cap_spawn, uint with_shadows, uint with_spawn,
                    global rc_shadow* shadows, global rc_ray* spawned) {
  uint i = get_global_id(0);
  if (i >= n || (nshadow[i] & 0x80000000u)) return;
  if (with_shadows) {
    global const rc_shadow* from = slot_shadows + (ulong)i * cap_shadow;
    global rc_shadow* to = shadows + shadow_offset[i];
    for (uint k = 0; k < nshadow[i]; ++k)
      to[k] = from[k];
  }
  if (with_spawn) {
    global const rc_ray* from = slot_spawned + (ulong)i * cap_spawn;
    global rc_ray* to = spawned + spawn_offset[i];
    for (uint k = 0; k < nspawn[i]; ++k)
      to[k] = from[k];
  }
}

/* What the host needs of a shadow request to trace it: its origin (w: tmin) and direction, w
 * its reach: the distance to a local source sample, INFINITY for a distant source (or one
 * already bent), -1 for a -dt estimate record, which is no ray. */
static void rc_shadow_view_of(const rc_shadow* s, global const rc_source* sources,
                              global float4* view) {
  float w = -1.0f;
  if (s->source != RC_NONE)
    w = sources[s->source].kind == RC_SRC_DISTANT || !isfinite(s->dir.w) ? INFINITY : s->dir.w;
  view[0] = s->org;
  view[1] = (float4)(s->dir.xyz, w);
}

kernel void rc_shadow_view(global const rc_shadow* shadows, uint n, global const rc_source* sources,
                           global float4* view) {
  uint i = get_global_id(0);
  if (i >= n) return;
  rc_shadow s = shadows[i];
  rc_shadow_view_of(&s, sources, view + 2 * (ulong)i);
}

/* The same for a count the device holds: totals[0] (rc_offsets). */
kernel void rc_shadow_view_counted(global const rc_shadow* shadows, global const uint* totals,
                                   global const rc_source* sources, global float4* view) {
  uint i = get_global_id(0);
  if (i >= totals[0]) return;
  rc_shadow s = shadows[i];
  rc_shadow_view_of(&s, sources, view + 2 * (ulong)i);
}

/* The packed places of a small wave's records, for rc_pack without a trip through the host: the
 * exclusive prefix sums of the counts by one work-group of RC_OFFSETS_GROUP items, each a run of
 * rays, and the totals (totals[0] shadow requests, totals[1] children). A ray whose records did
 * not fit (top bit of its shadow count) takes no room here: rc_pack skips it, and the host then
 * places the wave's records itself. */
#define RC_OFFSETS_GROUP 256
kernel void rc_offsets(global const uint* nshadow, global const uint* nspawn, uint n,
                       global uint* shadow_offset, global uint* spawn_offset, global uint* totals) {
  local uint sh[RC_OFFSETS_GROUP], sp[RC_OFFSETS_GROUP];
  uint t = get_local_id(0), per = (n + RC_OFFSETS_GROUP - 1) / RC_OFFSETS_GROUP;
  uint a = min(n, t * per), b = min(n, a + per), ssh = 0, ssp = 0;
  for (uint i = a; i < b; ++i)
    if (!(nshadow[i] & 0x80000000u)) {
      ssh += nshadow[i];
      ssp += nspawn[i];
    }
  sh[t] = ssh;
  sp[t] = ssp;
  barrier(CLK_LOCAL_MEM_FENCE);
  if (t == 0) {
    uint x = 0, y = 0;
    for (uint k = 0; k < RC_OFFSETS_GROUP; ++k) {
      uint u = sh[k], v = sp[k];
      sh[k] = x;
      sp[k] = y;
      x += u;
      y += v;
    }
    totals[0] = x;
    totals[1] = y;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  ssh = sh[t];
  ssp = sp[t];
  for (uint i = a; i < b; ++i) {
    shadow_offset[i] = ssh;
    spawn_offset[i] = ssp;
    if (!(nshadow[i] & 0x80000000u)) {
      ssh += nshadow[i];
      ssp += nspawn[i];
    }
  }
}

#include "pipeline/shadow_step.cl"
