/* The ray context a generated .cal function reads: plain C shared by the host (C++) and the
 * OpenCL kernels, like radcl/device_types.h. Inputs are float (one slot per ray variable);
 * generated code computes in rc_calc_real, which is double when the program is built with
 * RC_CALC_FP64 (the device has cl_khr_fp64) and float otherwise. The primitive's real
 * arguments (arg(n), A1..An) live in a separate float buffer: args[arg_base .. arg_base+nargs). */
#ifndef RADCL_CALC_DEVICE_CONTEXT_H
#define RADCL_CALC_DEVICE_CONTEXT_H

/* Slots of rc_calc_ray.v. Slots 0..26 are Radiance's channels $1..$27 (channel = slot + 1);
 * the rest are the material-specific variables of ../shared/docs/radiance/calc-language.md §5.2. */
#define RC_CALC_RAY_VARS(X)                                                                        \
  X(DX, "Dx")                                                                                      \
  X(DY, "Dy")                                                                                      \
  X(DZ, "Dz") X(NX, "Nx") X(NY, "Ny") X(NZ, "Nz") X(PX, "Px") X(PY, "Py") X(PZ, "Pz") X(T, "T")    \
      X(RDOT, "Rdot") X(S, "S") X(TX, "Tx") X(TY, "Ty") X(TZ, "Tz") X(IX, "Ix") X(IY, "Iy")        \
          X(IZ, "Iz") X(JX, "Jx") X(JY, "Jy") X(JZ, "Jz") X(KX, "Kx") X(KY, "Ky") X(KZ, "Kz")      \
              X(TS, "Ts") X(LU, "Lu") X(LV, "Lv") X(NXP, "NxP") X(NYP, "NyP") X(NZP, "NzP")        \
                  X(RDOTP, "RdotP") X(CRP, "CrP") X(CGP, "CgP") X(CBP, "CbP") X(DXA, "DxA")        \
                      X(DYA, "DyA") X(DZA, "DzA")

#define RC_CALC_SLOT_ENTRY(id, name) RC_CALC_##id,
enum rc_calc_slot { RC_CALC_RAY_VARS(RC_CALC_SLOT_ENTRY) RC_CALC_NSLOTS };
#undef RC_CALC_SLOT_ENTRY

/* Channels $1..$27 map to slots 0..26. */
#define RC_CALC_NCHANNELS 27
/* Slot array length: RC_CALC_NSLOTS rounded up so the struct stays a multiple of 16 bytes. */
#define RC_CALC_SLOT_CAPACITY 40

/* Error bits a generated function ORs into rc_calc_env.error (Radiance prints a warning and
 * carries on with 0; the device cannot print, the caller reports). */
#define RC_CALC_ERR_DIVIDE 1    /* division by zero: result 0 */
#define RC_CALC_ERR_POWER 2     /* x^y not finite: result 0 */
#define RC_CALC_ERR_DOMAIN 4    /* library function not finite / out of domain: result 0 */
#define RC_CALC_ERR_DEPTH 8     /* recursion deeper than the generated copies: result 0 */
#define RC_CALC_ERR_ARGUMENT 16 /* arg(n) with n beyond the primitive's real arguments: 0 */

typedef struct rc_calc_ray {
  float v[RC_CALC_SLOT_CAPACITY]; /* ray variables by slot */
  int nargs;                      /* number of real arguments of the primitive */
  int arg_base;                   /* index of its first real argument in the args buffer */
  int pad0, pad1;
} rc_calc_ray;

#ifdef __OPENCL_C_VERSION__
#ifdef RC_CALC_FP64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double rc_calc_real;
#else
typedef float rc_calc_real;
#endif
/* What every generated function receives: the ray, the real-argument buffer and the error bits. */
typedef struct rc_calc_env {
  rc_calc_ray ray;
  global const float* args;
  int error;
} rc_calc_env;
#else
#ifdef __cplusplus
static_assert(sizeof(rc_calc_ray) == 176, "rc_calc_ray layout");
#endif
#endif

#endif
