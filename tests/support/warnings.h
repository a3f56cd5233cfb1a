// radcl::warning() messages kept for a test to check. The sink is a plain function pointer, so
// the list is process-wide: one capture at a time, installed for the capture's lifetime (a
// fixture member covers SetUp to TearDown).
#pragma once

#include <string>
#include <vector>

namespace radcl::test {

class CapturedWarnings {
public:
  CapturedWarnings();  // empties the list and installs the sink
  ~CapturedWarnings(); // the default sink again
  CapturedWarnings(const CapturedWarnings&) = delete;
  CapturedWarnings& operator=(const CapturedWarnings&) = delete;

  // The messages since the capture began (clear() to start over).
  std::vector<std::string>& list();
};

} // namespace radcl::test
