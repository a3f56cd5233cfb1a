/* Shadow rays through transmitting surfaces (Radiance traces them on like any ray, with the
 * material's transmission coefficient, only along pure transmission or refraction). One step
 * per shadow ray still under way: the host found its next hit; this decides whether it reached
 * its source, is blocked, or continues beyond the surface with a reduced contribution.
 * Included at the end of shade.cl, whose scene arguments (RC_SCENE_PARAMS) it takes. */
#define RC_SH_BLOCKED 0u
#define RC_SH_REACHED 1u
#define RC_SH_CONTINUE 2u
#define RC_SH_STATUS 3u
#define RC_SH_BENT 4u  /* direction changed by refraction: the source must be re-checked */
#define RC_SH_LATER 8u /* not the first segment */

RC_NOINLINE
static uint rc_shadow_at(const rc_scene_args* S, rc_shadow* s, const rc_hit* h, uint state) {
  const rc_params* P = &S->params;
  global const rc_source* src = S->sources + s->source;
  float3 d = s->dir.xyz;
  float3 cext = s->cext.xyz; /* the medium it travels in: extinction, albedo's source, sources */
  uint med = as_uint(s->cext.w), slights = s->pad0;
  int distant = src->kind == RC_SRC_DISTANT;
  if (src->flags & RC_SRCF_VIRTUAL) {
    /* Aimed at a source's image: it must meet the mirror's front (within its outline, which
     * is what Embree hit), then, if the pretest asked for it, go on to the imaged source. */
    if (h->pos.w < 0.0f || h->surface == RC_NONE) return RC_SH_BLOCKED;
    if (h->surface == src->surface) {
#ifdef RADCL_HAS_PRISM
      uint k = S->mirrors[src->mirror].redirect;
      if (k) { /* a prism, either side: on in its redirection toward the source imaged */
        global const rc_source* to = S->sources + src->parent;
        float3 toward =
            to->kind == RC_SRC_DISTANT ? to->pos.xyz : normalize(to->pos.xyz - h->pos.xyz);
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
#ifdef RADCL_HAS_ANTIMATTER
  /* Shadow rays see clipped surfaces and antimatter boundaries as other rays do; going on
   * beyond the surface is a transmission, which updates their antimatter state. */
  invisible |= (surf.clip & s->clip) != 0u;
  uint next_clip = s->clip;
  uint next_inside = rc_inside_add(s->inside, surf.slots, h->front ? 1 : -1);
  rc_hit flipped = *h;
#endif
  if (!invisible && !distant && h->surface == src->surface) {
    s->contrib.xyz *= rc_ext(rc_shadow_ext(S, cext, med), t);
    return RC_SH_REACHED;
  }
  float3 coef = (float3)(1.0f);
  float3 next_cext = cext;
  uint next_med = med, next_slights = slights;
  int pass = 1;
  if (!invisible) {
    rc_material m = S->materials[surf.material];
#ifdef RADCL_HAS_ANTIMATTER
    if (m.type == RC_OBJ_ANTIMATTER) {
      global const float* a = S->args + m.args;
      next_clip = rc_antimatter_clip(a, s->clip, h->front);
      if (rc_antimatter_shades(&m, a, s->inside)) { /* mod1's material, facing the ray */
        m = S->materials[m.alt];
        flipped.nrm = -flipped.nrm;
        flipped.pert = -flipped.pert; /* flipsurface turns the perturbation too */
        flipped.front = !flipped.front;
        h = &flipped;
      }
    }
#endif
#ifdef RADCL_HAS_MIRROR
    /* Another mirror (or this one aimed elsewhere) with an alternate: as for other rays, the
     * alternate decides, unless an ambient or specular ray's shadow meets its front (then, as
     * without one, the mirror blocks it). A `void` alternate lets it through (the switch). */
    int mirror_alt = m.type == RC_OBJ_MIRROR && m.alt != RC_NONE && !(h->front && s->crtype);
    if (mirror_alt && m.alt != RC_ALT_VOID) m = S->materials[m.alt];
#endif
    if (m.type == RC_OBJ_ILLUM) {
      /* An illum or glow source is not seen through the front of another illum. */
      if (src->surface != RC_NONE && (src->flags & (RC_SRCF_ILLUM | RC_SRCF_GLOW)) && h->front)
        return RC_SH_BLOCKED;
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
        cext = f.cext_in;
        med = RC_MEDIUM_CLEAR;
      }
    }
#endif
    next_cext = cext;
    next_med = med;
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
      coef = rc_shadow_mix(S, &m, d, h);
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
      float cos1 = rc_raynormal(n, h->front ? pert : -pert, d, -dot(d, n), &pn);
      rc_ward_iso w = rc_trans_setup((float3)(a[0], a[1], a[2]) * pcol, a, cos1);
      if (!rc_trans_pure(&w)) return RC_SH_BLOCKED;
      coef = w.tcolor * w.tspec;
      break;
    }
#endif
#ifdef RADCL_HAS_GLASS
    case RC_OBJ_GLASS: {
      if (back_pass) break;
      rc_glass g = rc_glass_hit(a, m.nargs, d, n, h->front ? pert : -pert); /* goes on straight */
      if (!g.hastrans) return RC_SH_BLOCKED;
      coef = g.trans * pcol;
      break;
    }
#endif
#ifdef RADCL_HAS_FUNC_MATERIALS
    case RC_OBJ_BRTDFUNC: /* its transmission expressions, on either side */
      if (!rc_brtdfunc_shadow(S, &m, d, h, pcol, pert, &coef)) return RC_SH_BLOCKED;
      break;
#endif
#ifdef RADCL_HAS_BSDF_MATERIALS
    case RC_OBJ_BSDF:
    case RC_OBJ_ABSDF: /* a proxy or aBSDF's through component; the back side as -bv says */
      if (back_pass) break;
      if (!rc_bsdf_shadow(S, &m, h, d, pcol, pert, &coef)) return RC_SH_BLOCKED;
      break;
#endif
#if defined(RADCL_HAS_DIELECTRIC) || defined(RADCL_HAS_INTERFACE)
    case RC_OBJ_DIELECTRIC:
    case RC_OBJ_INTERFACE: {
      rc_refraction f = rc_refract_tex(m.type, a, d, h->nrm.xyz, pert);
      if (f.trans <= 0.0f) return RC_SH_BLOCKED; /* total internal reflection */
      coef = (float3)(f.trans);
      next_cext = f.cext_out;
      next_med = RC_MEDIUM_CLEAR;
#ifdef RADCL_HAS_MEDIUM
      if (f.to_global) {
        next_cext = P->medium.xyz;
        next_med = RC_MEDIUM_GLOBAL;
      }
#endif
      if (any(f.tdir != d)) {
        d = f.tdir;
        state |= RC_SH_BENT;
      }
      break;
    }
#endif
#ifdef RADCL_HAS_MIST
    case RC_OBJ_MIST: { /* on through, in the medium beyond (mist.cl) */
      rc_mist_medium in;
      in.cext = cext;
      in.medium = med;
      in.gecc = 0.0f;
      in.slights = slights;
      rc_mist_medium out = rc_mist_cross(S, m.args, pcol, h->front, &in);
      cext = in.cext;
      med = in.medium;
      next_cext = out.cext;
      next_med = out.medium;
      next_slights = out.slights;
      break;
    }
#endif
    default:
      pass = 0;
      break;
    }
  }
  if (!pass || rc_max3(coef) <= 0.0f) return RC_SH_BLOCKED;
  float3 c = s->contrib.xyz * rc_ext(rc_shadow_ext(S, cext, med), t) * coef;
  if (rc_max3(c) <= 0.0f) return RC_SH_BLOCKED;
  s->org = (float4)(rc_leave(h->pos.xyz, h->nrm.xyz, d, P->spec.z), RC_TMIN_OFF);
  /* A straight ray still has the rest of the way to a local source; a bent one goes on until
   * it meets something. */
  float rest = (state & RC_SH_BENT) ? INFINITY : s->dir.w - t;
  s->dir = (float4)(d, distant ? s->dir.w : rest);
  s->contrib = (float4)(c, 0.0f);
  s->cext = (float4)(next_cext, as_float(next_med));
#ifdef RADCL_HAS_MIST
  s->pad0 = next_slights;
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
