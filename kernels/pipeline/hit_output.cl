/* Where a shaded hit writes its shadow requests and child rays (rc_out), and the rules by
 * which a child may live (Radiance's rayorigin). Included by shade.cl. */

/* Where one hit writes: counts in count mode, records in write mode. In write mode a hit
 * whose records outgrow their slots (cap_shadow, cap_spawn) stops writing and only counts:
 * the host shades it again with exact room. */
typedef struct rc_out {
  int write;
  uint nshadow, nspawn;
  uint cap_shadow, cap_spawn;
  global rc_shadow* shadows;
  global rc_ray* spawned;
  float3 immediate; /* contributions that need no shadow test (emission, ambient value) */
  float3 cext;      /* medium of the rays this hit spawns */
#ifdef RADCL_HAS_MEDIUM
  uint medium;   /* where its scattering albedo comes from (rc_ray.medium) */
  float3 albedo; /* that albedo (Radiance's r->albedo) */
  float gecc;    /* its scattering eccentricity (r->gecc) */
  uint slights;  /* the mist sources that scatter into those rays (r->slights) */
  float3 av;     /* the ambient value it scatters into rays (-av) */
#endif
  float wfac; /* extinction estimate on their weight (Radiance's rayorigin) */
  /* -as second pass: per-division super-sample counts of hemisphere `super_which` of this
   * ray ([0] = which, then ns * ns counts); only those samples are written. Else null. */
  global const uint* super;
  uint nhemi;   /* hemispheres sampled so far by this ray */
  uint cells;   /* whether it marked a hemisphere's samples for the host's -as tally (rc_ray.cell),
                   written or not: the host reads only such rays' children */
  uint child;   /* sample number of the next child (keys its random numbers) */
  float3 pcol;  /* patterns' colour at the hit (Radiance's r->pcol) */
  float3 pert;  /* textures' normal perturbation at the hit (r->pert), world space */
  uint newclip; /* antimatter: clip set of transmitted children (Radiance's newcset) */
  uint slots;   /* antimatter: crossing counters a transmission through the hit changes */
  int side;     /* and by how much: +1 through the front, -1 through the back */
  float dist;   /* length of the ray tree up to this hit (the ray's dist0 + t): where its
                   children and shadow rays start (rc_ray.dist0) */
  /* Cache records the host's leak tests rule out at this hit: [count, index...], or null. */
  global const uint* blocked;
  float3 ng; /* the hit's geometric normal: rays leave from beside the surface (rc_leave) */
  /* The hit reported a cache miss: the host shades its primary again once records exist and
   * drops this value, so its direct part (shadow rays, the bulk of a miss's cost) is skipped.
   * Its spawned rays stay: they may report misses of their own. */
  int doomed;
} rc_out;

static inline void rc_out_init(rc_out* o, int write) {
  o->write = write;
  o->nshadow = o->nspawn = 0;
  o->cap_shadow = o->cap_spawn = 0xFFFFFFFFu;
  o->immediate = (float3)(0.0f);
  o->cext = (float3)(0.0f);
#ifdef RADCL_HAS_MEDIUM
  o->albedo = o->av = (float3)(0.0f);
  o->medium = RC_MEDIUM_CLEAR;
  o->gecc = 0.0f;
  o->slights = 0u;
#endif
  o->wfac = 1.0f;
  o->super = 0;
  o->blocked = 0;
  o->ng = (float3)(0.0f);
  o->doomed = 0;
  o->nhemi = 0;
  o->cells = 0;
  o->child = 0;
  o->pcol = (float3)(1.0f);
  o->pert = (float3)(0.0f);
  o->newclip = 0u;
  o->slots = 0u;
  o->side = 0;
  o->dist = 0.0f;
}

/* Write mode ends for good once `shadows` more shadow records or `spawns` more children would
 * not fit: a partly written hit is rewritten in full later, so nothing may depend on it. */
static inline void rc_out_reserve(rc_out* o, uint shadows, uint spawns) {
  if (o->nshadow + shadows > o->cap_shadow || o->nspawn + spawns > o->cap_spawn) o->write = 0;
}

/* How far from surface point p (relative to the scene's centre) a ray leaving it starts: the
 * scene's floor (spec.z), or more where p's float rounding is coarser than that, so a 10 km
 * ground keeps a hair's breadth near its centre and only far out needs more. */
