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
/* Large functions called from several places (shading, patterns, generated .cal code) stay
 * calls: a compiler that inlines everything, as NVIDIA's does, builds a copy per call site, and
 * a scene's first build took twice as long (docs/internals.md). -DRADCL_INLINE_ALL undoes it. */
#ifdef RADCL_INLINE_ALL
#define RC_NOINLINE
#else
#define RC_NOINLINE __attribute__((noinline))
#endif
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
  X(CONE, "cone")                                                                                  \
  X(SPHERE, "sphere")                                                                              \
  X(TEXFUNC, "texfunc")                                                                            \
  X(RING, "ring") X(CYLINDER, "cylinder") X(INSTANCE, "instance") X(CUP, "cup") X(                 \
      BUBBLE, "bubble") X(TUBE, "tube") X(MESH, "mesh") X(ALIAS, "alias") X(PLASTIC, "plastic")    \
      X(METAL, "metal") X(GLASS, "glass") X(TRANS, "trans") X(DIELECTRIC, "dielectric") X(         \
          PLASTIC2, "plastic2") X(METAL2, "metal2") X(TRANS2, "trans2") X(INTERFACE, "interface")  \
          X(PLASFUNC, "plasfunc") X(METFUNC, "metfunc") X(BRIGHTFUNC, "brightfunc")                \
              X(BRIGHTDATA, "brightdata") X(BRIGHTTEXT, "brighttext") X(COLORPICT, "colorpict")    \
                  X(GLOW, "glow") X(SOURCE, "source") X(LIGHT, "light") X(ILLUM, "illum")          \
                      X(SPOTLIGHT, "spotlight") X(MIST, "mist") X(MIRROR, "mirror")                \
                          X(TRANSFUNC, "transfunc") X(BRTDFUNC, "BRTDfunc") X(BSDF, "BSDF")        \
                              X(ABSDF, "aBSDF") X(PLASDATA, "plasdata") X(METDATA, "metdata")      \
                                  X(TRANSDATA, "transdata") X(COLORFUNC, "colorfunc")              \
                                      X(ANTIMATTER, "antimatter") X(COLORDATA, "colordata")        \
                                          X(COLORTEXT, "colortext") X(TEXDATA, "texdata")          \
                                              X(MIXFUNC, "mixfunc") X(MIXDATA, "mixdata")          \
                                                  X(MIXTEXT, "mixtext") X(MIXPICT, "mixpict")      \
                                                      X(PRISM1, "prism1") X(PRISM2, "prism2")      \
                                                          X(ASHIK2, "ashik2")

#define RADCL_ENUM_ENTRY(id, name) RC_OBJ_##id,
enum rc_object_type { RADCL_OBJECT_TYPES(RADCL_ENUM_ENTRY) RC_OBJ_COUNT };
#undef RADCL_ENUM_ENTRY

/* Coordinates on the device are relative to the scene's re-centring origin (its bounding-box
 * centre, see geometry::SceneGeometry::centre()), so float keeps its precision far from the
 * world origin. "~0u" marks "none" in index fields. */
#define RC_NONE 0xFFFFFFFFu
#define RC_ALT_VOID 0xFFFFFFFEu /* rc_material.alt of a mirror whose alternate is `void` */
/* rc_hit.surface of an -I measurement point: a diffuse irradiance meter facing rc_hit.nrm. */
#define RC_SURF_IRRADIANCE 0xFFFFFFFEu

/* Ray kinds (rc_ray.flags low bits), as Radiance's ray types. */
#define RC_RAY_PRIMARY 0u
#define RC_RAY_REFLECTED 1u   /* pure specular reflection */
#define RC_RAY_TRANSMITTED 2u /* pure specular transmission */
#define RC_RAY_SPECULAR 3u    /* sampled rough specular */
#define RC_RAY_AMBIENT 4u     /* indirect diffuse sample */
#define RC_RAY_AMBMISS                                                                             \
  5u /* not a ray: an irradiance-cache miss the host makes a record for                            \
        (org = point, dir = normal, coef.w = the hit ray's weight) */
