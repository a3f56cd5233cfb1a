/* Virtual sources (images of sources in planar mirrors and prisms,
 * src/render/lights/virtual_sources.cpp): the way from a shading point to a virtual source must meet
 * the front of each mirror (either side of a prism) within its outline (Radiance's srcvalue()
 * for SVIRTUAL sources, then m_mirror() aiming on). A virtual source's geometry is already
 * mapped, so its sampling, horizon, spot and glow tests need nothing else. */
#ifndef RADCL_RENDER_VIRTUAL_CL
#define RADCL_RENDER_VIRTUAL_CL
#if defined(RADCL_HAS_PRISM1) || defined(RADCL_HAS_PRISM2)
#define RADCL_HAS_PRISM 1 /* relays of prisms (redirect > 0) in the programs that have them */
#endif

#include "radcl/device_types.h"

/* Whether the ray org + t dir (t > 0) meets the front of mirror m within its outline; *q is
 * where it meets the plane. */
static inline int rc_mirror_hit(global const rc_mirror* m, global const float4* verts, float3 org,
                                float3 dir, float3* q) {
  float3 n = m->plane.xyz;
  float dn = dot(dir, n);
  /* Parallel, or a mirror's back (which is black); a prism relays on either side. */
#ifdef RADCL_HAS_PRISM
  if (m->redirect ? fabs(dn) <= 1e-6f : dn >= -1e-6f) return 0;
#else
  if (dn >= -1e-6f) return 0;
#endif
  float t = (m->plane.w - dot(n, org)) / dn;
  if (!(t > 0.0f)) return 0;
  float3 x = org + t * dir;
  *q = x;
  if (m->nverts == 0u) { /* ring */
    float3 d = x - m->centre.xyz;
    float r2 = dot(d, d) - dot(d, n) * dot(d, n);
    return r2 <= m->centre.w * m->centre.w && r2 >= m->refl.w * m->refl.w;
  }
  /* Even-odd crossing test with the plane's most perpendicular axis dropped. */
  float3 an = fabs(n);
  int ax = an.y > an.x ? 1 : 0;
  if (an.z > (ax ? an.y : an.x)) ax = 2;
  float2 p = ax == 0 ? x.yz : (ax == 1 ? x.zx : x.xy);
  global const float4* v = verts + m->verts;
  uint nv = m->nverts;
  int in = 0;
  float4 a4 = v[nv - 1u];
  float2 a = ax == 0 ? a4.yz : (ax == 1 ? a4.zx : a4.xy);
  for (uint i = 0; i < nv; ++i) {
    float4 b4 = v[i];
    float2 b = ax == 0 ? b4.yz : (ax == 1 ? b4.zx : b4.xy);
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    a = b;
  }
  return in;
}

/* Product of the mirror reflectances on the way from p in direction l to source s, through
 * every mirror that relays it; 0 if the way misses one. */
static float3 rc_virtual_path(global const rc_source* sources, global const rc_mirror* mirrors,
                              global const float4* verts, global const rc_source* s, float3 p,
                              float3 l) {
  float3 f = (float3)(1.0f);
  for (uint relay = 0; relay < 64u && (s->flags & RC_SRCF_VIRTUAL); ++relay) {
    global const rc_mirror* m = mirrors + s->mirror;
    float3 q;
    if (!rc_mirror_hit(m, verts, p, l, &q)) return (float3)(0.0f);
#ifdef RADCL_HAS_PRISM
    /* A prism's coefficient and direction are known only at the point met: its shadow rays
     * follow the way (shadow_step.cl). */
    if (m->redirect) return f;
#endif
    f *= m->refl.xyz;
    l -= 2.0f * dot(l, m->plane.xyz) * m->plane.xyz;
    p = q;
    s = sources + s->parent;
  }
  return f;
}

#endif /* RADCL_RENDER_VIRTUAL_CL */