#define RC_LEAVE_REL 8e-7f
static inline float rc_leave_dist(float3 p, float eps) {
  float3 a = fabs(p);
  return fmax(eps, RC_LEAVE_REL * fmax(a.x, fmax(a.y, a.z)));
}

/* Where a ray leaving surface point p (geometric normal ng) along dir starts: that far off the
 * surface on the side it goes to, traced from there with no minimum distance (RC_TMIN_OFF).
 * Starting on the surface and skipping the first part of the way would also skip any other
 * surface that near the point, which lets light through closed corners. */
static inline float3 rc_leave(float3 p, float3 ng, float3 dir, float eps) {
  return p + ng * (dot(dir, ng) < 0.0f ? -rc_leave_dist(p, eps) : rc_leave_dist(p, eps));
}

/* A ray's origin and tmin as it leaves the hit `o` describes: beside a surface; from a -I meter
 * (no surface: ng = 0) at its point, skipping hits nearer than tmin (and what the geometry
 * adds for float rounding there), as Radiance skips FTINY: a meter placed on a surface sees
 * through it, one a millimetre from a fin sees the fin. */
static inline float4 rc_leave_org(const rc_out* o, float3 org, float3 dir, float tmin) {
  if (!(tmin > 0.0f)) return (float4)(org, tmin);
  if (all(o->ng == (float3)(0.0f))) return (float4)(org, tmin);
  return (float4)(rc_leave(org, o->ng, dir, tmin), RC_TMIN_OFF);
}

/* A shadow request from `org` (as rc_leave_org gives it) along dir up to tmax, having travelled
 * dist0 from its eye ray's origin, in the medium o holds. */
static inline void rc_emit_shadow_from(rc_out* o, float4 org, float3 dir, float tmax,
                                       float3 contrib, const rc_ray* r, uint source, float dist0) {
  if (o->super) return;
  rc_out_reserve(o, 1u, 0u);
  if (o->write) {
    rc_shadow s;
    s.org = org;
    s.dir = (float4)(dir, tmax);
    s.contrib = (float4)(contrib, 0.0f);
    /* The medium the shadow ray starts in (rc_shadow_ext: what it loses). */
#ifdef RADCL_HAS_MEDIUM
    s.cext = (float4)(o->cext, as_float(o->medium));
    s.slights_or_tested = o->slights;
#else
    s.cext = (float4)(o->cext, as_float(RC_MEDIUM_CLEAR));
    s.slights_or_tested = 0;
#endif
    s.crtype = rc_crtype(r->flags) & (RC_CR_AMBIENT | RC_CR_SPECULAR);
    s.dist0 = dist0;
    s.sdist0 = 0.0f;
    s.clip = r->clip;
    s.inside = r->inside;
    s.primary = r->primary;
    s.source = source;
    o->shadows[o->nshadow] = s;
  }
  o->nshadow++;
}

/* A shadow request leaving the surface point o is shading. */
static inline void rc_emit_shadow(rc_out* o, float3 org, float3 dir, float tmin, float tmax,
                                  float3 contrib, const rc_ray* r, uint source) {
  if (o->super) return;
  rc_emit_shadow_from(o, rc_leave_org(o, org, dir, tmin), dir, tmax, contrib, r, source, o->dist);
}

/* A child's random-number stream: mixes the parent's sample index with the child's number. */
static inline uint rc_child_sample(uint parent, uint child) {
  uint h = (parent ^ 0x9E3779B9u) * 0x85EBCA6Bu;
  h ^= h >> 13;
  h = (h + child * 0xC2B2AE35u) * 0x27D4EB2Fu;
  return h ^ (h >> 15);
}

/* Radiance's rayorigin() test for a child: the weight falls by the largest coefficient (at
 * most 1); reflections (not transmissions) count towards -lr; below -lw the ray dies, or with
 * -lr <= 0 plays Russian roulette and a survivor's coefficient is promoted. Returns the child's
 * weight (0: it dies) and sets its reflection depth. */
static inline float rc_child_weight_s(const rc_out* o, const rc_ray* parent, float3* coef,
                                      uint kind, const rc_params* P, rc_rng_stream* rs, uint dim,
                                      uint* depth) {
  float rw = fmin(rc_max3(*coef), 1.0f);
  float weight = parent->coef.w * rw * o->wfac;
  if (weight <= 0.0f) return 0.0f;
  *depth = parent->depth + (kind == RC_RAY_TRANSMITTED ? 0u : 1u);
  int lr = P->lr;
  float lw = P->av.w;
  if (lr <= 0) {
    if (lr < 0 && *depth > (uint)(-lr)) return 0.0f;
    if (weight < lw) {
      if (rc_stream_random(rs, dim) > weight / lw) return 0.0f;
      *coef *= lw / weight;
      weight = lw;
    }
  } else if (weight < lw || *depth > (uint)lr) {
    return 0.0f;
  }
  return weight;
}

