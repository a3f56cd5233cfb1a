// Where function files, data files and radcl's own modules are found: one rule for every
// program and every kind of file, so that a moved installation keeps working.
#pragma once

#include <string>
#include <vector>

namespace radcl {

// radcl's own library folders, searched after RAYPATH: the folder RADCL_LIB names if it is set
// (set but empty: none), else the installed library beside the program (../lib/radcl from its
// bin/), then the source tree's lib/ when the program runs from the build tree's bin/.
std::vector<std::string> radcl_library_dirs();

// The installed library folder relative to the running program (program_folder() + the
// install's bin -> lib/radcl path); empty if the program's folder is unknown.
std::string installed_library_dir();

// Radiance's getpath() on RAYPATH, then radcl_library_dirs(): names starting with '/', '.' or
// '~' are used as given; otherwise each RAYPATH entry is tried in order (empty entry = the
// current directory; default ":/usr/local/lib/ray"). Returns "" when not found.
std::string find_library_file(const std::string& name);

} // namespace radcl
