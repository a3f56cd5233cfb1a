/* Fills buffers with the counter-based generator so the host can check it bit for bit. Item i
 * uses key (primary = i, sample = i / 7, depth = i % 5, seed). */
#include "radcl/rng.h"

kernel void rc_rng_fill(global uint* bits, global float* unit, uint n, uint dims, uint seed) {
  uint i = get_global_id(0);
  if (i >= n) return;
  rc_rng_key key = rc_make_key(i, i / 7u, i % 5u, seed);
  for (uint d = 0; d < dims; ++d) {
    rc_u32x4 b = rc_random_bits(key, d >> 2);
    bits[i * dims + d] = b.v[d & 3u];
    unit[i * dims + d] = rc_random(key, d);
  }
}
