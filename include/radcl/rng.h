/* Counter-based random numbers: Philox4x32-10 (Salmon et al., "Parallel random numbers: as easy
 * as 1, 2, 3", SC 2011). Plain C shared by host and kernels, so both produce the same bits.
 * A value depends only on (primary ray, sample, depth, seed) and a dimension index, never on
 * wave size, thread count or device: that is what makes -u- runs repeatable everywhere. */
#ifndef RADCL_RNG_H
#define RADCL_RNG_H

#include "radcl/device_types.h"

#define RC_RNG_INLINE static inline

typedef struct rc_u32x4 {
  rc_u32 v[4];
} rc_u32x4;

#define RC_PHILOX_M0 0xD2511F53u
#define RC_PHILOX_M1 0xCD9E8D57u
#define RC_PHILOX_W0 0x9E3779B9u
#define RC_PHILOX_W1 0xBB67AE85u

/* In the kernels the generator's ten rounds stay one function rather than a copy at each of
 * its many call sites (RC_NOINLINE, device_types.h: NVIDIA's first build of office_clear
 * 7.79 -> 7.00 s, run times the same; docs/internals.md). */
#ifdef __OPENCL_C_VERSION__
#define RC_RNG_PHILOX RC_NOINLINE static
#else
#define RC_RNG_PHILOX RC_RNG_INLINE
#endif

RC_RNG_PHILOX rc_u32x4 rc_philox4x32(rc_u32x4 c, rc_u32 k0, rc_u32 k1) {
#ifdef __OPENCL_C_VERSION__
#pragma unroll
#endif
  for (int r = 0; r < 10; ++r) {
    rc_u64 p0 = (rc_u64)RC_PHILOX_M0 * (rc_u64)c.v[0];
    rc_u64 p1 = (rc_u64)RC_PHILOX_M1 * (rc_u64)c.v[2];
    rc_u32 hi0 = (rc_u32)(p0 >> 32), lo0 = (rc_u32)p0;
    rc_u32 hi1 = (rc_u32)(p1 >> 32), lo1 = (rc_u32)p1;
    rc_u32x4 n;
    n.v[0] = hi1 ^ c.v[1] ^ k0;
    n.v[1] = lo1;
    n.v[2] = hi0 ^ c.v[3] ^ k1;
    n.v[3] = lo0;
    c = n;
    k0 += RC_PHILOX_W0;
    k1 += RC_PHILOX_W1;
  }
  return c;
}

/* Four independent 32-bit values for dimensions 4*block .. 4*block+3 of this key. */
RC_RNG_INLINE rc_u32x4 rc_random_bits(rc_rng_key key, rc_u32 block) {
  rc_u32x4 c;
  c.v[0] = key.primary;
  c.v[1] = key.sample;
  c.v[2] = key.depth;
  c.v[3] = block;
  return rc_philox4x32(c, key.seed, 0x5EED1DCAu);
}

/* 32 random bits -> float in [0,1): the top 24 bits scaled exactly, same on every device. */
RC_RNG_INLINE float rc_bits_to_unit(rc_u32 x) {
  return (float)(x >> 8) * (1.0f / 16777216.0f);
}

/* One uniform number in [0,1) for dimension `dim` of this key. */
RC_RNG_INLINE float rc_random(rc_rng_key key, rc_u32 dim) {
  rc_u32x4 b = rc_random_bits(key, dim >> 2);
  return rc_bits_to_unit(b.v[dim & 3u]);
}

/* A low-discrepancy alternative over the primary index: the R2 sequence (Roberts' generalised
 * golden ratio, 2-D) in 32-bit fixed point, rotated per (sample, depth, seed, dimension).
 * Within each aligned block of 4096 primaries the points are dealt out in a scrambled order
 * (a keyed bijection of the index's low 12 bits), so the block's set is still the sequence's
 * evenly spread run of 4096 points, but pixels a scanline (or any fixed step) apart no longer
 * sit a fixed step apart in the sequence: in raster order that step drew a lattice (issue 54).
 * Like Radiance's -u-: stratified over the picture, uncorrelated from pixel to pixel. */
RC_RNG_INLINE rc_u32 rc_ld_scramble(rc_u32 primary, rc_u32 key) {
  const rc_u32 m = 0xFFFu;
  rc_u32 k = key ^ ((primary >> 12) * 0x9E3779B9u);
  k ^= k >> 15;
  k *= 0x2C1B3C6Du;
  k ^= k >> 12;
  rc_u32 x = primary & m;
  x = (x ^ k) & m;
  x = (x * ((k >> 12) | 1u)) & m;
  x ^= x >> 6;
  x = (x * 0x5BDu) & m;
  x ^= x >> 5;
  x = (x + (k >> 20)) & m;
  x = (x * 0x3A7u) & m;
  x ^= x >> 6;
  return (primary & ~m) | x;
}
RC_RNG_INLINE void rc_random_ld_pair(rc_rng_key key, rc_u32 dim, float* a, float* b) {
  rc_rng_key shared = key;
  shared.primary = 0x9E3779B9u; /* the rotation must not depend on the primary */
  rc_u32x4 rot = rc_random_bits(shared, dim >> 2);
  rc_u32 i = rc_ld_scramble(key.primary, rot.v[(dim + 2u) & 3u]);
  *a = rc_bits_to_unit(rot.v[dim & 3u] + i * 0xC13FA9A9u);        /* 2^32 / phi2 */
  *b = rc_bits_to_unit(rot.v[(dim + 1u) & 3u] + i * 0x91E10DA5u); /* 2^32 / phi2^2 */
}
RC_RNG_INLINE float rc_random_ld(rc_rng_key key, rc_u32 dim) {
  float a, b;
  rc_random_ld_pair(key, dim & ~1u, &a, &b);
  return (dim & 1u) ? b : a;
}

/* Dimensions dim and dim + 1 (dim even: one block) at the cost of one block. */
RC_RNG_INLINE void rc_random_pair(rc_rng_key key, rc_u32 dim, float* a, float* b) {
  rc_u32x4 x = rc_random_bits(key, dim >> 2);
  *a = rc_bits_to_unit(x.v[dim & 3u]);
  *b = rc_bits_to_unit(x.v[(dim + 1u) & 3u]);
}
/* Numbers of one key read in rising dimensions, each block of four computed once: the same
 * values as rc_random at a fraction of the generator's work. */
typedef struct rc_rng_stream {
  rc_rng_key key;
  rc_u32 block;
  rc_u32x4 bits;
} rc_rng_stream;
RC_RNG_INLINE rc_rng_stream rc_stream(rc_rng_key key) {
  rc_rng_stream s;
  s.key = key;
  s.block = 0xFFFFFFFFu; /* no dimension's block */
  s.bits.v[0] = s.bits.v[1] = s.bits.v[2] = s.bits.v[3] = 0u;
  return s;
}
RC_RNG_INLINE float rc_stream_random(rc_rng_stream* s, rc_u32 dim) {
  if ((dim >> 2) != s->block) {
    s->block = dim >> 2;
    s->bits = rc_random_bits(s->key, s->block);
  }
  return rc_bits_to_unit(s->bits.v[dim & 3u]);
}
RC_RNG_INLINE rc_rng_key rc_make_key(rc_u32 primary, rc_u32 sample, rc_u32 depth, rc_u32 seed) {
  rc_rng_key k;
  k.primary = primary;
  k.sample = sample;
  k.depth = depth;
  k.seed = seed;
  return k;
}

#endif /* RADCL_RNG_H */
