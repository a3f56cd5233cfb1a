// rpict's -o/-z file specifications: printf patterns of the frame number (frame%03d.hdr).
#pragma once

#include <string>

namespace radcl::cli {

// Each integer conversion (%d, %03d, %x, ...) becomes `frame`; "%%" is a '%'. Throws
// FatalError for any other conversion.
std::string frame_name(const std::string& pattern, int frame);

} // namespace radcl::cli