static inline float rc_child_weight(const rc_out* o, const rc_ray* parent, float3* coef, uint kind,
                                    const rc_params* P, rc_rng_key key, uint dim, uint* depth) {
  rc_rng_stream rs = rc_stream(key); /* no block drawn unless the roulette needs one */
  return rc_child_weight_s(o, parent, coef, kind, P, &rs, dim, depth);
}

/* Writes (or counts) a child that passed rc_child_weight. */
static inline void rc_emit_ray(rc_out* o, const rc_ray* parent, float3 org, float3 dir, float3 coef,
                               uint kind, float tmin, float weight, uint depth,
                               uint ambient_depth) {
  rc_out_reserve(o, 0u, 1u);
  if (o->write) {
    rc_ray r;
    r.org = rc_leave_org(o, org, dir, tmin);
    r.dir = (float4)(dir, INFINITY);
    r.coef = (float4)(parent->coef.xyz * coef, weight);
    r.primary = parent->primary;
    r.tally = parent->tally;
    /* Reflections (and shadow rays) keep the clip set of the surface point; transmissions take
     * the one beyond it and count their crossing of listed surfaces. */
    r.clip = parent->clip;
    r.inside = parent->inside;
#ifdef RADCL_HAS_ANTIMATTER
    if (kind == RC_RAY_TRANSMITTED) {
      r.clip = o->newclip;
      r.inside = rc_inside_add(parent->inside, o->slots, o->side);
    }
#endif
    r.cell = 0;
    r.depth = depth;
    r.flags = (kind | rc_crtype(parent->flags)) & ~RC_RAY_ROOT;
    uint pk = parent->flags & RC_RAY_KIND_MASK;
    int root = pk == RC_RAY_PRIMARY || (parent->flags & RC_RAY_ROOT) != 0u;
    if (kind == RC_RAY_REFLECTED && root) r.flags |= RC_RAY_MIRRORED;
    /* Only an unbroken chain of transmissions from the primary keeps the "through" bit. */
    if (kind == RC_RAY_TRANSMITTED &&
        (root || (pk == RC_RAY_TRANSMITTED && (parent->flags & RC_RAY_THROUGH))))
      r.flags |= RC_RAY_THROUGH;
    else
      r.flags &= ~RC_RAY_THROUGH;
    r.sample = rc_child_sample(parent->sample, o->child);
    r.ambient_depth = ambient_depth;
    r.cext_r = o->cext.x;
    r.cext_g = o->cext.y;
    r.cext_b = o->cext.z;
    r.dist0 = o->dist;
#ifdef RADCL_HAS_MEDIUM
    r.medium = o->medium;
    r.gecc = o->gecc;
    r.slights = o->slights;
#else
    r.medium = RC_MEDIUM_CLEAR;
    r.gecc = 0.0f;
    r.slights = 0u;
#endif
    o->spawned[o->nspawn] = r;
  }
  o->nspawn++;
  o->child++;
}

/* Spawns a child ray if rayorigin()'s rules let it live (its roulette number: dimension dim
 * of the stream). */
static inline void rc_spawn_s(rc_out* o, const rc_ray* parent, float3 org, float3 dir, float3 coef,
                              uint kind, float tmin, const rc_params* P, rc_rng_stream* rs,
                              uint dim, uint ambient_depth) {
  if (o->super) return; /* the -as pass writes only its super-samples */
  uint depth;
  float weight = rc_child_weight_s(o, parent, &coef, kind, P, rs, dim, &depth);
  if (weight > 0.0f)
    rc_emit_ray(o, parent, org, dir, coef, kind, tmin, weight, depth, ambient_depth);
  else
    o->child++;
}

static inline void rc_spawn(rc_out* o, const rc_ray* parent, float3 org, float3 dir, float3 coef,
                            uint kind, float tmin, const rc_params* P, rc_rng_key key, uint dim,
                            uint ambient_depth) {
  rc_rng_stream rs = rc_stream(key);
  rc_spawn_s(o, parent, org, dir, coef, kind, tmin, P, &rs, dim, ambient_depth);
}
