#include "warnings.h"

#include "radcl/util/error.h"

namespace radcl::test {
namespace {
std::vector<std::string>& messages() {
  static std::vector<std::string> m;
  return m;
}
void keep(const std::string& msg) {
  messages().push_back(msg);
}
} // namespace

CapturedWarnings::CapturedWarnings() {
  messages().clear();
  set_warning_sink(keep);
}
CapturedWarnings::~CapturedWarnings() {
  set_warning_sink(nullptr);
}
std::vector<std::string>& CapturedWarnings::list() {
  return messages();
}

} // namespace radcl::test
