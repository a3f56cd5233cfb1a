/* Shadow rays through transmitting surfaces (Radiance traces them on like any ray, with the
 * material's transmission coefficient, only along pure transmission or refraction). One step
 * per shadow ray still under way: the host found its next hit; this decides whether it reached
 * its source, is blocked, or continues beyond the surface with a reduced contribution.
 * Included at the end of shade.cl, whose scene arguments (RC_SCENE_PARAMS) it takes. */
/* Its answers are the RC_SH_* codes of radcl/device_types.h, which the host reads too. */

/* Where a shadow ray goes on beyond a surface it passes: its direction, the medium it
 * travelled in (cext, med: a dielectric met from inside or a mist changes what it was) and the
 * one beyond, its mist sources, the transmission, and its state (RC_SH_BENT). */
typedef struct rc_shadow_way {
  float3 d, cext, next_cext, coef;
  uint med, next_med, next_slights, state;
} rc_shadow_way;

/* A ray aimed at a source's image has met the mirror or prism that makes it (Embree hit it
 * within its outline): on to the imaged source through a prism's redirection, or reflected by
 * the mirror's front where the pretest asked it to follow the whole way. */
static uint rc_shadow_at_image(const rc_scene_args* S, rc_shadow* s, const rc_hit* h, uint state,
                               global const rc_source* src, float3 d, float3 cext, uint med,
                               int distant) {
  const rc_params* P = &S->params;
#ifdef RADCL_HAS_PRISM
  uint k = S->mirrors[src->mirror].redirect;
  if (k) { /* a prism, either side: on in its redirection toward the source imaged */
    global const rc_source* to = S->sources + src->parent;
    float3 toward = to->kind == RC_SRC_DISTANT ? to->pos.xyz : normalize(to->pos.xyz - h->pos.xyz);
    rc_material m = S->materials[S->surfaces[h->surface].material];
    float3 nd;
    float c = rc_redirect(S, &m, h, d, toward, k - 1u, &nd);
    if (!(c > 0.0f)) return RC_SH_BLOCKED;
    float t = h->pos.w;
    s->contrib.xyz *= c * rc_ext(rc_shadow_ext(S, cext, med), t);
    s->org = (float4)(rc_leave(h->pos.xyz, h->nrm.xyz, nd, P->spec.z), RC_TMIN_OFF);
    s->dist0 += t;
    s->sdist0 += t;
    s->dir = (float4)(nd, distant ? s->dir.w : INFINITY);
    s->source = src->parent;
    return (state & ~RC_SH_STATUS) | RC_SH_LATER | RC_SH_BENT | RC_SH_CONTINUE;
  }
#endif
  if (!h->front) return RC_SH_BLOCKED;
  float t = h->pos.w;
  s->contrib.xyz *= rc_ext(rc_shadow_ext(S, cext, med), t);
  if (!(src->flags & RC_SRCF_FOLLOW)) return RC_SH_REACHED;
  float3 n = h->nrm.xyz, rd = d - 2.0f * dot(d, n) * n;
  s->org = (float4)(rc_leave(h->pos.xyz, n, rd, P->spec.z), RC_TMIN_OFF);
  s->dist0 += t;
  s->sdist0 += t;
  s->dir = (float4)(rd, distant ? s->dir.w : s->dir.w - t);
  s->source = src->parent;
  return (state & ~RC_SH_STATUS) | RC_SH_LATER | RC_SH_CONTINUE;
}

/* What a shadow ray takes through the material m it passes (rc_shadow_through has applied its
 * alternates, patterns and medium): 0 if m blocks it, else way->coef, the medium beyond and the
 * new direction in `way`. */
