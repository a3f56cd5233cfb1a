/* brighttext, colortext and mixtext (../shared/docs/radiance/scene-format.md §4, §4.2): whether a
 * hit lies inside a glyph of the pattern's text, laid out by the host
 * (include/radcl/render/compile/text_pattern.h). */

/* Whether (x, y), in glyph units of a 256 x 256 cell, is inside glyph g: the glyph's extent,
 * then the parity of the edges crossed by a ray along +x. Edges are taken to straddle the
 * ray when they cross the middle of the unit row holding y, and the half-unit offsets keep
 * vertices off the ray; the side an edge passes on is decided with the exact point. */
static int rc_text_glyph(global const float* g, float x, float y) {
  int n = (int)g[0];
  int xl = (int)x, yl = (int)y;
  if ((int)g[1] > xl || (int)g[2] <= xl || (int)g[3] > yl || (int)g[4] <= yl || n <= 0) return 0;
  int xh = 2 * xl + 1, yh = 2 * yl + 1;
  global const float* v = g + 5;
  int x0 = (int)v[2 * n - 2], y0 = (int)v[2 * n - 1];
  int crossings = 0;
  for (int k = 0; k < n; ++k) {
    int x1 = (int)v[2 * k], y1 = (int)v[2 * k + 1];
    if ((2 * y0 > yh) != (2 * y1 > yh)) {
      int right = (2 * x0 > xh) | ((2 * x1 > xh) << 1);
      if (right == 3)
        ++crossings;
      else if (right)
        crossings +=
            (y1 > y0) ^ (((float)y0 - y) * ((float)x1 - x) > ((float)x0 - x) * ((float)y1 - y));
    }
    x0 = x1;
    y0 = y1;
  }
  return crossings & 1;
}

/* Whether point p (pattern coordinates) is inside the text whose descriptor is t. */
static int rc_text_inside(global const float* A, global const float* t, float3 p) {
  float3 v = p - (float3)(t[0], t[1], t[2]);
  float x = dot(v, (float3)(t[3], t[4], t[5])) * t[9]; /* glyph units along the line */
  float y = dot(v, (float3)(t[6], t[7], t[8]));        /* lines down from the top */
  uint nlines = as_uint(t[16]);
  if (!(x >= 0.0f) || !(y >= 0.0f) || y >= (float)nlines) return 0;
  int line = (int)y;
  global const float* l = A + as_uint(t[17 + line]);
  if (x >= l[0]) return 0; /* past the line's width */
  int h = (int)x;
  float fx = x - (float)h;
  float gy = ((float)(line + 1) - y) * 255.0f;
  uint n = as_uint(l[1]);
  /* Step through the characters' cells; overlapping glyphs each get their test. */
  for (uint i = 0; i < n; ++i) {
    h -= (int)l[2 + 2 * i];
    if (h < 0) break;
    uint g = as_uint(l[3 + 2 * i]);
    if (h < 255 && g != 0xffffffffu && rc_text_glyph(A + g, (float)h + fx, gy)) return 1;
  }
  return 0;
}

/* Whether a hit is inside the text of pattern pt (x: its transform, then its descriptor). A
 * hit on a distant source has no point: it sees the background. */
static int rc_text_hit(const rc_scene_args* S, global const float* x, const rc_hit* h) {
  if (h->pos.w < 0.0f) return 0;
  float3 r0 = (float3)(x[0], x[1], x[2]), r1 = (float3)(x[3], x[4], x[5]);
  float3 r2 = (float3)(x[6], x[7], x[8]), tr = (float3)(x[9], x[10], x[11]);
  float3 p = h->pos.x * r0 + h->pos.y * r1 + h->pos.z * r2 + tr;
  return rc_text_inside(S->args, x + 25, p);
}

/* brighttext and colortext: multiply *pcol by the foreground or background colour. */
static void rc_apply_text(const rc_scene_args* S, global const float* x, const rc_hit* h,
                          float3* pcol) {
  global const float* t = x + 25;
  *pcol *= rc_text_hit(S, x, h) ? (float3)(t[10], t[11], t[12]) : (float3)(t[13], t[14], t[15]);
}
