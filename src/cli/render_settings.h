// The rendering options both front ends share (cli-rtrace-rpict.md §2) as renderer settings.
#pragma once

#include "radcl/options/render_options.h"
#include "radcl/render/renderer.h"

namespace radcl::cli {

// -u+ seeds from the clock and process; -u- gives the same numbers every run.
render::RenderSettings render_settings(const options::RenderOptions& r);

} // namespace radcl::cli
