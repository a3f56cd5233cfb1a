// The BSDF and aBSDF materials' function records (../shared/docs/radiance/scene-format.md §3.13):
// string arguments
//   BSDF:  thickness  file.xml  ux uy uz  funcfile  [transform]
//   aBSDF:            file.xml  ux uy uz  funcfile  [transform]
// The thickness and the up vector are expressions evaluated at each hit in function space
// (the up vector turned to world space, the thickness scaled by the transform). The XML file is
// read once per scene (radcl::bsdf) and flattened into device tables (BsdfTables), packed into
// the argument buffer; kernels/materials/bsdf_shade.cl reads them through the offsets kept in
// the record's descriptor.
#include "radcl/bsdf/xml_reader.h"
#include "radcl/render/compile/bsdf_tables.h"
#include "radcl/render/compile/func_materials.h"
#include "radcl/render/compile/pattern_compiler.h"
#include "radcl/scene/raypath.h"
#include "radcl/util/error.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numbers>

namespace radcl::render {
namespace {

constexpr std::size_t kRecordFloats = sizeof(rc_bsdf) / sizeof(float);
constexpr std::size_t kCompFloats = sizeof(rc_bsdf_comp) / sizeof(float);
constexpr double kPi = std::numbers::pi;

// Pads `args` to a multiple of 4 floats: the records hold float4s.
void align16(std::vector<float>& args) {
  while (args.size() % 4)
    args.push_back(0.0f);
}

template <class T> void append_records(std::vector<float>& args, const std::vector<T>& recs) {
  const std::size_t at = args.size();
  args.resize(at + recs.size() * sizeof(T) / sizeof(float));
  if (!recs.empty()) std::memcpy(args.data() + at, recs.data(), recs.size() * sizeof(T));
}

// Radiance's check of a loaded file: a side that scatters more than 101% of the light it gets
// (its Lambertian part plus the residual's largest directional total) is worth a warning.
void warn_over_unity(const BsdfTables& t, const std::string& file) {
  std::string name = std::filesystem::path(file).stem().string();
  const char* what[4] = {"front reflection", "rear reflection", "front transmission",
                         "back transmission"};
  const rc_bsdf& f = t.files.at(0);
  for (int p = 0; p < 4; ++p) {
    double amt = kPi * f.lamb[p].y;
    if (f.comp[p] != RC_NONE) amt += t.comps[f.comp[p]].max_hemi;
    if (amt <= 1.01) continue;
    char pct[32];
    std::snprintf(pct, sizeof pct, "%.1f%%", amt * 100);
    warning("BSDF \"" + name + "\" has " + pct + " " + what[p]);
  }
}

} // namespace

// Offsets in `args` of the file's record, its components, its float and its int array.
std::array<std::uint32_t, 4> PatternCompiler::bsdf_file(const std::string& file,
                                                        const std::string& where,
                                                        std::vector<float>& args) {
  if (auto it = bsdf_files_.find(file); it != bsdf_files_.end()) return it->second;
  const std::string path = scene::find_on_raypath(file);
  if (path.empty()) throw FatalError(where + ": cannot find BSDF file \"" + file + "\"");
  BsdfTables t;
  t.add(bsdf::read_bsdf_xml(path));
  warn_over_unity(t, file);
  static_assert(kRecordFloats % 4 == 0 && kCompFloats % 4 == 0, "16-byte records");
  std::array<std::uint32_t, 4> off{};
  align16(args);
  off[0] = static_cast<std::uint32_t>(args.size());
  append_records(args, t.files);
  off[1] = static_cast<std::uint32_t>(args.size());
  append_records(args, t.comps);
  off[2] = static_cast<std::uint32_t>(args.size());
  args.insert(args.end(), t.vals.begin(), t.vals.end());
  off[3] = static_cast<std::uint32_t>(args.size());
  append_records(args, t.ints);
  if (args.size() >= 0xFFFFFFF0u)
    throw FatalError(where + ": BSDF file \"" + file + "\" too large");
  bsdf_files_[file] = off;
  return off;
}

// Descriptor (after the record's 25 transform floats): flags (bit 0: aBSDF), the four table
// offsets, the thickness expression (RC_NONE for aBSDF), the up vector's three expressions.
std::vector<std::uint32_t> PatternCompiler::compile_bsdf(const scene::Object& o,
                                                         const std::string& where,
                                                         std::vector<float>& args,
                                                         std::size_t& transform) {
  const bool thick = o.type == RC_OBJ_BSDF;
  const std::size_t first = thick ? 1 : 0; // the file's argument
  if (o.sargs.size() < first + 5 || o.fargs.size() > 9 || o.fargs.size() % 3)
    throw FatalError("bad # arguments for " + where);
  const std::string ctx = load(o.sargs[first + 4], where);
  std::vector<std::uint32_t> desc{thick ? 0u : 1u};
  for (std::uint32_t v : bsdf_file(o.sargs[first], where, args))
    desc.push_back(v);
  desc.push_back(thick ? request(o.sargs[0], ctx, where) : RC_NONE);
  for (std::size_t i = 1; i <= 3; ++i)
    desc.push_back(request(o.sargs[first + i], ctx, where));
  // As Radiance's getfunc: the transform starts at the first argument beginning with '-'.
  transform = first + 5;
  while (transform < o.sargs.size() && o.sargs[transform].rfind('-', 0) != 0)
    ++transform;
  return desc;
}

} // namespace radcl::render
