/* Radiance's noise functions, written once in the common subset of C++ and OpenCL C so the host
 * evaluator and generated device code compute the same values. Include with RC_NOISE_REAL
 * defined (double on the host; rc_calc_real on the device).
 *   rc_noise3(x,y,z, i): i = 3 Perlin's improved noise (2002 reference algorithm);
 *                        i = 0..2 its backward-difference partial along x, y or z.
 *   rc_fnoise3(x,y,z):   fractal noise by recursive midpoint displacement of the unit
 *                        lattice cube (2000 steps per unit, halving each level). */
#ifndef RADCL_CALC_NOISE_H
#define RADCL_CALC_NOISE_H

#ifdef __OPENCL_C_VERSION__
#define RC_NOISE_TABLE constant int
#define RC_NOISE_FN
#define RC_NOISE_BIG __attribute__((noinline))
typedef long rc_noise_i64;
typedef ulong rc_noise_u64;
#else
#include <math.h>
#define RC_NOISE_TABLE static const int
#define RC_NOISE_FN static inline
#define RC_NOISE_BIG static inline
typedef long long rc_noise_i64;
typedef unsigned long long rc_noise_u64;
#endif

/* Step of the derivative differences and the fractal's finest displacement scale. */
#define RC_NOISE_EPS 0.0005

/* Perlin's reference permutation (Improving Noise, SIGGRAPH 2002). */
RC_NOISE_TABLE rc_noise_perm[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180,
};

RC_NOISE_FN int rc_noise_p(int i) {
  return rc_noise_perm[i & 0xff];
}