static int rc_shadow_transmission(const rc_scene_args* S, const rc_material* mp, const rc_hit* h,
                                  float3 pcol, float3 pert, int mirror_alt, rc_shadow_way* way) {
  const rc_params* P = &S->params;
  rc_material m = *mp;
  int pass = 1;
  way->coef = (float3)(1.0f);
  way->next_cext = way->cext;
  way->next_med = way->med;
  int back_pass = !h->front && !(P->flags & RC_PF_BV);
  float3 n = h->front ? h->nrm.xyz : -h->nrm.xyz;
  global const float* a = S->args + m.args;
  switch (m.type) {
  case RC_OBJ_ILLUM: /* without an alternate: invisible */
    break;
#ifdef RADCL_HAS_MIRROR
  case RC_OBJ_MIRROR: /* blocks, unless its alternate is `void` */
    pass = mirror_alt && m.alt == RC_ALT_VOID;
    break;
#endif
#ifdef RADCL_HAS_MIXFUNC
  case RC_OBJ_MIXFUNC:
    way->coef = rc_shadow_mix(S, &m, way->d, h);
    break;
#endif
#ifdef RADCL_HAS_ANTIMATTER
  case RC_OBJ_ANTIMATTER: /* a boundary without mod1 here */
    break;
#endif
#ifdef RADCL_HAS_TRANS
  case RC_OBJ_TRANS: {
    if (back_pass) break;
    float3 pn; /* m_normal's Fresnel term takes the tilted normal's cosine */
    float cos1 = rc_raynormal(n, h->front ? pert : -pert, way->d, -dot(way->d, n), &pn);
    rc_ward_iso w = rc_trans_setup((float3)(a[0], a[1], a[2]) * pcol, a, cos1);
    if (!rc_trans_pure(&w)) return 0;
    way->coef = w.tcolor * w.tspec;
    break;
  }
#endif
#ifdef RADCL_HAS_GLASS
  case RC_OBJ_GLASS: {
    if (back_pass) break;
    rc_glass g =
        rc_glass_hit(a, m.nargs, way->d, n, h->front ? pert : -pert); /* goes on straight */
    if (!g.hastrans) return 0;
    way->coef = g.trans * pcol;
    break;
  }
#endif
#ifdef RADCL_HAS_FUNC_MATERIALS
  case RC_OBJ_BRTDFUNC: /* its transmission expressions, on either side */
    if (!rc_brtdfunc_shadow(S, &m, way->d, h, pcol, pert, &way->coef)) return 0;
    break;
#endif
#ifdef RADCL_HAS_BSDF_MATERIALS
  case RC_OBJ_BSDF:
  case RC_OBJ_ABSDF: /* a proxy or aBSDF's through component; the back side as -bv says */
    if (back_pass) break;
    if (!rc_bsdf_shadow(S, &m, h, way->d, pcol, pert, &way->coef)) return 0;
    break;
#endif
#if defined(RADCL_HAS_DIELECTRIC) || defined(RADCL_HAS_INTERFACE)
  case RC_OBJ_DIELECTRIC:
  case RC_OBJ_INTERFACE: {
    rc_refraction f = rc_refract_tex(m.type, a, way->d, h->nrm.xyz, pert);
    if (f.trans <= 0.0f) return 0; /* total internal reflection */
    way->coef = (float3)(f.trans);
    way->next_cext = f.cext_out;
    way->next_med = RC_MEDIUM_CLEAR;
#ifdef RADCL_HAS_MEDIUM
    if (f.to_global) {
      way->next_cext = P->medium.xyz;
      way->next_med = RC_MEDIUM_GLOBAL;
    }
#endif
    if (any(f.tdir != way->d)) {
      way->d = f.tdir;
      way->state |= RC_SH_BENT;
    }
    break;
  }
#endif
#ifdef RADCL_HAS_MIST
  case RC_OBJ_MIST: { /* on through, in the medium beyond (mist.cl) */
    rc_mist_medium in;
    in.cext = way->cext;
    in.medium = way->med;
    in.gecc = 0.0f;
    in.slights = way->next_slights;
    rc_mist_medium out = rc_mist_cross(S, m.args, pcol, h->front, &in);
    way->cext = in.cext;
    way->med = in.medium;
    way->next_cext = out.cext;
    way->next_med = out.medium;
    way->next_slights = out.slights;
    break;
  }
#endif
  default:
    pass = 0;
    break;
  }
  return pass;
}

/* The material a shadow ray met on its way (not its source): 0 if it blocks the ray, else the
 * ray goes on through it with its contribution times way->coef, in the medium beyond, perhaps
 * bent (RC_SH_BENT in way->state). An antimatter boundary that shows its mod1 turns the hit *hp
 * around. */
