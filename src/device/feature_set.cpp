#include "radcl/device/feature_set.h"

#include <cctype>

#include "radcl/device/embedded_sources.h"

namespace radcl::device {
namespace {

struct TypeNames {
  const char* id;   // "PLASTIC"
  const char* name; // "plastic"
};
#define RADCL_TYPE_ROW(id, name) {#id, name},
constexpr TypeNames kTypes[] = {RADCL_OBJECT_TYPES(RADCL_TYPE_ROW)};
#undef RADCL_TYPE_ROW

bool has_embedded(const std::string& name) {
  for (const EmbeddedFile& f : embedded_files())
    if (name == f.name) return true;
  return false;
}

std::string lower(const char* s) {
  std::string out(s);
  for (char& c : out)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

} // namespace

void FeatureSet::define(const std::string& name, const std::string& value) {
  defines_[name] = value;
}

std::string FeatureSet::options() const {
  std::string out = "-cl-std=CL1.2";
  for (int t = 0; t < RC_OBJ_COUNT; ++t)
    if (types_.test(t)) out += std::string(" -DRADCL_HAS_") + kTypes[t].id + "=1";
  for (const auto& [name, value] : defines_)
    out += " -D" + name + "=" + value;
  return out;
}

std::string FeatureSet::generated_source() const {
  std::string out = "/* generated for this scene's feature set */\n";
  for (int t = 0; t < RC_OBJ_COUNT; ++t) {
    if (!types_.test(t)) continue;
    for (const char* category : {"materials", "surfaces", "patterns"}) {
      std::string file = std::string(category) + "/" + lower(kTypes[t].name) + ".cl";
      if (has_embedded(file)) out += "#include \"" + file + "\"\n";
    }
  }
  out += code_;
  return out;
}

ProgramSource FeatureSet::program(std::vector<std::string> roots) const {
  return ProgramSource{std::move(roots), generated_source(), options()};
}

} // namespace radcl::device