#define RC_RAY_KIND_MASK 7u
/* Lineage bit: the ray descends from the primary hit's pure specular reflection, whose
 * contribution rtrace reports as "mirrored" (-o r, x, R, l). */
#define RC_RAY_MIRRORED 32u
/* Lineage bit: the ray continues the primary straight through transmitting surfaces (glass,
 * dielectric): rtrace's unmirrored length (-o X, l) adds these rays' lengths. */
#define RC_RAY_THROUGH 64u
/* Lineage bit: a reflection about a normal tilted by a texture (glass, dielectric): rtrace's
 * mirrored length (-o l, L) stops at the surface, as Radiance's rmt there. */
#define RC_RAY_TILTED 128u
/* A hemisphere sample of a record being made: its lineage counts as a primary's (the MIRRORED
 * and THROUGH bits of its children), so that its length is Radiance's raydistance(), the
 * effective length through glass or along a mirror. Not inherited. */
#define RC_RAY_ROOT 256u

/* rc_ray.org.w / rc_shadow.org.w of a ray whose origin was moved off the surface it leaves
 * (rc_leave): traced with no minimum distance, so that nothing near the point is skipped. */
#define RC_TMIN_OFF (-1.0f)

/* One ray of a wave. org.w = tmin, dir.w = tmax; coef.xyz is the accumulated coefficient
 * (product of material coefficients down the tree), coef.w the scalar ray weight that -lw cuts. */
typedef struct rc_ray {
  rc_float4 org;
  rc_float4 dir;
  rc_float4 coef;
  rc_u32 primary;               /* index of the primary ray this contribution belongs to */
  rc_u32 depth;                 /* reflection depth (Radiance's r->rlvl) */
  rc_u32 flags;                 /* RC_RAY_* kind */
  rc_u32 sample;                /* sample index within its parent, keys the random numbers */
  rc_u32 ambient_depth;         /* ambient bounces taken so far (Radiance's r->rlvl for -ab) */
  float cext_r, cext_g, cext_b; /* extinction per unit length of the medium it travels in */
  rc_u32 tally;   /* host tally its contributions add to (the primary's slot unless the host
                     splits the tree: hemisphere cells for -as, every ray in trace mode) */
  rc_u32 clip;    /* antimatter: bit set of the clipped modifiers the ray is inside */
  rc_u32 inside;  /* antimatter: four signed 8-bit crossing counts (one per antimatter with a
                     shading modifier) */
  rc_u32 cell;    /* a hemisphere sample the host may super-sample: RC_CELL_* bits, else 0 */
  float dist0;    /* length of the ray tree from the primary's start to this ray's origin (the
                     sum of its ancestors' segments): patterns see T = (dist0 + t) x S, as
                     Radiance's raydist() sums r->rot up the parent chain. 0 for a primary. */
  rc_u32 medium;  /* where the scattering albedo of its medium comes from: RC_MEDIUM_GLOBAL
                     (-ma), RC_MEDIUM_CLEAR (none: inside a dielectric), else the args offset of a
                     mist's albedo (rgb) */
  float gecc;     /* scattering eccentricity of its medium (-mg, or a mist's) */
  rc_u32 slights; /* mist: the listed sources that scatter into it, one bit per entry of the
                     scene's table (rc_params.mist) */
} rc_ray;

#define RC_MEDIUM_GLOBAL 0xFFFFFFFFu
#define RC_MEDIUM_CLEAR 0xFFFFFFFEu
/* A mist material's arguments as compiled: extinction (rgb, 0 without), albedo (rgb), g, the
 * count of real arguments given, and its source list as a bit set of rc_params.mist's table. */
