// Loading only the OpenCL driver the user named. The ICD loader (ocl-icd) opens every
// registered driver on the first OpenCL call: a run on PoCL also loads and starts NVIDIA's
// driver, a quarter of a second on the GPU machine (0.36 s warm start-up against 0.09 s with
// PoCL's alone). Given one .icd file in OCL_ICD_VENDORS it opens that driver only.
#pragma once

#include <string>

namespace radcl::device {

// The .icd file in `vendors_dir` whose driver library's path contains `spec` (ignoring case),
// when exactly one does and `spec` is not a device index; else "".
std::string icd_file_for(const std::string& vendors_dir, const std::string& spec);

// Before the process's first OpenCL call: with RADCL_DEVICE naming a driver (pocl, nvidia) and
// OCL_ICD_VENDORS unset or a folder, points OCL_ICD_VENDORS at that driver's .icd file alone.
void load_only_named_driver();

} // namespace radcl::device
