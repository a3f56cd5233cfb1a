/* Test kernels for kernels/materials/bsdf_eval.cl (tests/render/compile/bsdf_device.cpp). Item i works
 * on in[i] (and out[i] or xi[i]); `file` set: the file functions of BSDF `which`, else the
 * component functions of component `which`. */
#include "materials/bsdf_eval.cl"

#define RC_TEST_TABLES                                                                             \
  global const rc_bsdf *files, global const rc_bsdf_comp *comps, global const float *vals,         \
      global const int *ints
#define RC_TEST_MAKE_TABLES                                                                        \
  rc_bsdf_tables tables = {files, comps, vals, ints};                                              \
  const rc_bsdf_tables* t = &tables

/* res[2i] = (f, 0); res[2i+1] = (total of the component or the file's reflection, the file's
 * transmission, the pdf of `out`, 0). */
kernel void rc_test_bsdf_eval(RC_TEST_TABLES, uint which, uint file, global const float4* in,
                              global const float4* out, uint n, global float4* res) {
  uint i = get_global_id(0);
  if (i >= n) return;
  RC_TEST_MAKE_TABLES;
  float3 a = in[i].xyz, b = out[i].xyz;
  if (file) {
    res[2u * i] = (float4)(rc_bsdf_eval(t, which, a, b), 0.0f);
    res[2u * i + 1u] = (float4)(rc_bsdf_total(t, which, a, 1), rc_bsdf_total(t, which, a, 0),
                                rc_bsdf_pdf(t, which, a, b), 0.0f);
  } else {
    res[2u * i] = (float4)(rc_bsdf_comp_eval(t, which, a, b), 0.0f);
    res[2u * i + 1u] =
        (float4)(rc_bsdf_comp_total(t, which, a), 0.0f, rc_bsdf_comp_pdf(t, which, a, b), 0.0f);
  }
}

/* res[i] = (out, pdf), pdf 0 when nothing was drawn. */
kernel void rc_test_bsdf_sample(RC_TEST_TABLES, uint which, uint file, global const float4* in,
                                global const float4* xi, uint n, global float4* res) {
  uint i = get_global_id(0);
  if (i >= n) return;
  RC_TEST_MAKE_TABLES;
  float3 out = (float3)(0.0f);
  float pdf = 0.0f;
  int ok = file ? rc_bsdf_sample(t, which, in[i].xyz, xi[i].xyz, &out, &pdf)
                : rc_bsdf_comp_sample(t, which, in[i].xyz, xi[i].xyz, &out, &pdf);
  res[i] = ok ? (float4)(out, pdf) : (float4)(0.0f);
}

#ifdef __clang__
#define RC_TEST_OFFSETOF(T, f) ((uint) __builtin_offsetof(T, f))
#else
#define RC_TEST_OFFSETOF(T, f) ((uint)(&(((T*)0)->f)))
#endif

/* The device's sizes and offsets of the shared records, in the order the test lists them. */
kernel void rc_test_bsdf_layout(global uint* out) {
  if (get_global_id(0) != 0) return;
  uint k = 0;
  out[k++] = sizeof(rc_bsdf);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf, lamb);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf, comp);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf, format);
  out[k++] = sizeof(rc_bsdf_comp);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf_comp, lamb);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf_comp, format);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf_comp, in_basis);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf_comp, values);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf_comp, rcdf);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf_comp, root);
  out[k++] = RC_TEST_OFFSETOF(rc_bsdf_comp, max_hemi);
}
