/* brightdata, colordata, texdata and colorpict (../shared/docs/radiance/scene-format.md §4, §4.1):
 * data sets packed by the host (include/radcl/render/compile/pattern_data.h), interpolated at
 * coordinates computed by the pattern's expressions, then passed through its functions
 * (rc_pattern_fcall). */

#define RC_DATA_MAXDIM 5

/* The value of the data set at `off` in A at point pt. Each axis gives weights for the two
 * grid values around the coordinate: linear inside the grid and up to one step beyond an
 * end, then falling off as 1/distance, as Radiance extrapolates. Both weights are linear in
 * the values, so the n-D value is the sum over the 2^n corners of the weights' product. */
static rc_calc_real rc_data_value(global const float* A, uint off, const rc_calc_real* pt) {
  global const float* h = A + off;
  uint nd = min(as_uint(h[0]), (uint)RC_DATA_MAXDIM);
  global const float* vals = h + 1 + 4 * nd;
  uint stride[RC_DATA_MAXDIM];
  rc_calc_real w0[RC_DATA_MAXDIM], w1[RC_DATA_MAXDIM];
  uint s = 1;
  for (int k = (int)nd - 1; k >= 0; --k) {
    stride[k] = s;
    s *= as_uint(h[1 + 4 * k]);
  }
  uint base = 0;
  for (uint k = 0; k < nd; ++k) {
    global const float* ax = h + 1 + 4 * k;
    int ne = (int)as_uint(ax[0]);
    uint po = as_uint(ax[1]);
    rc_calc_real x;
    int i;
    if (po == 0xffffffffu) { /* evenly spaced: begin ax[2], extent ax[3] */
      x = (pt[k] - (rc_calc_real)ax[2]) / (rc_calc_real)ax[3] * (rc_calc_real)(ne - 1);
      i = x >= (rc_calc_real)0 ? (int)min(x, (rc_calc_real)(ne - 2)) : 0;
    } else { /* explicit points, ascending or descending: bisect as Radiance does */
      global const float* p = A + po;
      int lo = ax[3] > 0.0f ? 0 : ne, hi = ax[3] > 0.0f ? ne : 0;
      do {
        i = (lo + hi) >> 1;
        if (pt[k] >= (rc_calc_real)p[i])
          lo = i;
        else
          hi = i;
      } while (i != ((lo + hi) >> 1));
      if (i > ne - 2) i = ne - 2;
      x = (rc_calc_real)i + (pt[k] - (rc_calc_real)p[i]) / (rc_calc_real)(p[i + 1] - p[i]);
    }
    rc_calc_real fi = (rc_calc_real)i;
    if (x > fi + 2) { /* beyond one step past the upper end */
      rc_calc_real d = x - (fi - 1);
      w0[k] = -1 / d;
      w1[k] = 2 / d;
    } else if (x < fi - 1) { /* beyond one step before the lower end */
      rc_calc_real d = fi - x;
      w0[k] = 2 / d;
      w1[k] = -1 / d;
    } else {
      w0[k] = fi + 1 - x;
      w1[k] = x - fi;
    }
    base += (uint)i * stride[k];
  }
  rc_calc_real sum = 0;
  for (uint c = 0; c < (1u << nd); ++c) {
    rc_calc_real w = 1;
    uint idx = base;
    for (uint k = 0; k < nd; ++k) {
      if ((c >> k) & 1u) {
        w *= w1[k];
        idx += stride[k];
      } else {
        w *= w0[k];
      }
    }
    sum += w * (rc_calc_real)vals[idx];
  }
  return sum;
}

/* The values of a data pattern's data sets at its coordinates (for one data set, v[0] copied
 * to all three): x is its transform and descriptor in the argument buffer, e its ray variables.
 * Returns 0 after a compute error in a coordinate. */
static int rc_data_values(const rc_scene_args* S, const rc_pattern* pt, global const float* x,
                          rc_calc_env* e, rc_calc_real* v) {
  global const float* dsc = x + 25;
  uint n = min(as_uint(dsc[0]), (uint)RC_DATA_MAXDIM);
  rc_calc_real pnt[RC_DATA_MAXDIM];
  for (uint k = 0; k < n; ++k)
    pnt[k] = rc_pattern_call(as_uint(dsc[1 + k]), e);
  if (e->error) return 0;
  global const float* data = dsc + 1 + n;
  int one = pt->type == RC_OBJ_BRIGHTDATA || pt->type == RC_OBJ_MIXDATA;
  for (uint c = 0; c < 3; ++c)
    v[c] = c == 0 || !one ? rc_data_value(S->args, as_uint(data[c]), pnt) : v[0];
  return 1;
}

/* A data pattern at a hit whose ray variables are in e: x is its transform and descriptor in
 * the argument buffer. Multiplies *pcol or adds to *pert; a compute error changes nothing. */
static void rc_apply_data(const rc_scene_args* S, const rc_pattern* pt, global const float* x,
                          rc_calc_env* e, float3* pcol, float3* pert) {
  rc_calc_real v[3];
  if (!rc_data_values(S, pt, x, e, v)) return;
  if (pt->type == RC_OBJ_BRIGHTDATA) {
    float b = (float)rc_pattern_fcall(pt->func[0], e, v[0], v[0], v[1], v[2]);
    if (!e->error) *pcol *= b;
    return;
  }
  float3 r = (float3)((float)rc_pattern_fcall(pt->func[0], e, v[0], v[0], v[1], v[2]),
                      (float)rc_pattern_fcall(pt->func[1], e, v[1], v[0], v[1], v[2]),
                      (float)rc_pattern_fcall(pt->func[2], e, v[2], v[0], v[1], v[2]));
  if (e->error) return;
  if (pt->type == RC_OBJ_TEXDATA) { /* rotate into world space and scale as texfunc does */
    float3 f0 = (float3)(x[13], x[14], x[15]), f1 = (float3)(x[16], x[17], x[18]);
    float3 f2 = (float3)(x[19], x[20], x[21]);
    *pert += r.x * f0 + r.y * f1 + r.z * f2;
  } else {
    *pcol *= r;
  }
}

/* mixdata's coefficient, its function of the interpolated value, and mixpict's, its function
 * of the picture's colour (red alone for a function of fewer than 3 parameters). A compute
 * error sets e->error. */
static rc_calc_real rc_data_coef(const rc_scene_args* S, const rc_pattern* pt, rc_calc_env* e) {
  rc_calc_real v[3];
  if (!rc_data_values(S, pt, S->args + pt->xform, e, v)) return 0;
  return rc_pattern_fcall(pt->func[0], e, v[0], v[0], v[1], v[2]);
}
