// One render of a study: the command for radcl's or Radiance's rtrace (sensors) or rpict
// (pictures), run and read back as one RGB value per sensor or per block.
#pragma once

#include <string>
#include <vector>

#include "radcl/cost/score.h"
#include "radcl/cost/study.h"
#include "radcl/cost/timed_run.h"

namespace radcl::cost {

struct RenderJob {
  bool radiance = false;
  std::vector<std::string> settings; // the step's options, after the user's
  std::uint32_t seed = 1;            // RADCL_SEED
  bool std_error = false;            // sensors: rtrace -oe as well (radcl only)
  bool warm_up = false; // the first 256 sensors, or a 32 x 32 picture; nothing read back
};

struct RenderOutput {
  double seconds = 0;
  std::vector<Rgb> values, std_error; // std_error only with RenderJob::std_error
};

RenderOutput render(const StudyOptions& o, const RenderJob& job);

// Sensor values as rtrace -h prints them: `columns` numbers per line (3 or 6), rgb first.
std::vector<Rgb> read_values(const std::string& path, int columns,
                             std::vector<Rgb>* second = nullptr);

// A picture's mean RGB over blocks of block x block pixels (partial blocks at the right and
// bottom edges count), exposure undone.
std::vector<Rgb> picture_blocks(const std::string& path, int block);

} // namespace radcl::cost
