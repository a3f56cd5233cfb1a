#include "radcl/scene/octree_reader.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "radcl/scene/object_type.h"
#include "radcl/scene/portable_io.h"
#include "radcl/scene/rad_reader.h"
#include "radcl/util/error.h"

namespace radcl::scene {

namespace {

constexpr int kOctMagic = 283; // 4 * MAXOBJSIZ + 251
constexpr int kMaxObjSize = 8;
constexpr std::int64_t kMaxSet = 511;

enum NodeType { kEmpty = 0, kFull = 1, kTree = 2 };

bool same_object(const Object& a, const Object& b) {
  return a.type == b.type && a.modifier == b.modifier && a.sargs == b.sargs && a.fargs == b.fargs;
}

// Walks the pre-order node stream without recursion (a damaged file could nest arbitrarily
// deep) and collects every set member. Nothing of the tree is kept.
std::vector<std::int64_t> walk_tree(ByteReader& in, int objsize) {
  std::vector<std::int64_t> members;
  std::size_t pending = 1;
  while (pending > 0) {
    --pending;
    const int t = in.get();
    switch (t) {
    case kEmpty:
      break;
    case kFull: {
      const std::int64_t n = in.getint(objsize);
      if (n < 0 || n > kMaxSet) in.fail("bad set in getfullnode");
      for (std::int64_t i = 0; i < n; ++i)
        members.push_back(in.getint(objsize));
      break;
    }
    case kTree:
      pending += 8;
      break;
    case -1:
      in.truncated();
    default:
      in.fail("damaged octree");
    }
  }
  std::sort(members.begin(), members.end());
  members.erase(std::unique(members.begin(), members.end()), members.end());
  return members;
}

} // namespace

bool read_binary_scene(ByteReader& in, int objsize, SceneDescription& scene) {
  // EOF anywhere the reader expects the next table entry or record ends the section, as
  // Radiance's getstr()/getint() returning EOF does; EOF inside a record is truncation.
  std::vector<std::optional<ObjectType>> types;
  for (;;) {
    if (in.at_end()) return false;
    std::string name = in.getstr();
    if (name.empty()) break;
    auto t = type_from_name(name);
    if (!t) warning("(" + in.name() + "): unknown object type \"" + name + "\"");
    types.push_back(t);
  }
  const auto base = static_cast<std::int64_t>(scene.objects.size());
  for (;;) {
    if (in.at_end()) return false;
    const int ti = static_cast<std::int8_t>(in.byte());
    if (ti == -1) return true;
    if (ti < 0 || static_cast<std::size_t>(ti) >= types.size() || !types[ti])
      in.fail("reference to unknown type");
    Object o;
    o.type = *types[ti];
    std::int64_t m = in.getint(objsize);
    o.name = in.getstr();
    const auto here = static_cast<std::int64_t>(scene.objects.size());
    if (m != kVoid) {
      m += base;
      // A modifier is always defined before its first use.
      if (m < base || m >= here)
        in.fail("bad modifier number for " + std::string(type_name(o.type)) + " \"" + o.name +
                "\"");
    }
    o.modifier = static_cast<std::int32_t>(m);
    const std::int64_t ns = in.getint(2);
    if (ns < 0) in.fail("bad string argument count for \"" + o.name + "\"");
    o.sargs.reserve(static_cast<std::size_t>(ns));
    for (std::int64_t i = 0; i < ns; ++i)
      o.sargs.push_back(in.getstr());
    const std::int64_t nf = in.getint(2);
    if (nf < 0) in.fail("bad real argument count for \"" + o.name + "\"");
    if (static_cast<std::size_t>(nf) * 5 > in.remaining()) in.truncated();
    o.fargs.reserve(static_cast<std::size_t>(nf));
    for (std::int64_t i = 0; i < nf; ++i)
      o.fargs.push_back(in.getflt());
    if (here >= std::numeric_limits<std::int32_t>::max()) in.fail("too many objects");
    // Modifier names resolve to the latest definition, except that an identical
    // redefinition keeps the older object (Radiance's insertobject()).
    if (is_modifier(o.type)) {
      auto it = scene.modifier_index.find(o.name);
      if (it == scene.modifier_index.end() || !same_object(scene.objects[it->second], o))
        scene.modifier_index[o.name] = static_cast<std::int32_t>(here);
    }
    scene.objects.push_back(std::move(o));
  }
}

SceneDescription read_octree(const std::string& path) {
  return read_octree_data(read_input_bytes(path, "octree file"), path);
}

SceneDescription read_octree_data(std::string bytes, const std::string& path,
                                  const ReadPolicy& policy) {
  ByteReader in(std::move(bytes), path, "truncated octree");
  SceneDescription scene;

  auto header = read_info_header(in);
  if (!header || (!header->format.empty() && header->format != "Radiance_octree"))
    in.fail("not an octree");
  scene.header = std::move(header->lines);

  const std::int64_t objsize = in.getint(2) - kOctMagic;
  if (objsize <= 0 || objsize > kMaxObjSize) in.fail("incompatible octree format");
  const int osz = static_cast<int>(objsize);

  // Cube strings are "%.12g"; Radiance converts them with atof().
  for (int i = 0; i < 3; ++i)
    scene.cube_origin[i] = std::atof(in.getstr().c_str());
  scene.cube_size = std::atof(in.getstr().c_str());

  // Each listed scene file is parsed as soon as it is read, before the rest of the list, so
  // that object numbers (and the order of any errors) match Radiance.
  int nfiles = 0;
  for (;;) {
    const std::string name = in.getstr();
    if (name.empty()) break;
    read_rad_file(scene, name, policy);
    ++nfiles;
  }
  scene.frozen = nfiles == 0;

  const std::int64_t nobjects = in.getint(osz);
  if (nobjects < 0 || nobjects > std::numeric_limits<std::int32_t>::max())
    in.fail("too many objects");

  const std::vector<std::int64_t> members = walk_tree(in, osz);

  if (scene.frozen) {
    // `oconv` with no input writes nothing after the tree: EOF there is an empty scene.
    const bool complete = read_binary_scene(in, osz, scene);
    if (static_cast<std::int64_t>(scene.objects.size()) != nobjects) {
      if (!complete) in.truncated();
      in.fail("bad object count; octree stale?");
    }
  } else if (static_cast<std::int64_t>(scene.objects.size()) != nobjects) {
    in.fail("bad object count; octree stale?");
  }

  for (const std::int64_t m : members) {
    if (m < 0 || m >= nobjects) in.fail("damaged octree");
    if (is_modifier(scene.objects[static_cast<std::size_t>(m)].type))
      in.fail("modifier in tree; octree stale?");
  }
  return scene;
}

} // namespace radcl::scene