static int rc_shadow_through(const rc_scene_args* S, const rc_shadow* s,
                             global const rc_source* src, const rc_surface* surf, rc_hit* hp,
                             rc_shadow_way* way, uint* next_clip) {
  const rc_params* P = &S->params;
  const rc_hit* h = hp;
  float3 d = way->d;
  rc_material m = S->materials[surf->material];
#ifdef RADCL_HAS_ANTIMATTER
  if (m.type == RC_OBJ_ANTIMATTER) {
    global const float* a = S->args + m.args;
    *next_clip = rc_antimatter_clip(a, s->clip, h->front);
    if (rc_antimatter_shades(&m, a, s->inside)) { /* mod1's material, facing the ray */
      m = S->materials[m.alt];
      hp->nrm = -hp->nrm;
      hp->pert = -hp->pert; /* flipsurface turns the perturbation too */
      hp->front = !hp->front;
    }
  }
#endif
  int mirror_alt = 0;
#ifdef RADCL_HAS_MIRROR
  /* Another mirror (or this one aimed elsewhere) with an alternate: as for other rays, the
   * alternate decides, unless an ambient or specular ray's shadow meets its front (then, as
   * without one, the mirror blocks it). A `void` alternate lets it through (the switch). */
  mirror_alt = m.type == RC_OBJ_MIRROR && m.alt != RC_NONE && !(h->front && s->crtype);
  if (mirror_alt && m.alt != RC_ALT_VOID) m = S->materials[m.alt];
#endif
  if (m.type == RC_OBJ_ILLUM) {
    /* An illum or glow source is not seen through the front of another illum. */
    if (src->surface != RC_NONE && (src->flags & (RC_SRCF_ILLUM | RC_SRCF_GLOW)) && h->front)
      return 0;
    if (m.alt != RC_NONE) m = S->materials[m.alt];
  }
  /* The shadow ray's own r->pert (o_mesh: a smoothed mesh's tilt), then the patterns'. */
  float3 pcol = (float3)(1.0f), pert = h->pert.xyz;
#ifdef RADCL_HAS_PATTERNS
  if (m.npatterns) rc_apply_patterns(S, &m, d, h, &pcol, &pert);
#endif
#if defined(RADCL_HAS_DIELECTRIC) || defined(RADCL_HAS_INTERFACE)
  if (rc_is_dielectric(m.type)) { /* from inside: it travelled in the dielectric's medium */
    rc_refraction f = rc_refract(m.type, S->args + m.args, d, h->nrm.xyz);
    if (f.set_medium) {
      way->cext = f.cext_in;
      way->med = RC_MEDIUM_CLEAR;
    }
  }
#endif
  return rc_shadow_transmission(S, &m, h, pcol, pert, mirror_alt, way);
}

