/* Radiance's bright(): the luminance of an RGB colour in its standard primaries (the CIE_rf,
 * CIE_gf and CIE_bf of its color.h). The one definition, for the host and the kernels. */
#ifndef RADCL_LUMINANCE_H
#define RADCL_LUMINANCE_H

#define RC_CIE_RF 0.265074126
#define RC_CIE_GF 0.670114631
#define RC_CIE_BF 0.064811243

#ifdef __OPENCL_C_VERSION__
/* The weights as float literals: a device need not have doubles. */
#define RC_FLOAT_LITERAL_(x) x##f
#define RC_FLOAT_LITERAL(x) RC_FLOAT_LITERAL_(x)
static inline float rc_bright(float3 c) {
  return RC_FLOAT_LITERAL(RC_CIE_RF) * c.x + RC_FLOAT_LITERAL(RC_CIE_GF) * c.y +
         RC_FLOAT_LITERAL(RC_CIE_BF) * c.z;
}
#else
namespace radcl {
inline double bright(double r, double g, double b) {
  return RC_CIE_RF * r + RC_CIE_GF * g + RC_CIE_BF * b;
}
template <class Rgb> inline double bright(const Rgb& c) {
  return bright(c[0], c[1], c[2]);
}
} // namespace radcl
#endif

#endif