#define RC_MIST_ALBEDO 3
#define RC_MIST_GECC 6
#define RC_MIST_NREALS 7
#define RC_MIST_MASK 8
#define RC_MIST_NARGS 9
/* Source-scattering samples per source and ray segment at most (Radiance's MAXSSAMP). */
#define RC_MIST_MAXSAMP 16

/* rc_ray.cell of the first samples of a hemisphere whose -as super-sampling the host decides
 * (Radiance's ambsupersamp): which of the ray's hemispheres, the super-sample budget and the
 * division index (row * ns + column). */
#define RC_CELL_FLAG 0x80000000u
#define RC_CELL_WHICH(c) (((c) >> 29) & 3u)
#define RC_CELL_BUDGET(c) (((c) >> 16) & 0x1FFFu)
#define RC_CELL_INDEX(c) ((c)&0xFFFFu)
#define RC_CELL_MAX_BUDGET 0x1FFFu

/* The host's answer for one ray of a wave (from Embree). */
typedef struct rc_hit {
  rc_float4 pos;  /* hit point (re-centred), w = distance t; t < 0 for a miss (then surface is
                     the distant source hit, if any) */
  rc_float4 nrm;  /* unit geometric normal in Radiance's orientation (not flipped); w: the bits
                     of the hit's list of cache records that failed the leak test (1 + its
                     offset in the leak lists, 0: none; the host's leak test writes it) */
  rc_float4 uv;   /* x,y: triangle barycentrics or surface parameters; z,w: 0 from the host, set
                     by the kernels from the ray before patterns see the hit: the ray's dist0,
                     and of it the shadow segments (rc_shadow.sdist0) */
  rc_float4 pert; /* xyz: the surface's own tilt of the normal (Radiance's r->pert from o_mesh:
                     a smoothed mesh triangle's interpolated unit normal less nrm), world, 0
                     elsewhere; the kernels start the textures' perturbation from it. w unused */
  rc_u32 surface; /* compiled surface; RC_NONE for a miss that hits no distant source */
  rc_u32 prim;    /* triangle within a polygon or mesh */
  rc_u32 source;  /* light-source index of the surface hit, else RC_NONE */
  rc_u32 front;   /* 1 if the ray arrived against the normal */
} rc_hit;

/* Surface flags. */
#define RC_SURFF_NO_AMBIENT                                                                        \
  1u /* -ae/-ai: its modifier is excluded (or not included), so its                                \
        hits take the ambient value -av instead of sampling */

/* A surface as the kernels see it. */
typedef struct rc_surface {
  rc_u32 material; /* index into the compiled materials, RC_NONE = void (invisible) */
  rc_u32 type;     /* rc_object_type of the surface */
  rc_u32 source;   /* light-source index when the surface is a direct source, else RC_NONE */
  rc_u32 object;   /* the surface's object number (names for output) */
  rc_u32 flags;    /* RC_SURFF_* */
  rc_u32 clip;     /* antimatter: the bit of its direct modifier in the rays' clip sets, 0 if no
                      antimatter lists it */
  rc_u32 slots;    /* antimatter: the rays' crossing counters (bit k: counter k) that a transmission
                      through this surface changes */
  rc_u32 pad2;
} rc_surface;

/* A material or other modifier; its real arguments live in a float buffer at [args, args+nargs). */
typedef struct rc_material {
  rc_u32 type; /* rc_object_type */
  rc_u32 args; /* offset into the argument buffer */
  rc_u32 nargs;
  rc_u32 alt;       /* alternate material of illum/mirror (illum: RC_NONE = none or void; mirror:
                       RC_NONE = none, RC_ALT_VOID = void), else RC_NONE */
  rc_u32 patterns;  /* first of its patterns/textures in the pattern buffer */
  rc_u32 npatterns; /* how many apply (those between the surface and it, then its own) */
  rc_u32 back;      /* mixfunc: background material (RC_NONE = void; alt is the foreground, and
                       `patterns` its coefficient's record); unused otherwise */
  rc_u32 func;      /* BRDF materials (plasfunc .. BRTDfunc): their function record in the
                       pattern buffer (render/compile/func_materials.h); unused otherwise */
} rc_material;

