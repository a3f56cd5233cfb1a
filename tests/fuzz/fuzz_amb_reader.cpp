// The .amb parser (header, magic, records) and lookamb's text forms: the records found are
// printed both ways, and the input is also read as lookamb -r text.
#include "fuzz_target.h"
#include "radcl/ambient/format.h"
#include "radcl/ambient/text.h"

RADCL_FUZZ_TARGET(amb_reader) {
  using namespace radcl::ambient;
  for (const bool data_only : {false, true})
    for (const AmbientRecord& r : parse_records(data, data_only))
      (void)encode_record(r);
  const AmbientContents c = parse_ambient(data, "bad ambient file");
  (void)header_format(c.header);
  for (const AmbientRecord& r : c.records) {
    (void)format_record(r, false);
    (void)format_record(r, true);
    (void)record_writable(r);
  }
}
