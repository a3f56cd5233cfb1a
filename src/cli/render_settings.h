// The rendering options both front ends share (../shared/docs/radiance/cli-rtrace-rpict.md §2) as
// renderer settings.
#pragma once

#include <memory>
#include <string>

#include "radcl/ambient/ambient_file.h"
#include "radcl/options/render_options.h"
#include "radcl/render/pipeline/renderer.h"

namespace radcl::cli {

// -u+ seeds from the clock and process; -u- gives the same numbers every run.
render::RenderSettings render_settings(const options::RenderOptions& r);

// The irradiance cache, with -aa > 0 and -ab > 0: the renderer makes records (Radiance's
// radii from the octree cube and -ar), and with -af the file is opened as Radiance's
// setambient() does (a missing file is created with its header, a damaged tail is cut off, a
// read-only one is only read) and its records are given to the renderer. Returns the open
// file (null without -af). `progname`: argv[0], for a new file's header; `octree`: the octree
// argument, if any.
std::unique_ptr<ambient::AmbientFile>
setup_ambient(render::RenderSettings& s, const options::RenderOptions& r,
              const scene::LoadedScene& ls, const std::string& progname, const std::string& octree);

// After a render() call: the records the renderer made go to the file (under its lock), and
// the ones other processes appended meanwhile go to the renderer.
void sync_ambient(ambient::AmbientFile* file, render::Renderer& renderer);

} // namespace radcl::cli
