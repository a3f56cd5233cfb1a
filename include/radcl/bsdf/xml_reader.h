// Reads Radiance BSDF files (LBNL WINDOW XML): Klems matrices in the built-in LBNL bases or
// bases the file defines, and tensor trees (TensorTree3/TensorTree4). Every fault is a
// radcl::FatalError naming the file (and the line where one is known); a file that cannot be
// read is a radcl::SystemError. docs/bsdf.md lists what is read and the messages.
#pragma once

#include "radcl/bsdf/bsdf_data.h"

#include <string>

namespace radcl::bsdf {

// `path` is already resolved by the caller (RAYPATH search); messages name it as given.
BsdfData read_bsdf_xml(const std::string& path);

// The same from the text of a file; `name_for_messages` names it in messages and in the result.
BsdfData parse_bsdf_xml(const std::string& text, const std::string& name_for_messages);

} // namespace radcl::bsdf