RC_NOINLINE
static uint rc_shadow_at(const rc_scene_args* S, rc_shadow* s, const rc_hit* h, uint state) {
  const rc_params* P = &S->params;
  global const rc_source* src = S->sources + s->source;
  float3 d = s->dir.xyz;
  float3 cext = s->cext.xyz; /* the medium it travels in: extinction, albedo's source, sources */
  uint med = as_uint(s->cext.w), slights = s->slights_or_tested;
  int distant = src->kind == RC_SRC_DISTANT;
  if (src->flags & RC_SRCF_VIRTUAL) {
    /* Aimed at a source's image: it must meet the mirror's front (within its outline, which
     * is what Embree hit), then, if the pretest asked for it, go on to the imaged source. */
    if (h->pos.w < 0.0f || h->surface == RC_NONE) return RC_SH_BLOCKED;
    if (h->surface == src->surface)
      return rc_shadow_at_image(S, s, h, state, src, d, cext, med, distant);
  } else if (h->pos.w < 0.0f || h->surface == RC_NONE) { /* nothing local hit */
    if (distant) {
      if ((state & RC_SH_BENT) && 2.0f * M_PI_F * (1.0f - dot(src->pos.xyz, d)) > src->axis.w)
        return RC_SH_BLOCKED; /* refracted away from the source */
      s->contrib.xyz *= rc_ext(rc_shadow_ext(S, cext, med), -1.0f);
      return RC_SH_REACHED;
    }
    /* Radiance lets an aimed ray that meets nothing count; a traced one that misses not. */
    return (state & RC_SH_LATER) ? RC_SH_BLOCKED : RC_SH_REACHED;
  }
  float t = h->pos.w;
  rc_surface surf = S->surfaces[h->surface];
  int invisible = surf.material == RC_NONE;
  uint next_clip = s->clip;
#ifdef RADCL_HAS_ANTIMATTER
  /* Shadow rays see clipped surfaces and antimatter boundaries as other rays do; going on
   * beyond the surface is a transmission, which updates their antimatter state. */
  invisible |= (surf.clip & s->clip) != 0u;
  uint next_inside = rc_inside_add(s->inside, surf.slots, h->front ? 1 : -1);
#endif
  if (!invisible && !distant && h->surface == src->surface) {
    s->contrib.xyz *= rc_ext(rc_shadow_ext(S, cext, med), t);
    return RC_SH_REACHED;
  }
  rc_shadow_way w;
  w.d = d;
  w.cext = w.next_cext = cext;
  w.med = w.next_med = med;
  w.next_slights = slights;
  w.coef = (float3)(1.0f);
  w.state = state;
  rc_hit at = *h;
  if (!invisible && !rc_shadow_through(S, s, src, &surf, &at, &w, &next_clip)) return RC_SH_BLOCKED;
  h = &at;
  d = w.d;
  state = w.state;
  if (rc_max3(w.coef) <= 0.0f) return RC_SH_BLOCKED;
  float3 c = s->contrib.xyz * rc_ext(rc_shadow_ext(S, w.cext, w.med), t) * w.coef;
  if (rc_max3(c) <= 0.0f) return RC_SH_BLOCKED;
  s->org = (float4)(rc_leave(h->pos.xyz, h->nrm.xyz, d, P->spec.z), RC_TMIN_OFF);
  /* A straight ray still has the rest of the way to a local source; a bent one goes on until
   * it meets something. */
  float rest = (state & RC_SH_BENT) ? INFINITY : s->dir.w - t;
  s->dir = (float4)(d, distant ? s->dir.w : rest);
  s->contrib = (float4)(c, 0.0f);
  s->cext = (float4)(w.next_cext, as_float(w.next_med));
#ifdef RADCL_HAS_MIST
  s->slights_or_tested = w.next_slights;
#endif
  s->dist0 += t;
  s->sdist0 += t;
#ifdef RADCL_HAS_ANTIMATTER
  s->clip = next_clip;
  s->inside = next_inside;
#endif
  return (state & ~RC_SH_STATUS) | RC_SH_LATER | RC_SH_CONTINUE;
}

/* Step i of the rays still under way: the request at slots[i] (in place, in the packed
 * requests), its hit hits[i]; a ray that goes on writes its new view (shade.cl's
 * rc_shadow_view_of) at view[2i] for its next trace, one that reaches its source clears
 * blocked[slots[i]] (rc_accumulate reads it there, with no trip through the host). */
kernel void rc_shadow_step(global rc_shadow* shadows, global const uint* slots,
                           global const rc_hit* hits, global uint* state, global float4* view,
                           global uchar* blocked, uint n, RC_SCENE_PARAMS) {
  uint i = get_global_id(0);
  if (i >= n) return;
  RC_SCENE_INIT
  uint j = slots[i];
  rc_shadow s = shadows[j];
  rc_hit h = hits[i];
  h.uv.z = s.dist0; /* T and Ts of patterns met on the way (patterns.cl) */
  h.uv.w = s.sdist0;
  uint st = rc_shadow_at(&S, &s, &h, state[i]);
  shadows[j] = s;
  state[i] = st;
  if ((st & RC_SH_STATUS) == RC_SH_REACHED) blocked[j] = 0;
  if ((st & RC_SH_STATUS) == RC_SH_CONTINUE) rc_shadow_view_of(&s, sources, view + 2 * (ulong)i);
}