/* A pattern or texture (brightfunc, colorfunc, texfunc) or a mixture's coefficient (mixfunc):
 * generated .cal functions that the kernel's dispatcher rc_pattern_call() knows by number, its real
 * arguments (A1..An) and its world-to-function transform: 25 floats at `xform` in the argument
 * buffer (the 4x3 affine map from re-centred device coordinates, rows x y z then translation; the
 * scale S; the 3x3 function-to-world rotation for texture vectors; the world origin in function
 * coordinates). */
typedef struct rc_pattern {
  rc_u32 type;    /* rc_object_type */
  rc_u32 func[3]; /* dispatcher numbers: colour (r, g, b; brightfunc uses [0]), texture x y z */
  rc_u32 args;    /* its real arguments in the argument buffer */
  rc_u32 nargs;
  rc_u32 xform;  /* offset of its transform in the argument buffer */
  rc_u32 object; /* object number, for messages */
} rc_pattern;

/* Mixtures (mixfunc, mixdata, mixpict). One whose sides reach materials is a material of type
 * mixfunc (alt: foreground, back: background, patterns: its coefficient's record); one with only
 * patterns on its sides is a blend in a material's pattern list: its coefficient's record, the
 * foreground's patterns, a record of type RC_PATTERN_MIX_BACK, the background's, a record of
 * type RC_PATTERN_MIX_END. Either may nest RC_MIX_MAX_DEPTH deep (radcl's limit). */
#define RC_MIX_MAX_DEPTH 4
#define RC_PATTERN_MIX_BACK 0x100u
#define RC_PATTERN_MIX_END 0x101u

/* Light-source geometry kinds. */
#define RC_SRC_SPHERE 0u   /* sphere: pos = centre, pos.w = radius */
#define RC_SRC_FLAT 1u     /* polygon or ring: pos = centre, axis = normal */
#define RC_SRC_CYLINDER 2u /* cylinder: pos = centre, axis = unit axis, axis.w = length */
#define RC_SRC_DISTANT 3u  /* source: pos = unit direction, axis.w = solid angle */

/* Light-source flags. */
#define RC_SRCF_ILLUM 1u /* illum: seen as its alternate by non-shadow rays */
#define RC_SRCF_GLOW 2u  /* glow: lights only points within emit.w of it */
#define RC_SRCF_SPOT 4u  /* spotlight: spot.xyz direction, spot.w = cos(half angle) */
#define RC_SRCF_VIRTUAL                                                                            \
  8u /* image of source `parent` in mirror `mirror` (surface = the mirror's) */
#define RC_SRCF_FOLLOW                                                                             \
  16u /* virtual: a shadow ray must go on from the mirror to the parent (the                       \
         -dp pretest found the way partly blocked); otherwise meeting the                          \
         mirror is enough */

/* A light source for the direct calculation (Radiance's SRCREC). */
typedef struct rc_source {
  rc_float4 pos;    /* centre (re-centred) or direction (distant); w = radius */
  rc_float4 axis;   /* normal (flat) or axis (cylinder); w = area (flat), length (cylinder) or
                       solid angle (distant) */
  rc_float4 su;     /* flat: first in-plane half-extent vector of the sampling rectangle;
                       w = inner radius of a ring */
  rc_float4 sv;     /* flat: second in-plane half-extent vector */
  rc_float4 emit;   /* radiance (rgb) of the material; w = glow's maximum radius */
  rc_float4 spot;   /* spotlight direction (unit) and cos(half angle); w = -2 if not a spot */
  rc_u32 kind;      /* RC_SRC_* */
  rc_u32 flags;     /* RC_SRCF_* */
  rc_u32 surface;   /* compiled surface index (RC_NONE for distant sources) */
  rc_u32 verts;     /* polygon: offset of its vertices (float4) in the vertex buffer */
  rc_u32 nverts;    /* polygon: vertex count (0 for ring, sphere, cylinder, distant) */
  float spot_focus; /* spotlight: distance of the virtual focus behind the centre */
  rc_u32 parent;    /* virtual: the source it images (itself possibly virtual), else RC_NONE */
  rc_u32 mirror;    /* virtual: the mirror (rc_mirror index) it is seen in, else RC_NONE */
} rc_source;

