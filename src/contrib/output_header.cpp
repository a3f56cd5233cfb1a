// The information header of rcontrib's outputs (Radiance's printheader()): rtrace's header
// with NCOMP=3 and the stream's own lines (MODIFIER=, BIN=, NROWS=, NCOLS=) after it.
#include "radcl/contrib/output.h"

#include "radcl/options/ray_io.h"

namespace radcl::contrib {

std::string format_header(const OutputSettings& s, const std::string& info) {
  options::RtraceHeader h;
  h.octree_lines = s.octree_header;
  h.command = s.command;
  h.software = s.software;
  h.time = s.time;
  h.ncomp = 3; // always rgb
  h.out_format = s.format;
  std::string text = options::format_rtrace_header(h);
  // rtrace's header ends NCOMP=, [BigEndian=,] FORMAT=; rcontrib's lines go after NCOMP=. The
  // last NCOMP= line is ours: the octree's header may hold one too.
  const std::string ncomp = "NCOMP=3\n";
  text.insert(text.rfind(ncomp) + ncomp.size(), info);
  return text;
}

} // namespace radcl::contrib
