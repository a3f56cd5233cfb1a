// The device every device test runs on: RADCL_DEVICE's choice (PoCL here, a GPU on the GPU
// machine).
#pragma once

#include "radcl/device/context.h"

inline radcl::device::Context& test_context() {
  return radcl::device::default_context();
}