/* A planar surface that relays light sources (Radiance's virtual sources, -dr): a mirror, or
 * one redirection of a prism1/prism2 (one entry per redirection). */
typedef struct rc_mirror {
  rc_float4 plane;  /* unit normal (the reflecting side) and offset: dot(plane.xyz, x) = w */
  rc_float4 centre; /* ring: centre, w = outer radius */
  rc_float4 refl;   /* mirror: reflectance (rgb); w = ring's inner radius */
  rc_u32 surface;   /* compiled surface */
  rc_u32 verts;     /* polygon: offset of its vertices in the vertex buffer */
  rc_u32 nverts;    /* polygon: vertex count; 0 for a ring */
  rc_u32 redirect;  /* 0: a mirror; k > 0: the prism's k-th redirection (either side relays) */
} rc_mirror;

/* A shadow-ray request and the contribution it adds to its primary ray if unoccluded. */
typedef struct rc_shadow {
  rc_float4 org;     /* w = tmin */
  rc_float4 dir;     /* w = distance to the source sample (tmax; large for distant) */
  rc_float4 contrib; /* rgb to add, w unused */
  rc_float4 cext;    /* extinction of the medium the shadow ray travels in (rgb); w: the bits of
                        its albedo's source (rc_ray.medium): it loses what is not scattered */
  rc_u32 primary;
  rc_u32 source; /* source index: the ray counts only if it reaches this source unblocked */
  rc_u32 slights_or_tested; /* a request: its ray's mist sources (rc_ray.slights), which mist
                               boundaries change; a -dt estimate record: the number of tested
                               requests before it */
  rc_u32 crtype; /* the ambient/specular ancestry bits of the ray it leaves (shade.cl's RC_CR_*) */
  rc_u32 clip;   /* antimatter state of the surface point it leaves (as rc_ray) */
  rc_u32 inside;
  float dist0;  /* length of the ray tree before its origin: the surface ray's dist0 plus that
                   ray's hit distance, plus the shadow segments before this one (T) */
  float sdist0; /* of that, the shadow segments alone (Radiance's Ts: the shadow chain) */
} rc_shadow;

/* A shadow ray's state after a step (kernels/pipeline/shadow_step.cl; the host reads the
 * status bits to find the rays that go on). */
#define RC_SH_BLOCKED 0u
#define RC_SH_REACHED 1u
#define RC_SH_CONTINUE 2u /* through a transmitting surface: traced again from there */
#define RC_SH_STATUS 3u   /* the bits above */
#define RC_SH_BENT 4u     /* direction changed by refraction: the source must be re-checked */
#define RC_SH_LATER 8u    /* not the first segment */

