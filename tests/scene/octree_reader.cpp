// Octree reader and the portable binary encodings it is built on.
#include "radcl/scene/octree_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "radcl/scene/portable_io.h"
#include "radcl/util/error.h"
#include "temp_dir.h"
#include "test_env.h"

namespace radcl::scene {
namespace {

namespace fs = std::filesystem;

// tests/data, also when the harness did not pass RADCL_TEST_DATA through.
std::string data(const std::string& name) {
  if (std::getenv("RADCL_TEST_DATA")) return test::data(name);
  return (fs::path(__FILE__).parent_path().parent_path() / "data" / name).string();
}

// Runs a test body with another current directory (unfrozen octrees name their .rad files
// relative to the directory oconv ran in).
class InDir {
public:
  explicit InDir(const fs::path& dir) : old_(fs::current_path()) { fs::current_path(dir); }
  ~InDir() { fs::current_path(old_); }

private:
  fs::path old_;
};

std::string bytes(std::initializer_list<int> b) {
  std::string s;
  for (int c : b)
    s.push_back(static_cast<char>(c));
  return s;
}

std::string hex(const std::string& s) {
  static const char* digits = "0123456789ABCDEF";
  std::string r;
  for (unsigned char c : s) {
    if (!r.empty()) r += ' ';
    r += digits[c >> 4];
    r += digits[c & 15];
  }
  return r;
}

fs::path temp_file(const std::string& name, const std::string& contents) {
  static const test::TempFolder dir("octree_reader"); // removed at exit
  fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << contents;
  return p;
}

std::string error_of(const std::string& path) {
  try {
    read_octree(path);
  } catch (const FatalError& e) {
    return e.what();
  }
  return "(no error)";
}

// ---------------------------------------------------------------- portable encodings

TEST(PortableIo, GetIntSignExtends) {
  EXPECT_EQ(decode_int(reinterpret_cast<const unsigned char*>("\xff"), 1), -1);
  EXPECT_EQ(decode_int(reinterpret_cast<const unsigned char*>("\x7f"), 1), 127);
  EXPECT_EQ(decode_int(reinterpret_cast<const unsigned char*>("\x01\x1f"), 2), 287);
  EXPECT_EQ(decode_int(reinterpret_cast<const unsigned char*>("\xff\xfe"), 2), -2);
  EXPECT_EQ(decode_int(reinterpret_cast<const unsigned char*>("\x80\x00\x00\x00"), 4),
            -2147483648LL);
  EXPECT_EQ(decode_int(reinterpret_cast<const unsigned char*>("\x00\x00\x00\x25"), 4), 37);
}

TEST(PortableIo, PutIntRoundTrips) {
  for (int n : {1, 2, 3, 4, 5, 8})
    for (std::int64_t v : {0LL, 1LL, -1LL, 100LL, -100LL, 127LL, -128LL}) {
      std::string s;
      put_int(s, v, n);
      ASSERT_EQ(s.size(), static_cast<std::size_t>(n));
      EXPECT_EQ(decode_int(reinterpret_cast<const unsigned char*>(s.data()), n), v) << n;
    }
  std::string s;
  put_int(s, 287, 2);
  EXPECT_EQ(s, bytes({0x01, 0x1f}));
  s.clear();
  put_int(s, -1, 4);
  EXPECT_EQ(s, bytes({0xff, 0xff, 0xff, 0xff}));
  s.clear();
  put_int(s, std::int64_t{1} << 40, 8);
  EXPECT_EQ(decode_int(reinterpret_cast<const unsigned char*>(s.data()), 8), std::int64_t{1} << 40);
}

TEST(PortableIo, PutFltWorkedExamples) {
  // octree-format.md §8: 0.7 and 0.1 in the frozen record of red_plastic.
  std::string s;
  put_flt(s, 0.7);
  EXPECT_EQ(hex(s), "59 99 99 98 00");
  s.clear();
  put_flt(s, 0.1);
  EXPECT_EQ(hex(s), "66 66 66 65 FD");
  s.clear();
  put_flt(s, 0.0);
  EXPECT_EQ(hex(s), "00 00 00 00 00");
  s.clear();
  put_flt(s, -0.5); // frac -0.5: m = trunc(-0.5 * 0x7fffffff)
  EXPECT_EQ(hex(s), "C0 00 00 01 00");
}

TEST(PortableIo, GetFltWorkedExamples) {
  // §3.3: 0.8 round-trips as 0.79999999995 (half-LSB reconstruction).
  std::string s;
  put_flt(s, 0.8);
  const double v = decode_flt(reinterpret_cast<const unsigned char*>(s.data()));
  EXPECT_NEAR(v, 0.79999999995, 5e-12);
  EXPECT_NE(v, 0.8);
  // m == 0 is exactly zero whatever the exponent byte says.
  EXPECT_EQ(decode_flt(reinterpret_cast<const unsigned char*>("\0\0\0\0\x05")), 0.0);
  // Negative mantissa reconstructs with m - 0.5.
  const auto m = bytes({0xc0, 0x00, 0x00, 0x01, 0x00});
  EXPECT_DOUBLE_EQ(decode_flt(reinterpret_cast<const unsigned char*>(m.data())),
                   (-1073741823.0 - 0.5) / 2147483647.0);
}

TEST(PortableIo, FltRoundTripPrecision) {
  for (double f : {1.0, -1.0, 0.7, 0.1, 3.14159265358979, -2.5e-7, 1e20, -6.02e23, 123456.789,
                   1e-30, 0.999999999, 179.0, -0.0001}) {
    std::string s;
    put_flt(s, f);
    ASSERT_EQ(s.size(), 5u);
    const double g = decode_flt(reinterpret_cast<const unsigned char*>(s.data()));
    EXPECT_LE(std::abs(g - f), 1e-9 * std::abs(f)) << f;
  }
}

TEST(PortableIo, FltOverflowAndUnderflow) {
  std::string s;
  put_flt(s, 1e300); // exponent > 127: clamped to the largest mantissa and exponent
  EXPECT_EQ(hex(s), "7F FF FF FF 7F");
  s.clear();
  put_flt(s, -1e300);
  EXPECT_EQ(hex(s), "80 00 00 01 7F");
  s.clear();
  put_flt(s, 1e-300); // exponent < -128: zero
  EXPECT_EQ(hex(s), "00 00 00 00 00");
}

TEST(PortableIo, ReaderStringsAndTruncation) {
  ByteReader in(std::string("abc\0\0xy", 7), "t.oct", "truncated octree");
  EXPECT_EQ(in.getstr(), "abc");
  EXPECT_EQ(in.getstr(), "");
  try {
    in.getstr();
    FAIL() << "no error";
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "(t.oct): truncated octree");
  }
  ByteReader in2(bytes({0x01}), "x.oct", "truncated octree");
  EXPECT_THROW(in2.getint(2), FatalError);
  ByteReader in3(bytes({1, 2, 3, 4}), "x.oct", "truncated octree");
  EXPECT_THROW(in3.getflt(), FatalError);
}

TEST(PortableIo, InfoHeader) {
  static const char text[] = "#?RADIANCE\noconv a.rad\nFORMAT=  Radiance_octree  \nX=1\n\n\x01";
  ByteReader in(std::string(text, sizeof text - 1), "h");
  auto h = read_info_header(in);
  ASSERT_TRUE(h);
  EXPECT_EQ(h->format, "Radiance_octree");
  EXPECT_EQ(h->lines, (std::vector<std::string>{"#?RADIANCE", "oconv a.rad", "X=1"}));
  EXPECT_EQ(in.get(), 1);

  ByteReader crlf("#?RADIANCE\r\nFORMAT=Radiance_tmesh\r\n\r\nZ", "h");
  auto h2 = read_info_header(crlf);
  ASSERT_TRUE(h2);
  EXPECT_EQ(h2->format, "Radiance_tmesh");
  EXPECT_EQ(crlf.get(), 'Z');

  ByteReader binary(bytes({0x01, 0x1f}), "h");
  EXPECT_FALSE(read_info_header(binary));
  ByteReader unterminated("#?RADIANCE\nno end", "h");
  EXPECT_FALSE(read_info_header(unterminated));
}

// ---------------------------------------------------------------- octrees

// Frozen octree bytes in the layout of §1, with a caller-chosen type table.
std::string frozen_octree(const std::vector<std::string>& types, const std::string& records,
                          std::int64_t nobjects, const std::string& tree) {
  std::string s = "#?RADIANCE\noconv -f test\nFORMAT=Radiance_octree\n\n";
  put_int(s, 287, 2);
  for (const char* c : {"0", "0", "0", "1"})
    put_str(s, c);
  put_str(s, ""); // no scene files: frozen
  put_int(s, nobjects, 4);
  s += tree;
  for (const auto& t : types)
    put_str(s, t);
  put_str(s, "");
  s += records;
  s.push_back(static_cast<char>(0xff));
  return s;
}

void put_record(std::string& s, int type, std::int32_t mod, const std::string& name,
                const std::vector<std::string>& sargs, const std::vector<double>& fargs) {
  put_int(s, type, 1);
  put_int(s, mod, 4);
  put_str(s, name);
  put_int(s, static_cast<std::int64_t>(sargs.size()), 2);
  for (const auto& a : sargs)
    put_str(s, a);
  put_int(s, static_cast<std::int64_t>(fargs.size()), 2);
  for (double f : fargs)
    put_flt(s, f);
}

TEST(OctreeReader, FrozenTypeTableMappedByName) {
  // The §8 example scene, with a type table in a made-up order to prove that types are
  // mapped by name and not by Radiance 5.4a's numbers.
  const std::vector<std::string> types = {"sphere", "alias", "light", "polygon", "plastic"};
  std::string rec;
  put_record(rec, 4, -1, "red_plastic", {}, {0.7, 0.1, 0.1, 0, 0});
  put_record(rec, 2, -1, "bright", {}, {100, 100, 100});
  put_record(rec, 3, 0, "floor", {}, {0, 0, 0, 1, 0, 0, 1, 1, 0});
  put_record(rec, 0, 1, "lamp", {}, {0.5, 0.5, 2, 0.1});
  put_record(rec, 1, 0, "red2", {}, {});               // inherit alias: modifier = target
  put_record(rec, 1, -1, "red3", {"red_plastic"}, {}); // void alias red3 red_plastic
  put_record(rec, 0, 4, "ball", {}, {0.5, 0.5, 0.3, 0.2});
  std::string tree = bytes({1});
  for (int m : {3, 2, 3, 6})
    put_int(tree, m, 4);
  const auto path = temp_file("mapped.oct", frozen_octree(types, rec, 7, tree));

  const SceneDescription s = read_octree(path.string());
  EXPECT_TRUE(s.frozen);
  ASSERT_EQ(s.objects.size(), 7u);
  EXPECT_EQ(s.objects[0].type, RC_OBJ_PLASTIC);
  EXPECT_EQ(s.objects[1].type, RC_OBJ_LIGHT);
  EXPECT_EQ(s.objects[2].type, RC_OBJ_POLYGON);
  EXPECT_EQ(s.objects[3].type, RC_OBJ_SPHERE);
  EXPECT_EQ(s.objects[4].type, RC_OBJ_ALIAS);
  EXPECT_EQ(s.objects[4].modifier, 0);
  EXPECT_TRUE(s.objects[4].sargs.empty());
  EXPECT_EQ(s.objects[5].modifier, kVoid);
  EXPECT_EQ(s.objects[5].sargs, std::vector<std::string>{"red_plastic"});
  EXPECT_EQ(s.objects[6].modifier, 4);
  EXPECT_EQ(s.objects[0].name, "red_plastic");
  EXPECT_NEAR(s.objects[0].fargs[0], 0.7, 1e-9);
  EXPECT_EQ(s.objects[0].fargs[3], 0.0);
  EXPECT_EQ(s.objects[2].fargs.size(), 9u);
  EXPECT_EQ(s.modifier_index.at("red2"), 4);
  EXPECT_EQ(s.modifier_index.at("bright"), 1);
  EXPECT_EQ(s.modifier_index.count("floor"), 0u);
  EXPECT_EQ(s.header, (std::vector<std::string>{"#?RADIANCE", "oconv -f test"}));
  EXPECT_EQ(s.cube_size, 1.0);
  fs::remove(path);
}

TEST(OctreeReader, EmptyOctree) {
  // `oconv` with no input: cube 0 0 0 0, no files, no objects, one empty node, then EOF.
  std::string s = "#?RADIANCE\noconv\nFORMAT=Radiance_octree\n\n";
  put_int(s, 287, 2);
  for (int i = 0; i < 4; ++i)
    put_str(s, "0");
  put_str(s, "");
  put_int(s, 0, 4);
  s.push_back('\0');
  const auto path = temp_file("empty.oct", s);
  const SceneDescription sc = read_octree(path.string());
  EXPECT_TRUE(sc.objects.empty());
  EXPECT_TRUE(sc.frozen);
  EXPECT_EQ(sc.cube_size, 0.0);
  fs::remove(path);
}

TEST(OctreeReader, CommandInput) {
  const std::string src = data("scenes/chair.oct");
  const SceneDescription s = read_octree("!cat '" + src + "'");
  EXPECT_EQ(s.objects.size(), 37u);
}

TEST(OctreeReader, MissingFile) {
  EXPECT_EQ(error_of("/nonexistent/x.oct"), "cannot open octree file \"/nonexistent/x.oct\"");
}

TEST(OctreeReader, FrozenChair) {
  const SceneDescription s = read_octree(data("scenes/chair.oct"));
  EXPECT_TRUE(s.frozen);
  ASSERT_EQ(s.objects.size(), 37u);
  EXPECT_EQ(s.header, (std::vector<std::string>{"#?RADIANCE", "oconv -f chair.rad"}));
  EXPECT_DOUBLE_EQ(s.cube_origin[0], -0.25501);
  EXPECT_DOUBLE_EQ(s.cube_origin[2], -9.99999999995e-06);
  EXPECT_DOUBLE_EQ(s.cube_size, 0.96002);
  EXPECT_EQ(s.objects[0].type, RC_OBJ_PLASTIC);
  EXPECT_EQ(s.objects[0].name, "chair_mat");
  EXPECT_EQ(s.objects[1].type, RC_OBJ_POLYGON);
  EXPECT_EQ(s.objects[1].name, "seat.1540");
  EXPECT_EQ(s.objects[1].modifier, 0);
  EXPECT_EQ(s.objects[1].fargs.size(), 12u);
  EXPECT_NEAR(s.objects[1].fargs[5], 0.46, 1e-9);
  EXPECT_EQ(s.find_modifier("chair_mat"), 0);
}

struct Expected {
  const char* file;
  std::size_t objects;
  bool frozen;
};

TEST(OctreeReader, EveryReferenceOctreeLoads) {
  InDir here(data("scenes"));
  // Counts decoded independently from each file's object-count field.
  const Expected all[] = {{"chair.oct", 37, true},
                          {"cornell.oct", 21, false},
                          {"furnished.oct", 52, false},
                          {"luminaires.oct", 23, false},
                          {"materials.oct", 30, false},
                          {"materials_plain.oct", 29, false},
                          {"office_clear.oct", 46, false},
                          {"office_clear_frozen.oct", 46, true},
                          {"office_overcast.oct", 44, false},
                          {"sphere.oct", 4, false},
                          {"aniso.oct", 30, false},
                          {"prism.oct", 24, false},
                          {"mist.oct", 33, false},
                          {"mist_nomist.oct", 20, false},
                          {"bsdf.oct", 117, false},
                          {"office_dome.oct", 42, false},
                          {"office_suns.oct", 51, false},
                          {"office_open.oct", 38, false},
                          {"office_vmx.oct", 40, true}};
  std::size_t seen = 0;
  for (const auto& e : all) {
    SCOPED_TRACE(e.file);
    const SceneDescription s = read_octree(e.file);
    EXPECT_EQ(s.objects.size(), e.objects);
    EXPECT_EQ(s.frozen, e.frozen);
    ASSERT_FALSE(s.header.empty());
    EXPECT_EQ(s.header[0], "#?RADIANCE");
    for (const auto& l : s.header)
      EXPECT_EQ(l.rfind("FORMAT=", 0), std::string::npos);
    ++seen;
  }
  // Every .oct in the folder is in the list above.
  std::size_t on_disk = 0;
  for (const auto& f : fs::directory_iterator("."))
    on_disk += f.path().extension() == ".oct";
  EXPECT_EQ(on_disk, seen);
}

TEST(OctreeReader, FrozenEqualsUnfrozen) {
  InDir here(data("scenes"));
  const SceneDescription a = read_octree("office_clear.oct");
  const SceneDescription b = read_octree("office_clear_frozen.oct");
  EXPECT_FALSE(a.frozen);
  EXPECT_TRUE(b.frozen);
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const Object& x = a.objects[i];
    const Object& y = b.objects[i];
    SCOPED_TRACE(x.name);
    EXPECT_EQ(x.type, y.type);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.modifier, y.modifier);
    EXPECT_EQ(x.sargs, y.sargs);
    ASSERT_EQ(x.fargs.size(), y.fargs.size());
    for (std::size_t k = 0; k < x.fargs.size(); ++k)
      EXPECT_LE(std::abs(x.fargs[k] - y.fargs[k]), 1e-9 * std::abs(x.fargs[k])) << k;
  }
  using Index = std::map<std::string, std::int32_t>;
  EXPECT_EQ(Index(a.modifier_index.begin(), a.modifier_index.end()),
            Index(b.modifier_index.begin(), b.modifier_index.end()));
  EXPECT_EQ(a.cube_origin, b.cube_origin);
  EXPECT_EQ(a.cube_size, b.cube_size);
}

// With ReadPolicy::open_files off (the fuzz target), an unfrozen octree's first scene file is
// refused as bad input; a frozen octree needs no file and reads as usual.
TEST(OctreeReader, PolicyRefusesTheScenesOfUnfrozenOctrees) {
  ReadPolicy no_files;
  no_files.open_files = false;
  no_files.run_commands = false;
  const std::string unfrozen = read_input_bytes(data("scenes/cornell.oct"), "");
  try {
    read_octree_data(unfrozen, "cornell.oct", no_files);
    ADD_FAILURE() << "no error";
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "cannot open scene file \"cornell.rad\": reading files is disabled");
  }
  const std::string frozen = read_input_bytes(data("scenes/office_clear_frozen.oct"), "");
  EXPECT_GT(read_octree_data(frozen, "f.oct", no_files).objects.size(), 0u);
}

} // namespace
} // namespace radcl::scene
