#include "radcl/device/icd_choice.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace radcl::device {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

} // namespace

std::string icd_file_for(const std::string& vendors_dir, const std::string& spec) {
  if (spec.empty() ||
      std::all_of(spec.begin(), spec.end(), [](unsigned char c) { return std::isdigit(c); }))
    return "";
  const std::string want = lower(spec);
  std::error_code ec;
  std::string found;
  for (const auto& e : std::filesystem::directory_iterator(vendors_dir, ec)) {
    if (e.path().extension() != ".icd") continue;
    std::ifstream in(e.path());
    std::string library;
    if (!std::getline(in, library)) continue;
    if (lower(library).find(want) == std::string::npos) continue;
    if (!found.empty()) return ""; // two drivers match: leave the choice to the device names
    found = e.path().string();
  }
  return found;
}

void load_only_named_driver() {
  const char* spec = std::getenv("RADCL_DEVICE");
  if (!spec) return;
  const char* vendors = std::getenv("OCL_ICD_VENDORS");
  std::string dir = vendors && *vendors ? vendors : "/etc/OpenCL/vendors";
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return; // a file already: the user's choice
  const std::string icd = icd_file_for(dir, spec);
  if (!icd.empty()) ::setenv("OCL_ICD_VENDORS", icd.c_str(), 1);
}

} // namespace radcl::device
