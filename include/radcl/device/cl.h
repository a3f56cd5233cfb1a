// The OpenCL C API for radcl's device module, and the check every call goes through. Only
// src/device/ and include/radcl/device/ include this: other modules use the wrappers.
#pragma once

#include <CL/cl.h>
#include <string>

namespace radcl::device {

// Symbolic name of an OpenCL status ("CL_INVALID_VALUE").
const char* cl_status_name(cl_int status);

// Throws FatalError naming the call and the status when status != CL_SUCCESS.
void cl_check(cl_int status, const char* call, const char* file, int line);

} // namespace radcl::device

#define RADCL_CL(call) ::radcl::device::cl_check((call), #call, __FILE__, __LINE__)
// For creators that return a handle and report through an out-parameter.
#define RADCL_CL_CREATE(var, expr)                                                                 \
  do {                                                                                             \
    cl_int radcl_status_ = CL_SUCCESS;                                                             \
    var = (expr);                                                                                  \
    ::radcl::device::cl_check(radcl_status_, #expr, __FILE__, __LINE__);                           \
  } while (0)