/* Rendering settings the kernels read (from the -d*, -s*, -a*, -l* options). */
#define RC_PF_DV 1u      /* -dv: sources visible to view rays */
#define RC_PF_BV 2u      /* -bv: back faces visible */
#define RC_PF_IRRAD_I 4u /* -i: primary hits become diffuse irradiance meters */
#define RC_PF_LOWDISC 8u /* -u-: first-hit samples stratified over the primary ray ids */
#define RC_PF_SPREAD 16u /* -oe: a primary's first hemispheres tallied per division */
typedef struct rc_params {
  rc_float4 av;     /* -av ambient value (rgb); w = -lw minimum ray weight */
  rc_float4 direct; /* -ds, -dj, -dt, -dc */
  rc_float4 spec;   /* -ss, -st; z = scene epsilon (ray start offset), w unused */
  rc_u32 seed;      /* random seed (-u) */
  rc_i32 lr;        /* -lr reflection limit */
  rc_u32 flags;     /* RC_PF_* */
  rc_u32 ab;        /* -ab */
  rc_u32 nsources;
  rc_u32 irradiance_material; /* built-in material of -i/-I */
  rc_u32 ad;                  /* -ad ambient divisions */
  rc_u32 as;                  /* -as ambient super-samples */
  rc_float4 amb;              /* irradiance cache: x = -aa, y = minimum radius (Radiance's
                                 minarad), z = number of BVH nodes (0: no cache), w = 1 when a
                                 miss is reported to the host (RC_RAY_AMBMISS) instead of
                                 sampled */
  rc_float4 medium;           /* the global medium: -me extinction (rgb), w = -mg */
  rc_float4 albedo;           /* -ma scattering albedo (rgb), w = -ms */
  rc_u32 mist;                /* args offset of the mist sources' table: per bit of
                                 rc_ray.slights, a source index (RC_NONE: unknown), then the
                                 bit set of the known ones; RC_NONE without mist */
  rc_u32 contrib;             /* rcontrib: args offset of the tracked modifiers' tables
                                 (render/compile/contrib_tables.h); RC_NONE otherwise */
  rc_u32 pad2, pad3;
} rc_params;

/* An irradiance-cache record as the lookup kernel reads it (../shared/docs/radiance/ambient-file.md
 * §3; Radiance's AMBVAL with its directions decoded). */
typedef struct rc_amb_record {
  rc_float4 pos;  /* position (re-centred); w = weight */
  rc_float4 nrm;  /* unit normal; w = rad[0] */
  rc_float4 udir; /* unit u axis; w = rad[1] */
  rc_float4 val;  /* ambient value (rgb); w = level */
  rc_float4 grad; /* translational gradient (u, v), rotational gradient (u, v) */
} rc_amb_record;

/* A node of the BVH over the records' discs, depth first: an inner node's first child follows
 * it, `skip` is the index after its subtree; a leaf lists records [first, first + count). The
 * nodes are a forest, one tree per orientation bin (2 x a normal's dominant axis, + 1 where
 * that component is negative): a node of a bin's tree holds records whose normals lie within
 * its cone, half-angle h (cos h in lo.w, sin h in hi.w) about the bin's axis, so a lookup
 * skips the trees of surfaces facing other ways. */
#define RC_AMB_BINS 6u
typedef struct rc_amb_node {
  rc_float4 lo; /* box; w = cos of the normal cone's half-angle */
  rc_float4 hi; /* box; w = its sine */
  rc_u32 skip;
  rc_u32 first;
  rc_u32 count; /* 0 for an inner node */
  rc_u32 bin;   /* 0..5: the axis is bin / 2, its negative where bin is odd */
} rc_amb_node;

/* One hemisphere of ambient samples to turn into a record (kernels/ambient/ambient_record.cl,
 * Radiance's doambient after sampling). ux, uy and nrm are orthonormal, uy = nrm x ux. */
typedef struct rc_amb_hemi {
  rc_float4 pos; /* the point (re-centred); w = the weight doambient gets (the record's) */
  rc_float4 nrm; /* unit normal; w = minimum radius (Radiance's minarad) */
  rc_float4 ux;  /* tangent the samples' first disc coordinate runs along; w = maximum radius */
  rc_float4 uy;  /* nrm x ux; w = -aa */
  rc_u32 first;  /* index of its first sample */
  rc_u32 ns;     /* divisions per axis: ns*ns samples, i*ns + j, i along uy, j along ux */
  rc_u32 level;  /* ambient level of the record */
  rc_u32 pad0;
} rc_amb_hemi;

