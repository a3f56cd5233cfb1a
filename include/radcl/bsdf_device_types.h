/* Plain-C records of BSDF data on the device (Radiance's BSDF and aBSDF materials), shared by
 * the host (include/radcl/render/compile/bsdf_tables.h builds them) and kernels/materials/bsdf_eval.cl.
 * Layout rules as device_types.h: 4-byte scalars and rc_float4 only, 16-byte multiples.
 *
 * Four buffers hold any number of BSDF files: rc_bsdf records (one per file), rc_bsdf_comp
 * records (one per component kept), one float array and one int array. Offsets below are
 * element indices into those arrays. Vectors are in the BSDF's local frame (front = +Z, both
 * pointing away from the surface: `in` towards the light, `out` towards the viewer).
 *
 * Float array ("vals"):
 *   Klems basis: theta bounds (rings + 1, degrees), then lambda (projected solid angle) per patch.
 *   Klems component: the residual (below) matrices, [o * n_in + i]: Y, then X, then Z (colour);
 *     cdf: per incident patch i, n_out running sums over o of Y(i, o) * lambda_out(o) (the
 *     last is the directional-hemispherical total); rcdf (transmission only, for light
 *     arriving from the other side through reciprocity): per outgoing patch o, n_in running
 *     sums over i of Y(i, o) * lambda_in(i).
 *   Tensor-tree leaf: Y, or Y, X, Z with colour. Slice tables of tree branches (below).
 * Int array ("ints"):
 *   Klems basis at b: [b] rings, [b+1] patches, [b+2] vals offset of the theta bounds,
 *     [b+3] vals offset of the lambdas, then per ring r: [b+4+2r] nphis, [b+5+2r] first patch.
 *   Tensor-tree node at k: a leaf when ints[k] >= 0 (the vals offset of its value); else a
 *     branch of height h = -ints[k] (levels of branches below it, itself included):
 *     [k+1] vals offset of its forward slice table, [k+2] of its reverse one (-1: none),
 *     [k+3+c] child c (c < 2^ndim; bit d of c set: the upper half of dimension d).
 *   A slice table holds, for each cell of the fixed dimensions at the branch's resolution 2^h
 *   per dimension (row-major, lower dimension slowest), the mean Y over the other two
 *   dimensions: forward fixes the incident dimensions (TT3: 0; TT4: 0, 1), reverse (TT4
 *   transmission only) the outgoing ones (2, 3). The mean over a leaf is its Y. */
#ifndef RADCL_BSDF_DEVICE_TYPES_H
#define RADCL_BSDF_DEVICE_TYPES_H

#include "radcl/device_types.h"

/* rc_bsdf_comp.format */
#define RC_BSDF_KLEMS 0u
#define RC_BSDF_TT3 1u
#define RC_BSDF_TT4 2u

/* Parts (radcl::bsdf::Part order), named by the side light arrives on: reflection front and
 * back, transmission from the front (out on the back) and from the back. */
#define RC_BSDF_RF 0u
#define RC_BSDF_RB 1u
#define RC_BSDF_TF 2u
#define RC_BSDF_TB 3u

/* One BSDF file. Radiance splits each component into a Lambertian part and a residual, and
 * keeps the Lambertian parts per side even where it drops the residual (bsdf_tables.h). */
typedef struct rc_bsdf {
  rc_float4 lamb[4]; /* per part: the Lambertian BSDF (1/sr), CIE X, Y, Z in x, y, z; w = 0.
                        A transmission part without data takes the other one's (Radiance). */
  rc_u32 comp[4];    /* per part: its residual component, RC_NONE if none or dropped */
  rc_u32 format;     /* RC_BSDF_* of the file */
  rc_u32 pad0, pad1, pad2;
} rc_bsdf;

/* One component's residual (its data less its Lambertian part). */
typedef struct rc_bsdf_comp {
  rc_float4 lamb; /* the Lambertian part split off this component (as rc_bsdf.lamb) */
  rc_u32 format;  /* RC_BSDF_KLEMS, RC_BSDF_TT3, RC_BSDF_TT4 */
  rc_u32 part;    /* RC_BSDF_RF ... RC_BSDF_TB */
  rc_u32 colour;  /* 1 when X and Z are stored besides Y */
  rc_u32 file;    /* its rc_bsdf */
  /* Klems */
  rc_u32 in_basis, out_basis; /* ints offsets of the incident and outgoing bases */
  rc_u32 n_in, n_out;         /* their patch counts */
  rc_u32 values;              /* vals offset of the Y matrix (X and Z follow with colour) */
  rc_u32 cdf;                 /* vals offset of the forward cumulative sums */
  rc_u32 rcdf;                /* vals offset of the reverse ones, RC_NONE for reflection */
  /* Tensor trees */
  rc_u32 root;    /* ints offset of the root node */
  float max_hemi; /* Radiance's maxHemi of the residual: the largest total over incidence */
  float min_psa;  /* Radiance's minProjSA: the smallest projected solid angle of a Klems patch
                     or (trees) pi times the smallest leaf's edge squared */
  float max_psa;  /* trees: pi times the largest leaf's edge squared; Klems: the largest patch */
  rc_u32 pad0;
} rc_bsdf_comp;

#ifndef __OPENCL_C_VERSION__
#ifdef __cplusplus
static_assert(sizeof(rc_bsdf) == 96, "rc_bsdf layout");
static_assert(sizeof(rc_bsdf_comp) == 80, "rc_bsdf_comp layout");
#else
_Static_assert(sizeof(rc_bsdf) == 96, "rc_bsdf layout");
_Static_assert(sizeof(rc_bsdf_comp) == 80, "rc_bsdf_comp layout");
#endif
#endif

#endif /* RADCL_BSDF_DEVICE_TYPES_H */
