// The pipeline's tuning from RADCL_* variables (render/pipeline/tuning.h).
#pragma once

#include "radcl/render/pipeline/tuning.h"

namespace radcl::cli {

render::PipelineTuning tuning_from_environment();

} // namespace radcl::cli