/* One stratum of a hemisphere. val.xyz: the stratum's radiance (mean of its samples) / ns^2;
 * val.w: reciprocal distance of its nearest hit (0: nothing hit), < 0 marks a failed sample.
 * pnt.xyz: its first sample's hit point (re-centred), clamped to 10 * cube size + 1000 along
 * the ray as Radiance does; pnt.w unused. */
typedef struct rc_amb_sample {
  rc_float4 val;
  rc_float4 pnt;
} rc_amb_sample;

/* What rc_make_record says of a hemisphere besides the record. */
#define RC_AMB_FAILED 0      /* no sample: no value */
#define RC_AMB_VALUE_ONLY -1 /* a value to use but no record to keep */
#define RC_AMB_RECORD 1      /* a record */
/* rc_make_record's work-group: the items that share one hemisphere (fixed, so that its sums
 * are added in the same order on every device). */
#define RC_AMR_GROUP 64u
typedef struct rc_amb_made {
  rc_u32 corral; /* sectors of possible light leaks (Radiance's ambcorral) */
  rc_i32 status; /* RC_AMB_* */
  rc_u32 pad0;
  rc_u32 pad1;
} rc_amb_made;

/* Counter-based random-number key: (primary ray, sample, depth, seed). */
typedef struct rc_rng_key {
  rc_u32 primary;
  rc_u32 sample;
  rc_u32 depth;
  rc_u32 seed;
} rc_rng_key;

/* Every struct above with every field, for the host/device layout test (rc_float4's members
 * are vector components on the device, which have no address: only its size is compared). */
#define RADCL_LAYOUT_STRUCTS(S)                                                                    \
  S(rc_float4)                                                                                     \
  S(rc_ray)                                                                                        \
  S(rc_hit)                                                                                        \
  S(rc_surface) S(rc_material) S(rc_source) S(rc_mirror) S(rc_shadow) S(rc_pattern) S(rc_rng_key)  \
      S(rc_params) S(rc_amb_record) S(rc_amb_node) S(rc_amb_hemi) S(rc_amb_sample) S(rc_amb_made)
