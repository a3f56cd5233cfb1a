// lookamb's text forms of records (../shared/docs/radiance/ambient-file.md §3): the labelled
// listing and the 21-column data lines (-d), and the reverse conversion (-r) that re-encodes
// directions.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "radcl/ambient/record.h"

namespace radcl::ambient {

// One record as lookamb prints it, with its line end(s).
std::string format_record(const AmbientRecord& r, bool data_only);

// lookamb -r: records from text until the first one that does not parse completely (the rest
// is ignored silently, as lookamb does). Labels are skipped as single words unless data_only.
// Records are not checked: lookamb writes what it reads.
std::vector<AmbientRecord> parse_records(std::string_view text, bool data_only);

} // namespace radcl::ambient
