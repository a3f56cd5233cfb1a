/* antimatter (../shared/docs/radiance/scene-format.md §3.16): a closed volume inside which surfaces
 * of the listed modifiers are invisible. A ray carries the set of clipped modifiers it is inside
 * (rc_ray.clip, one bit per modifier the scene's antimatters list) and, for each antimatter that
 * shades its boundary with a material (mod1), a count of how often its ancestry crossed a listed
 * surface by transmission: in through a front side +1, out through a back side -1 (rc_ray.inside,
 * four signed bytes). Arguments as the scene compiler writes them: the list's bits as two 16-bit
 * halves (floats hold integers exactly only up to 2^24), then the counter slot (-1: none).
 * rc_material.alt is mod1's material (RC_NONE: the boundary is invisible). */

static inline uint rc_antimatter_mask(global const float* a) {
  return (uint)a[0] | ((uint)a[1] << 16);
}

/* The clip set beyond the boundary: entering (hit from the front) adds the list, leaving
 * removes it. */
static inline uint rc_antimatter_clip(global const float* a, uint clip, int front) {
  uint mask = rc_antimatter_mask(a);
  return front ? (clip | mask) : (clip & ~mask);
}

static inline int rc_inside_count(uint inside, uint slot) {
  return (int)(char)((inside >> (8u * slot)) & 0xFFu);
}

/* Adds `step` to the counters of `slots` (bit k: counter k), saturating at the byte's range. */
static inline uint rc_inside_add(uint inside, uint slots, int step) {
  for (uint k = 0; k < 4u; ++k) {
    if (!(slots & (1u << k))) continue;
    int c = clamp(rc_inside_count(inside, k) + step, -127, 127);
    inside = (inside & ~(0xFFu << (8u * k))) | (((uint)c & 0xFFu) << (8u * k));
  }
  return inside;
}

/* Whether a ray with counters `inside` meeting this antimatter's boundary sees mod1 there:
 * its ancestry entered one of the clipped objects more often than it left. */
static inline int rc_antimatter_shades(const rc_material* m, global const float* a, uint inside) {
  if (m->alt == RC_NONE || a[2] < 0.0f) return 0;
  return rc_inside_count(inside, (uint)a[2]) > 0;
}