#define RADCL_LAYOUT_FIELDS(F)                                                                                             \
  F(rc_ray, org)                                                                                                           \
  F(rc_ray, dir)                                                                                                           \
  F(rc_ray, coef)                                                                                                          \
  F(rc_ray, primary) F(rc_ray, depth) F(rc_ray, flags) F(rc_ray, sample) F(                                                \
      rc_ray, ambient_depth) F(rc_ray, cext_b) F(rc_ray, tally) F(rc_ray, clip) F(rc_ray, inside)                          \
      F(rc_ray, cell) F(rc_ray, dist0) F(rc_ray, medium) F(rc_ray, gecc) F(rc_ray, slights) F(                             \
          rc_hit, pos) F(rc_hit, nrm) F(rc_hit, uv) F(rc_hit, pert) F(rc_hit, surface)                                     \
          F(rc_hit, prim) F(rc_hit, source) F(                                                                             \
              rc_hit,                                                                                                      \
              front) F(rc_surface,                                                                                         \
                       material) F(rc_surface,                                                                             \
                                   type) F(rc_surface,                                                                     \
                                           source) F(rc_surface,                                                           \
                                                     object) F(rc_surface,                                                 \
                                                               flags) F(rc_surface, clip)                                  \
              F(rc_surface, slots) F(rc_surface, pad2) F(rc_material, type) F(rc_material, args) F(                        \
                  rc_material, nargs) F(rc_material, alt)                                                                  \
                  F(rc_material, patterns) F(rc_material, npatterns) F(rc_material, back) F(                               \
                      rc_material, func) F(rc_pattern,                                                                     \
                                           type) F(rc_pattern,                                                             \
                                                   args) F(rc_pattern,                                                     \
                                                           nargs) F(rc_pattern,                                            \
                                                                    xform) F(rc_pattern, object)                           \
                      F(rc_source, pos) F(rc_source, axis) F(rc_source, su) F(rc_source, sv) F(                            \
                          rc_source, emit) F(rc_source, spot)                                                              \
                          F(rc_source, kind) F(rc_source, flags) F(rc_source, surface) F(                                  \
                              rc_source,                                                                                   \
                              verts) F(rc_source,                                                                          \
                                       nverts) F(rc_source, spot_focus)                                                    \
                              F(rc_source, parent) F(rc_source, mirror) F(rc_mirror, plane) F(                             \
                                  rc_mirror,                                                                               \
                                  centre) F(rc_mirror, refl)                                                               \
                                  F(rc_mirror, surface) F(rc_mirror, verts) F(rc_mirror, nverts) F(rc_mirror, redirect) F( \
                                      rc_shadow,                                                                           \
                                      org) F(rc_shadow,                                                                    \
                                             dir) F(rc_shadow, contrib)                                                    \
                                      F(rc_shadow, cext) F(rc_shadow, primary) F(rc_shadow, source) F(                     \
                                          rc_shadow,                                                                       \
                                          slights_or_tested) F(rc_shadow,                                                  \
                                                               crtype) F(rc_shadow, clip)                                  \
                                          F(rc_shadow, inside) F(rc_shadow, dist0) F(rc_shadow, sdist0) F(                 \
                                              rc_rng_key,                                                                  \
                                              primary) F(rc_rng_key,                                                       \
                                                         sample) F(rc_rng_key,                                             \
                                                                   depth) F(rc_rng_key, seed)                              \
                                              F(rc_params, av) F(rc_params, direct) F(                                     \
                                                  rc_params, spec) F(rc_params, seed)                                      \
                                                  F(rc_params, lr) F(rc_params, flags) F(rc_params, ab) F(                 \
                                                      rc_params,                                                           \
                                                      nsources) F(rc_params, irradiance_material)                          \
                                                      F(rc_params, ad) F(rc_params, as) F(                                 \
                                                          rc_params,                                                       \
                                                          amb) F(rc_params,                                                \
                                                                 medium) F(rc_params, albedo)                              \
                                                          F(rc_params, mist) F(rc_params, contrib) F(                      \
                                                              rc_amb_record,                                               \
                                                              pos) F(rc_amb_record,                                        \
                                                                     nrm) F(rc_amb_record, udir)                           \
                                                              F(rc_amb_record,                                             \
                                                                val) F(rc_amb_record,                                      \
                                                                       grad) F(rc_amb_node,                                \
                                                                               lo) F(rc_amb_node,                          \
                                                                                     hi) F(rc_amb_node, skip)              \
                                                                  F(rc_amb_node, first) F(                                 \
                                                                      rc_amb_node,                                         \
                                                                      count) F(rc_amb_node,                                \
                                                                               bin) F(rc_amb_hemi, pos)                    \
                                                                      F(                                                   \
                                                                          rc_amb_hemi,                                     \
                                                                          nrm) F(rc_amb_hemi,                              \
                                                                                 ux) F(rc_amb_hemi,                        \
                                                                                       uy) F(rc_amb_hemi,                  \
                                                                                             first)                        \
                                                                          F(rc_amb_hemi, ns) F(                            \
                                                                              rc_amb_hemi,                                 \
                                                                              level) F(rc_amb_hemi,                        \
                                                                                       pad0)                               \
                                                                              F(rc_amb_sample, val) F(                     \
                                                                                  rc_amb_sample,                           \
                                                                                  pnt) F(rc_amb_made,                      \
                                                                                         corral)                           \
                                                                                  F(rc_amb_made,                           \
                                                                                    status)                                \
                                                                                      F(rc_amb_made,                       \
                                                                                        pad0)                              \
                                                                                          F(rc_amb_made,                   \
                                                                                            pad1)

#endif /* RADCL_DEVICE_TYPES_H */
