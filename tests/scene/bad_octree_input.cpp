// Bad octree, mesh and instance input: every file of tests/data/scene/bad_octree must give a
// FatalError with Radiance's message, never a crash. The catalogue is made by make_catalogue()
// below from the reference octrees; the first test checks that the committed files are exactly
// what it makes (RADCL_WRITE_BAD_OCTREES=1 rewrites them).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "files.h"
#include "radcl/scene/loader.h"
#include "radcl/scene/mesh.h"
#include "radcl/scene/octree_reader.h"
#include "radcl/scene/portable_io.h"
#include "radcl/util/error.h"
#include "temp_dir.h"
#include "test_env.h"

namespace radcl::scene {
namespace {

namespace fs = std::filesystem;

fs::path data_root() {
  if (std::getenv("RADCL_TEST_DATA")) return test::data_dir();
  return fs::path(__FILE__).parent_path().parent_path() / "data";
}

fs::path catalogue_dir() {
  return data_root() / "scene" / "bad_octree";
}

class InDir {
public:
  explicit InDir(const fs::path& dir) : old_(fs::current_path()) { fs::current_path(dir); }
  ~InDir() { fs::current_path(old_); }

private:
  fs::path old_;
};

// Byte offsets of the parts of an octree (§1), found by walking its leading fields.
struct Layout {
  std::size_t magic, cube, files, nobjects, tree;
};

Layout layout(const std::string& oct) {
  Layout l{};
  l.magic = oct.find("\n\n") + 2;
  l.cube = l.magic + 2;
  std::size_t p = l.cube;
  for (int i = 0; i < 4; ++i)
    p = oct.find('\0', p) + 1;
  l.files = p;
  while (oct[p] != '\0')
    p = oct.find('\0', p) + 1;
  l.nobjects = p + 1;
  l.tree = l.nobjects + 4;
  return l;
}

std::string patch_int(std::string s, std::size_t at, std::int64_t v, int n) {
  std::string b;
  put_int(b, v, n);
  s.replace(at, static_cast<std::size_t>(n), b);
  return s;
}

std::string octree_start(const std::vector<std::string>& files, std::int64_t nobjects) {
  std::string s = "#?RADIANCE\nradcl test catalogue\nFORMAT=Radiance_octree\n\n";
  put_int(s, 287, 2);
  for (const char* c : {"-1", "-1", "-1", "2"})
    put_str(s, c);
  for (const auto& f : files)
    put_str(s, f);
  put_str(s, "");
  put_int(s, nobjects, 4);
  return s;
}

std::string full_node(const std::vector<std::int64_t>& set) {
  std::string s(1, '\1');
  put_int(s, static_cast<std::int64_t>(set.size()), 4);
  for (auto m : set)
    put_int(s, m, 4);
  return s;
}

// A frozen section holding one `void instance <name> 1 <octree>`.
std::string frozen_instance(const std::string& name, const std::string& octree) {
  std::string s;
  put_str(s, "instance");
  put_str(s, "");
  put_int(s, 0, 1);
  put_int(s, -1, 4);
  put_str(s, name);
  put_int(s, 1, 2);
  put_str(s, octree);
  put_int(s, 0, 2);
  s.push_back(static_cast<char>(0xff));
  return s;
}

std::map<std::string, std::string> make_catalogue() {
  const fs::path scenes = data_root() / "scenes";
  const std::string chair = test::read_file(scenes / "chair.oct");   // frozen, 37 objects
  const std::string sphere = test::read_file(scenes / "sphere.oct"); // names sphere.rad, 4 objects
  const std::string octa = test::read_file(scenes / "octa.rtm");
  const Layout c = layout(chair);
  std::map<std::string, std::string> out;

  std::string s = chair;
  s[0] = '\0';
  out["not_printable.oct"] = s;
  s = chair;
  s.replace(s.find("Radiance_octree"), 15, "Radiance_picture");
  out["wrong_format.oct"] = s;
  out["truncated_header.oct"] = chair.substr(0, 30);
  out["bad_magic.oct"] = patch_int(chair, c.magic, 0, 2);
  out["objsize0.oct"] = patch_int(chair, c.magic, 283, 2);
  out["objsize9.oct"] = patch_int(chair, c.magic, 292, 2);
  out["truncated_cube.oct"] = chair.substr(0, c.cube + 5);
  out["truncated_tree.oct"] = chair.substr(0, c.tree + 40);
  const std::size_t types = chair.find(std::string("polygon\0cone\0", 13));
  const std::size_t records = chair.find(std::string("ashik2\0\0", 8)) + 8;
  out["truncated_types.oct"] = chair.substr(0, types + 30);
  out["truncated_at_record.oct"] = chair.substr(0, records); // EOF where a record should be
  out["truncated_record.oct"] = chair.substr(0, chair.size() - 100);
  s = chair;
  s[c.tree] = 7;
  out["bad_node.oct"] = s;
  s = chair;
  s.replace(s.find(std::string("\0plastic\0", 9)) + 1, 7, "plostic");
  out["unknown_type.oct"] = s;
  out["count_mismatch.oct"] = patch_int(chair, c.nobjects, 38, 4);

  // Synthetic trees: a set above MAXSET, and a set member past the object count.
  std::vector<std::int64_t> big(512);
  for (std::size_t i = 0; i < big.size(); ++i)
    big[i] = static_cast<std::int64_t>(i);
  out["big_set.oct"] = octree_start({}, 1) + full_node(big) + frozen_instance("i", "x.oct");
  out["bad_member.oct"] = octree_start({}, 1) + full_node({5}) + frozen_instance("i", "x.oct");

  // Unfrozen octrees re-read ../../scenes/sphere.rad relative to this folder.
  const Layout sl = layout(sphere);
  std::string rel = sphere.substr(0, sl.files);
  put_str(rel, "../../scenes/sphere.rad");
  rel += sphere.substr(sl.nobjects - 1);
  const Layout rl = layout(rel);
  out["stale.oct"] = patch_int(rel, rl.nobjects, 5, 4);
  // The tree is one full node {2, 3}; object 0 is the plastic sphere_wall.
  out["modifier_in_tree.oct"] = patch_int(rel, rl.tree + 5, 0, 4);

  // Instances that reach themselves: a frozen octree instancing itself, and an unfrozen
  // octree whose own .rad file instances it.
  out["self.oct"] = octree_start({}, 1) + full_node({0}) + frozen_instance("me", "self.oct");
  out["loop.rad"] = "# instances loop.oct, which is made from this file\n"
                    "void instance loop 1 loop.oct 0 0\n";
  out["loop.oct"] = octree_start({"loop.rad"}, 1) + full_node({0});
  out["missing_mesh.rad"] = "void mesh m 1 no_such_mesh.rtm 0 0\n";
  out["truncated.rtm"] = octa.substr(0, 500);
  out["truncated_mesh.rad"] = "void mesh m 1 truncated.rtm 0 0\n";
  out["bad_transform.rad"] = "void instance c 3 self.oct -t 1 0 0\n";
  return out;
}

TEST(BadOctreeCatalogue, FilesMatchGenerator) {
  const auto cat = make_catalogue();
  const bool write = std::getenv("RADCL_WRITE_BAD_OCTREES") != nullptr;
  for (const auto& [name, bytes] : cat) {
    const fs::path p = catalogue_dir() / name;
    if (write) test::write_file(p, bytes);
    EXPECT_EQ(test::read_file(p), bytes) << name << " differs from what make_catalogue() makes";
  }
}

std::string octree_error(const std::string& file) {
  try {
    read_octree(file);
  } catch (const FatalError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string load_error(const std::string& file) {
  try {
    load_scene({file});
  } catch (const FatalError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BadOctree, Messages) {
  InDir here(catalogue_dir());
  const std::pair<const char*, const char*> cases[] = {
      {"not_printable.oct", "not an octree"},
      {"wrong_format.oct", "not an octree"},
      {"truncated_header.oct", "not an octree"},
      {"bad_magic.oct", "incompatible octree format"},
      {"objsize0.oct", "incompatible octree format"},
      {"objsize9.oct", "incompatible octree format"},
      {"truncated_cube.oct", "truncated octree"},
      {"truncated_tree.oct", "truncated octree"},
      {"truncated_types.oct", "truncated octree"},
      {"truncated_at_record.oct", "truncated octree"},
      {"truncated_record.oct", "truncated octree"},
      {"bad_node.oct", "damaged octree"},
      {"big_set.oct", "bad set in getfullnode"},
      {"bad_member.oct", "damaged octree"},
      {"unknown_type.oct", "reference to unknown type"},
      {"count_mismatch.oct", "bad object count; octree stale?"},
      {"stale.oct", "bad object count; octree stale?"},
      {"modifier_in_tree.oct", "modifier in tree; octree stale?"},
  };
  for (const auto& [file, msg] : cases)
    EXPECT_EQ(octree_error(file), std::string("(") + file + "): " + msg);
}

TEST(BadOctree, EveryTruncationOfAFrozenOctreeFails) {
  const std::string chair = test::read_file(data_root() / "scenes" / "chair.oct");
  const test::TempFolder tmp("bad_octree");
  const fs::path p = tmp / "cut.oct";
  for (std::size_t n = 0; n < chair.size(); n += 7) {
    test::write_file(p, chair.substr(0, n));
    const std::string e = octree_error(p.string());
    EXPECT_TRUE(e.find("truncated octree") != std::string::npos ||
                e.find("not an octree") != std::string::npos)
        << n << ": " << e;
  }
}

TEST(BadOctree, RandomCorruptionNeverCrashes) {
  const std::string chair = test::read_file(data_root() / "scenes" / "chair.oct");
  const test::TempFolder tmp("bad_octree");
  const fs::path p = tmp / "flip.oct";
  std::uint32_t state = 12345;
  auto next = [&] { return state = state * 1664525u + 1013904223u; };
  for (int i = 0; i < 300; ++i) {
    std::string s = chair;
    const std::size_t body = s.find("\n\n") + 2;
    for (int k = 0; k < 3; ++k)
      s[body + next() % (s.size() - body)] = static_cast<char>(next() >> 24);
    test::write_file(p, s);
    try {
      read_octree(p.string()); // a flipped coordinate can still be a valid octree
    } catch (const FatalError&) {
    }
  }
}

TEST(BadInstances, RecursionIsFatal) {
  InDir here(catalogue_dir());
  EXPECT_NE(load_error("self.oct").find("recursive instance"), std::string::npos);
  EXPECT_NE(load_error("loop.oct").find("recursive instance"), std::string::npos);
  EXPECT_NE(load_error("loop.rad").find("recursive instance"), std::string::npos);
}

TEST(BadInstances, MeshesAndTransforms) {
  InDir here(catalogue_dir());
  EXPECT_EQ(load_error("missing_mesh.rad"), "cannot find mesh file \"no_such_mesh.rtm\"");
  const std::string t = load_error("truncated_mesh.rad");
  EXPECT_NE(t.find("truncated.rtm): truncated mesh file"), std::string::npos) << t;
  const std::string x = load_error("bad_transform.rad");
  EXPECT_NE(x.find("bad transform"), std::string::npos) << x;
}

} // namespace
} // namespace radcl::scene
