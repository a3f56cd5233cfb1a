// The rendering options both front ends share (cli-rtrace-rpict.md §2) as renderer settings.
#pragma once

#include "radcl/options/render_options.h"
#include "radcl/render/renderer.h"

namespace radcl::cli {

// -u+ seeds from the clock and process; -u- gives the same numbers every run.
render::RenderSettings render_settings(const options::RenderOptions& r);

// -af with -aa > 0 and -ab > 0: opens the ambient file as Radiance's setambient() does (a
// missing file is created with its header, a damaged tail is cut off, a read-only one is only
// read) and gives its records to the renderer's lookups. `progname`: argv[0], for a new file's
// header; `octree`: the octree argument, if any.
void attach_ambient_file(render::RenderSettings& s, const options::RenderOptions& r,
                         const scene::LoadedScene& ls, const std::string& progname,
                         const std::string& octree);

} // namespace radcl::cli
