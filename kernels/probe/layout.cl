/* Reports the device's view of every shared struct: sizes in RADCL_LAYOUT_STRUCTS order, then
 * field offsets in RADCL_LAYOUT_FIELDS order. The host compares them with its own. */
#include "radcl/device_types.h"

#ifdef __clang__
#define RC_OFFSETOF(T, f) ((ulong)__builtin_offsetof(T, f))
#else
#define RC_OFFSETOF(T, f) ((ulong)(&(((T*)0)->f)))
#endif

kernel void rc_layout(global ulong* out, uint capacity) {
  if (get_global_id(0) != 0) return;
  uint i = 0;
#define RC_SIZE(T)                                                                             \
  if (i < capacity) out[i] = sizeof(T);                                                        \
  ++i;
#define RC_FIELD(T, f)                                                                         \
  if (i < capacity) out[i] = RC_OFFSETOF(T, f);                                                \
  ++i;
  RADCL_LAYOUT_STRUCTS(RC_SIZE)
  RADCL_LAYOUT_FIELDS(RC_FIELD)
}
