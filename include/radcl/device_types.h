/* Plain-C types shared by the host (C++) and the OpenCL kernels. This is the one definition:
 * the host includes it directly, the device program gets it through the embedded sources.
 * Layout rules: only 4-byte scalars and 16-byte rc_float4 members, every struct a multiple of
 * 16 bytes, no float3 (its size differs between C and OpenCL C). tests/device/layout checks
 * every size and offset listed in RADCL_LAYOUT_FIELDS against what a kernel reports. */
#ifndef RADCL_DEVICE_TYPES_H
#define RADCL_DEVICE_TYPES_H

#ifdef __OPENCL_C_VERSION__
typedef uint rc_u32;
typedef int rc_i32;
typedef ulong rc_u64;
typedef float4 rc_float4;
#else
#include <stdint.h>
typedef uint32_t rc_u32;
typedef int32_t rc_i32;
typedef uint64_t rc_u64;
typedef struct rc_float4 {
  float x, y, z, w;
} __attribute__((aligned(16))) rc_float4;
#endif

/* Radiance's primitive types, in the order of Radiance 5.4a's type table (the frozen-octree
 * table lists them by name; readers map names, never rely on these numbers in files). */
#define RADCL_OBJECT_TYPES(X)                                                                      \
  X(POLYGON, "polygon")                                                                            \
  X(CONE, "cone") X(SPHERE, "sphere") X(TEXFUNC, "texfunc") X(RING, "ring") X(                     \
      CYLINDER, "cylinder") X(INSTANCE, "instance") X(CUP, "cup") X(BUBBLE, "bubble")              \
      X(TUBE, "tube") X(MESH, "mesh") X(ALIAS, "alias") X(PLASTIC, "plastic") X(METAL, "metal") X( \
          GLASS, "glass") X(TRANS, "trans") X(DIELECTRIC, "dielectric") X(PLASTIC2, "plastic2")    \
          X(METAL2, "metal2") X(TRANS2, "trans2") X(INTERFACE, "interface")                        \
              X(PLASFUNC, "plasfunc") X(METFUNC, "metfunc") X(BRIGHTFUNC, "brightfunc") X(         \
                  BRIGHTDATA, "brightdata") X(BRIGHTTEXT, "brighttext") X(COLORPICT, "colorpict")  \
                  X(GLOW, "glow") X(SOURCE, "source") X(LIGHT, "light") X(ILLUM, "illum")          \
                      X(SPOTLIGHT, "spotlight") X(MIST, "mist") X(MIRROR, "mirror")                \
                          X(TRANSFUNC, "transfunc") X(BRTDFUNC, "BRTDfunc") X(BSDF, "BSDF")        \
                              X(ABSDF, "aBSDF") X(PLASDATA, "plasdata") X(METDATA, "metdata")      \
                                  X(TRANSDATA, "transdata") X(COLORFUNC, "colorfunc")              \
                                      X(ANTIMATTER, "antimatter")                                  \
                                          X(COLORDATA, "colordata") X(COLORTEXT, "colortext")      \
                                              X(TEXDATA, "texdata") X(MIXFUNC, "mixfunc")          \
                                                  X(MIXDATA, "mixdata") X(MIXTEXT, "mixtext")      \
                                                      X(MIXPICT, "mixpict") X(PRISM1, "prism1")    \
                                                          X(PRISM2, "prism2") X(ASHIK2, "ashik2")

#define RADCL_ENUM_ENTRY(id, name) RC_OBJ_##id,
enum rc_object_type { RADCL_OBJECT_TYPES(RADCL_ENUM_ENTRY) RC_OBJ_COUNT };
#undef RADCL_ENUM_ENTRY

/* One ray of a wave. org.w = tmin, dir.w = tmax; coef.xyz is the accumulated coefficient
 * (product of material coefficients down the tree), coef.w the scalar ray weight that -lw cuts. */
typedef struct rc_ray {
  rc_float4 org;
  rc_float4 dir;
  rc_float4 coef;
  rc_u32 primary; /* index of the primary ray this contribution belongs to */
  rc_u32 depth;   /* reflection depth (Radiance's r->rlvl) */
  rc_u32 flags;   /* RC_RAY_* kind bits */
  rc_u32 sample;  /* sample index within its parent, keys the random numbers */
} rc_ray;

/* The host's answer for one ray of a wave (from Embree). */
typedef struct rc_hit {
  rc_float4 ng;  /* geometric normal (unnormalised), w = hit distance t, <0 for a miss */
  rc_float4 uvw; /* x,y barycentric/surface parameters, z,w unused */
  rc_u32 object; /* surface object index in the compiled scene, or ~0u for a miss */
  rc_u32 prim;   /* primitive within the object (triangle of a polygon/mesh) */
  rc_u32 inst;   /* instance index, or ~0u */
  rc_u32 pad;
} rc_hit;

/* A shadow-ray request and the contribution it adds to its primary ray if unoccluded. */
typedef struct rc_shadow {
  rc_float4 org;     /* w = tmin */
  rc_float4 dir;     /* w = distance to the source sample (tmax) */
  rc_float4 contrib; /* rgb to add, w unused */
  rc_u32 primary;
  rc_u32 source; /* light-source index: the ray must hit this source (or nothing, for distant) */
  rc_u32 pad0;
  rc_u32 pad1;
} rc_shadow;

/* Counter-based random-number key: (primary ray, sample, depth, seed). */
typedef struct rc_rng_key {
  rc_u32 primary;
  rc_u32 sample;
  rc_u32 depth;
  rc_u32 seed;
} rc_rng_key;

/* Every struct above with every field, for the host/device layout test (rc_float4's members
 * are vector components on the device, which have no address: only its size is compared). */
#define RADCL_LAYOUT_STRUCTS(S) S(rc_float4) S(rc_ray) S(rc_hit) S(rc_shadow) S(rc_rng_key)
#define RADCL_LAYOUT_FIELDS(F)                                                                     \
  F(rc_ray, org)                                                                                   \
  F(rc_ray, dir) F(rc_ray, coef) F(rc_ray, primary) F(rc_ray, depth) F(rc_ray, flags)              \
      F(rc_ray, sample) F(rc_hit, ng) F(rc_hit, uvw) F(rc_hit, object) F(rc_hit, prim)             \
          F(rc_hit, inst) F(rc_hit, pad) F(rc_shadow, org) F(rc_shadow, dir) F(rc_shadow, contrib) \
              F(rc_shadow, primary) F(rc_shadow, source) F(rc_shadow, pad0) F(rc_shadow, pad1)     \
                  F(rc_rng_key, primary) F(rc_rng_key, sample) F(rc_rng_key, depth)                \
                      F(rc_rng_key, seed)

#endif /* RADCL_DEVICE_TYPES_H */