RC_NOISE_FN RC_NOISE_REAL rc_noise_fade(RC_NOISE_REAL t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

RC_NOISE_FN RC_NOISE_REAL rc_noise_lerp(RC_NOISE_REAL t, RC_NOISE_REAL a, RC_NOISE_REAL b) {
  return a + t * (b - a);
}

/* One of 12 gradient directions from the low 4 bits of the hash, dotted with (x,y,z). */
RC_NOISE_FN RC_NOISE_REAL rc_noise_grad(int hash, RC_NOISE_REAL x, RC_NOISE_REAL y,
                                        RC_NOISE_REAL z) {
  int h = hash & 15;
  RC_NOISE_REAL u = h < 8 ? x : y;
  RC_NOISE_REAL v = h < 4 ? y : ((h == 12 || h == 14) ? x : z);
  return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

/* Lattice cell of a coordinate as Radiance takes it: (int)x - (x < 0), which for a negative
 * integer is x - 1 (not floor). Done in floating point so huge values stay defined. */
RC_NOISE_FN RC_NOISE_REAL rc_noise_cell(RC_NOISE_REAL x) {
  RC_NOISE_REAL f = floor(x);
  return (x < 0 && f == x) ? f - 1 : f;
}

RC_NOISE_FN int rc_noise_wrap(RC_NOISE_REAL c) {
  RC_NOISE_REAL m = c - 256.0 * floor(c / 256.0);
  /* NaN or infinite coordinates (m is NaN then): cell 0 rather than an undefined conversion. */
  return (m >= 0 && m < 256.0) ? (int)m & 0xff : 0;
}

RC_NOISE_BIG RC_NOISE_REAL rc_noise_perlin(RC_NOISE_REAL x, RC_NOISE_REAL y, RC_NOISE_REAL z) {
  RC_NOISE_REAL cx = rc_noise_cell(x), cy = rc_noise_cell(y), cz = rc_noise_cell(z);
  x -= cx;
  y -= cy;
  z -= cz;
  int X = rc_noise_wrap(cx), Y = rc_noise_wrap(cy), Z = rc_noise_wrap(cz);
  RC_NOISE_REAL u = rc_noise_fade(x), v = rc_noise_fade(y), w = rc_noise_fade(z);
  int a = rc_noise_p(X) + Y, aa = rc_noise_p(a) + Z, ab = rc_noise_p(a + 1) + Z;
  int b = rc_noise_p(X + 1) + Y, ba = rc_noise_p(b) + Z, bb = rc_noise_p(b + 1) + Z;
  RC_NOISE_REAL near_z =
      rc_noise_lerp(v,
                    rc_noise_lerp(u, rc_noise_grad(rc_noise_p(aa), x, y, z),
                                  rc_noise_grad(rc_noise_p(ba), x - 1, y, z)),
                    rc_noise_lerp(u, rc_noise_grad(rc_noise_p(ab), x, y - 1, z),
                                  rc_noise_grad(rc_noise_p(bb), x - 1, y - 1, z)));
  RC_NOISE_REAL far_z =
      rc_noise_lerp(v,
                    rc_noise_lerp(u, rc_noise_grad(rc_noise_p(aa + 1), x, y, z - 1),
                                  rc_noise_grad(rc_noise_p(ba + 1), x - 1, y, z - 1)),
                    rc_noise_lerp(u, rc_noise_grad(rc_noise_p(ab + 1), x, y - 1, z - 1),
                                  rc_noise_grad(rc_noise_p(bb + 1), x - 1, y - 1, z - 1)));
  return rc_noise_lerp(w, near_z, far_z);
}

RC_NOISE_FN RC_NOISE_REAL rc_noise3(RC_NOISE_REAL x, RC_NOISE_REAL y, RC_NOISE_REAL z, int i) {
  RC_NOISE_REAL f = rc_noise_perlin(x, y, z);
  if (i == 3) return f;
  RC_NOISE_REAL back =
      rc_noise_perlin(x - (i == 0 ? RC_NOISE_EPS : 0.0), y - (i == 1 ? RC_NOISE_EPS : 0.0),
                      z - (i == 2 ? RC_NOISE_EPS : 0.0));
  return (f - back) / RC_NOISE_EPS;
}

/* Hash of an integer seed to [-1, 1), as Radiance's frand (wrapping 64-bit arithmetic). */
RC_NOISE_FN RC_NOISE_REAL rc_noise_frand(rc_noise_i64 seed) {
  rc_noise_u64 s = (rc_noise_u64)seed;
  s = (s << 13) ^ s;
  rc_noise_u64 h = s * (s * s * 15731u + 789221u) + 1376312589u;
  return 1.0 - (RC_NOISE_REAL)(h & 0x7fffffffu) / 1073741824.0;
}

RC_NOISE_FN RC_NOISE_REAL rc_noise_frand3(rc_noise_i64 x, rc_noise_i64 y, rc_noise_i64 z) {
  /* Wrapping (unsigned) arithmetic: the same bits as Radiance's long arithmetic, defined. */
  rc_noise_u64 h = (rc_noise_u64)17 * (rc_noise_u64)x + (rc_noise_u64)23 * (rc_noise_u64)y +
                   (rc_noise_u64)29 * (rc_noise_u64)z;
  return rc_noise_frand((rc_noise_i64)h);
}

/* A lattice coordinate as a 64-bit integer: values beyond its range (or NaN) are clamped
 * rather than converted with undefined behaviour. */
RC_NOISE_FN rc_noise_i64 rc_noise_lattice(RC_NOISE_REAL v) {
  if (!(v == v)) return 0;
  if (v > 1.0e17) return (rc_noise_i64)1.0e17;
  if (v < -1.0e17) return (rc_noise_i64)-1.0e17;
  return (rc_noise_i64)v;
}

RC_NOISE_BIG RC_NOISE_REAL rc_fnoise3(RC_NOISE_REAL x, RC_NOISE_REAL y, RC_NOISE_REAL z) {
  RC_NOISE_REAL p[3] = {x, y, z};
  rc_noise_i64 step = 2000; /* 1 / RC_NOISE_EPS lattice steps per unit */
  rc_noise_i64 target[3], corner[3], v[3];
  RC_NOISE_REAL val[8];
  for (int i = 0; i < 3; i++) {
    target[i] = rc_noise_lattice(step * p[i]);
    corner[i] = rc_noise_lattice(step * floor(p[i]));
  }
  /* val[k]: value at the cube corner whose axis-i offset is bit i of k. */
  for (int k = 0; k < 8; k++)
    val[k] = rc_noise_frand3(corner[0] + ((k & 1) ? step : 0), corner[1] + ((k & 2) ? step : 0),
                             corner[2] + ((k & 4) ? step : 0));
  for (;;) {
    RC_NOISE_REAL mean = 0.0;
    for (int k = 0; k < 8; k++)
      mean += val[k];
    mean *= 0.125;
    step >>= 1;
    if (step == 0) return mean;
    /* Which half along each axis holds the point: the sub-cube kept for the next level. */
    int side = 0;
    for (int i = 0; i < 3; i++) {
      v[i] = corner[i] + step;
      if (target[i] > v[i]) side |= 1 << i;
    }
    RC_NOISE_REAL amp = step * RC_NOISE_EPS;
    /* Centre of the cube: the sub-cube's corner opposite the kept old corner. */
    val[~side & 7] = mean + amp * rc_noise_frand3(v[0], v[1], v[2]);
    /* Face centres on the kept side of each axis. */
    for (int i = 0; i < 3; i++) {
      v[i] += (side & (1 << i)) ? step : -step;
      RC_NOISE_REAL sum = 0.0;
      for (int k = 0; k < 8; k++)
        if (((k ^ side) & (1 << i)) == 0) sum += val[k];
      val[~(side ^ (1 << i)) & 7] = 0.25 * sum + amp * rc_noise_frand3(v[0], v[1], v[2]);
      v[i] = corner[i] + step;
    }
    /* Edge midpoints parallel to each axis, on the kept side of the other two. */
    for (int i = 0; i < 3; i++) {
      int j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      v[j1] += (side & (1 << j1)) ? step : -step;
      v[j2] += (side & (1 << j2)) ? step : -step;
      RC_NOISE_REAL ends = val[side & ~(1 << i)] + val[side | (1 << i)];
      val[side ^ (1 << i)] = 0.5 * ends + amp * rc_noise_frand3(v[0], v[1], v[2]);
      v[j1] = corner[j1] + step;
      v[j2] = corner[j2] + step;
    }
    for (int i = 0; i < 3; i++)
      if (side & (1 << i)) corner[i] += step;
  }
}

#endif
