// The .rad reader: syntax (scene-format.md §1), object numbering and modifier resolution
// (§1.1), alias (§1.2), commands, and the reference scenes.
#include "radcl/scene/rad_reader.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "radcl/util/error.h"
#include "temp_dir.h"
#include "test_env.h"
#include "warnings.h"

namespace fs = std::filesystem;
using radcl::FatalError;
using namespace radcl::scene;

namespace {

class RadReader : public ::testing::Test {
protected:
  radcl::test::CapturedWarnings warnings;

  SceneDescription read(const std::string& text, const std::string& name = "t.rad") {
    SceneDescription s;
    std::istringstream in(text);
    read_rad_stream(s, in, name);
    return s;
  }
  std::string error_of(const std::string& text) {
    try {
      read(text);
    } catch (const FatalError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

// A scratch directory that is the current directory while it lives (for !commands).
class ScratchDir {
public:
  ScratchDir() : old_(fs::current_path()) { fs::current_path(dir_.path()); }
  ~ScratchDir() { fs::current_path(old_); } // before dir_ goes
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
  }
  fs::path path(const std::string& name) const { return dir_ / name; }

private:
  fs::path old_;
  radcl::test::TempFolder dir_{"scene_test"};
};

} // namespace

TEST_F(RadReader, OnePrimitive) {
  auto s = read("# a comment\nvoid plastic red\n0\n0\n5 .7 .05 .05 .02 .01\n");
  ASSERT_EQ(s.objects.size(), 1u);
  const Object& o = s.objects[0];
  EXPECT_EQ(o.type, RC_OBJ_PLASTIC);
  EXPECT_EQ(o.modifier, kVoid);
  EXPECT_EQ(o.name, "red");
  EXPECT_TRUE(o.sargs.empty());
  EXPECT_EQ(o.fargs, (std::vector<double>{.7, .05, .05, .02, .01}));
  EXPECT_EQ(o.line, 2);
  EXPECT_EQ(o.file, 0);
  ASSERT_EQ(s.files.size(), 1u);
  EXPECT_EQ(s.files[0], "t.rad");
  EXPECT_EQ(s.find_modifier("red"), 0);
  EXPECT_EQ(s.find_modifier("void"), kVoid);
  EXPECT_EQ(s.find_modifier("nothing"), kVoid);
  EXPECT_TRUE(warnings.list().empty());
}

TEST_F(RadReader, LineBreaksAndWhiteSpaceAreNotSignificant) {
  auto a = read("void plastic red_paint 0 0 5 .7 .05 .05 .02 .01");
  auto b = read("\t\v\f void\r\n\tplastic   red_paint\r0\n\n0 5\n.7\t.05 .05\n.02 .01  ");
  ASSERT_EQ(a.objects.size(), 1u);
  ASSERT_EQ(b.objects.size(), 1u);
  EXPECT_EQ(a.objects[0].fargs, b.objects[0].fargs);
  EXPECT_EQ(b.objects[0].name, "red_paint");
}

TEST_F(RadReader, LineNumbersCountLfCrLfAndLoneCr) {
  auto s = read("\n\r\n\r# c\nvoid light a 0 0 3 1 1 1\r\n\r\nvoid light b 0 0 3 1 1 1\n"
                "#\n\n   void\nlight c 0 0 3 1 1 1");
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.objects[0].line, 5);
  EXPECT_EQ(s.objects[1].line, 7);
  EXPECT_EQ(s.objects[2].line, 10);
}

TEST_F(RadReader, QuotedWords) {
  auto s = read("void brightfunc 'my pat' 4 \"a b\" 'c\"d' \"multi\nline\" e\"f 0 0\n"
                "void plastic \"\" 0 0 5 0 0 0 0 0\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].name, "my pat");
  EXPECT_EQ(s.objects[0].sargs, (std::vector<std::string>{"a b", "c\"d", "multi\nline", "e\"f"}));
  EXPECT_EQ(s.objects[1].name, "");
  // Quoted numbers are numbers (Radiance checks the word, not how it was written).
  auto q = read("void light l \"0\" '0' ' 3' \"1\" 2 '3'"); // leading blanks allowed
  EXPECT_EQ(q.objects[0].fargs, (std::vector<double>{1, 2, 3}));
}

TEST_F(RadReader, NumberForms) {
  auto s = read("void glow g 0 +0 4 1 -2.5 +.5e+1 5.\n"
                "void glow h 0 -0 4 .25 1E2 -1e-2 007\n"
                "void glow i 00 0 +4 1.5E+02 -.0 0. 3e0\n");
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.objects[0].fargs, (std::vector<double>{1, -2.5, 5, 5}));
  EXPECT_EQ(s.objects[1].fargs, (std::vector<double>{.25, 100, -0.01, 7}));
  EXPECT_EQ(s.objects[2].fargs, (std::vector<double>{150, 0, 0, 3}));
  for (const char* bad : {"1.2.3", "nan", "inf", "-inf", "NaN", "0x10", "1e", "1e+", ".", "-", "+",
                          "e5", "1,5", "1f", "--1", "1e1.5", "infinity", "1 e5"})
    EXPECT_NE(error_of(std::string("void light l 0 0 3 1 1 '") + bad + "'")
                  .find("bad arguments for light \"l\""),
              std::string::npos)
        << bad;
  for (const char* bad : {"1.0", "x", "-1", "3e0", "0x3", "+", "2."})
    EXPECT_NE(error_of(std::string("void light l 0 0 ") + bad + " 1 1 1").find("bad arguments"),
              std::string::npos)
        << bad;
}

TEST_F(RadReader, IntegerArgumentsMustBeZero) {
  EXPECT_EQ(error_of("void plastic p 0 1 7 5 0 0 0 0 0"),
            "(t.rad line 1): bad arguments for plastic \"p\"");
}

TEST_F(RadReader, ModifiersResolveToTheMostRecentDefinition) {
  auto s = read("void plastic m 0 0 5 1 0 0 0 0\n"         // 0
                "m polygon a 0 0 9 0 0 0 1 0 0 0 1 0\n"    // 1
                "void plastic m 0 0 5 0 1 0 0 0\n"         // 2: different, replaces
                "m polygon b 0 0 9 0 0 0 1 0 0 0 1 0\n"    // 3
                "void polygon m 0 0 9 0 0 0 1 0 0 0 1 0\n" // 4: a surface is not indexed
                "m sphere c 0 0 4 0 0 0 1\n");             // 5
  ASSERT_EQ(s.objects.size(), 6u);
  EXPECT_EQ(s.objects[1].modifier, 0);
  EXPECT_EQ(s.objects[3].modifier, 2);
  EXPECT_EQ(s.objects[5].modifier, 2);
  EXPECT_EQ(s.find_modifier("m"), 2);
  EXPECT_EQ(s.last_modifier(2, "m"), 0);
  EXPECT_EQ(s.last_modifier(1, "m"), 0);
  EXPECT_EQ(s.last_modifier(0, "m"), kVoid);
  EXPECT_EQ(s.last_modifier(kVoid, "m"), 2);
  EXPECT_EQ(s.last_modifier(5, "m"), 2);
}

TEST_F(RadReader, IdenticalRedefinitionKeepsTheOlderEntry) {
  auto s = read("void brightfunc pat 2 f f.cal 0 1 2\n"     // 0
                "pat plastic m 0 0 5 .5 .5 .5 0 0\n"        // 1
                "pat plastic m 0 0 5 .5 .5 .50000001 0 0\n" // 2: same within 1e-6
                "void brightfunc pat 2 f f.cal 0 1 2\n"     // 3: same as 0
                "pat plastic m 0 0 5 .5 .5 .5 0 0\n"        // 4: chain 3 == chain 0
                "void brightfunc pat 2 g f.cal 0 1 2\n"     // 5: differs in a string
                "pat plastic m 0 0 5 .5 .5 .5 0 0\n"        // 6: chain differs
                "void plastic m 0 0 5 .5 .5 .5 0 0\n");     // 7: modifier differs
  ASSERT_EQ(s.objects.size(), 8u);
  EXPECT_EQ(s.objects[4].modifier, 0); // "pat" still indexed as object 0
  EXPECT_EQ(s.objects[6].modifier, 5);
  EXPECT_EQ(s.find_modifier("pat"), 5);
  EXPECT_EQ(s.find_modifier("m"), 7);
  auto t = read("void plastic m 0 0 5 .5 .5 .5 0 0\nvoid plastic m 0 0 5 .5 .5 .5 0 0\n"
                "void plastic m 0 0 5 .5 .5 .5 0 0.1\nvoid plastic m 0 0 5 .5 .5 .5 0 0.1\n");
  EXPECT_EQ(t.find_modifier("m"), 2);
  // Named references compare what they resolve to: two mirrors with the same alternate name
  // but a different alternate in between are different.
  auto u = read("void plastic alt 0 0 5 1 1 1 0 0\n"
                "void mirror mir 1 alt 0 3 1 1 1\n"
                "void mirror mir 1 alt 0 3 1 1 1\n"
                "void plastic alt 0 0 5 0 0 0 0 0\n"
                "void mirror mir 1 alt 0 3 1 1 1\n");
  EXPECT_EQ(u.find_modifier("mir"), 4);
  auto v = read("void plastic alt 0 0 5 1 1 1 0 0\n"
                "void mirror mir 1 alt 0 3 1 1 1\n"
                "void mirror mir 1 alt 0 3 1 1 1\n");
  EXPECT_EQ(v.find_modifier("mir"), 1);
}

TEST_F(RadReader, AliasForms) {
  auto s = read("void plastic wood 0 0 5 .5 .3 .1 0 0\n"           // 0
                "void brightfunc grain 2 g g.cal 0 0\n"            // 1
                "grain alias wood_floor wood\n"                    // 2: own modifier
                "inherit alias wood2 wood\n"                       // 3: pass-through
                "void alias wood3 wood\n"                          // 4: same modifier
                "grain alias again wood_floor\n"                   // 5: alias of alias
                "wood_floor polygon f 0 0 9 0 0 0 1 0 0 0 1 0\n"); // 6
  ASSERT_EQ(s.objects.size(), 7u);
  const Object& a = s.objects[2];
  EXPECT_EQ(a.type, RC_OBJ_ALIAS);
  EXPECT_EQ(a.modifier, 1);
  EXPECT_EQ(a.sargs, (std::vector<std::string>{"wood"}));
  EXPECT_TRUE(a.fargs.empty());
  EXPECT_EQ(s.objects[3].modifier, 0);
  EXPECT_TRUE(s.objects[3].sargs.empty());
  EXPECT_EQ(s.objects[4].modifier, 0);
  EXPECT_TRUE(s.objects[4].sargs.empty());
  EXPECT_EQ(s.objects[5].modifier, 2); // grain == wood_floor's modifier: pass-through
  EXPECT_EQ(s.objects[6].modifier, 2);
  EXPECT_EQ(s.find_modifier("wood2"), 3);
  EXPECT_EQ(error_of("void alias x nowhere"),
            "(t.rad line 1): bad reference \"nowhere\" for alias \"x\"");
  EXPECT_EQ(error_of("void polygon p 0 0 9 0 0 0 1 0 0 0 1 0\nvoid alias x p"),
            "(t.rad line 2): bad reference \"p\" for alias \"x\"");
  EXPECT_EQ(error_of("void plastic m 0 0 5 0 0 0 0 0\n\ninherit plastic x 0 0 5 0 0 0 0 0"),
            "(t.rad line 3): inappropriate use of 'inherit' modifier for plastic \"x\"");
}

TEST_F(RadReader, VoidIsNotAnObjectAndSurfacesAreNotModifiers) {
  auto s = read("void polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n");
  EXPECT_EQ(s.objects.size(), 1u);
  EXPECT_TRUE(s.modifier_index.empty());
  EXPECT_EQ(error_of("void sphere s 0 0 4 0 0 0 1\ns polygon p 0 0 9 0 0 0 1 0 0 0 1 0"),
            "(t.rad line 2): undefined modifier \"s\"");
}

TEST_F(RadReader, Messages) {
  EXPECT_EQ(error_of("\n\nvoid plastik x 0 0 0"), "(t.rad line 3): unknown type \"plastik\"");
  EXPECT_EQ(error_of("foo plastic x 0 0 5 0 0 0 0 0"),
            "(t.rad line 1): undefined modifier \"foo\"");
  EXPECT_EQ(error_of("void polygon w1 0 0 12 0 0 0 1 0 0 1 1 0 0 1"),
            "(t.rad line 1): bad arguments for polygon \"w1\"");
  EXPECT_EQ(error_of("void polygon w1 0 0 6 0 0 0 1 0 0"),
            "(t.rad line 1): bad # arguments for polygon \"w1\"");
  EXPECT_EQ(error_of("void"), "(t.rad line 1): unknown type \"EOF\"");
  EXPECT_EQ(error_of("void plastic"), "(t.rad line 1): bad arguments for plastic \"\"");
  EXPECT_EQ(error_of("void plastic 'a\tb' 0 0 5 0 0 0 0 0"),
            "(t.rad line 1): illegal tab in identifier \"a\tb\"");
}

TEST_F(RadReader, ArgumentCounts) {
  auto ok = [&](const std::string& prim) { EXPECT_EQ(error_of(prim), "(no error)") << prim; };
  auto bad = [&](const std::string& prim, const std::string& what = "bad # arguments") {
    EXPECT_NE(error_of(prim).find(what), std::string::npos) << prim << ": " << error_of(prim);
  };
  ok("void polygon p 0 0 9 0 0 0 1 0 0 0 1 0");
  ok("void polygon p 0 0 15 0 0 0 1 0 0 1 1 0 0 1 0 .5 .5 0");
  bad("void polygon p 0 0 4 0 0 0 1");
  bad("void polygon p 0 0 10 0 0 0 1 0 0 0 1 0 1");
  bad("void polygon p 0 0 0");
  ok("void sphere s 0 0 4 0 0 0 -1"); // negative radius: a geometry matter, not a count
  bad("void sphere s 0 0 3 0 0 0");
  ok("void cone c 0 0 8 0 0 0 0 0 1 1 0");
  bad("void cone c 0 0 7 0 0 0 0 0 1 1");
  ok("void cylinder c 0 0 7 0 0 0 0 0 1 1");
  bad("void tube c 0 0 8 0 0 0 0 0 1 1 1");
  ok("void ring r 0 0 8 0 0 0 0 0 1 0 1");
  ok("void source s 0 0 4 0 0 1 0.5");
  bad("void source s 0 0 3 0 0 1");
  ok("void instance i 1 a.oct 0 0");
  ok("void instance i 10 a.oct -t 1 2 3 -rz 90 -s 2 -mx 0 0");
  bad("void instance i 0 0 0");
  bad("void instance i 2 a.oct b.oct 0 0", "bad transform");
  bad("void mesh m 3 a.rtm -s 0 0 0", "bad transform");
  bad("void plastic p 0 0 4 0 0 0 0");
  bad("void plastic p 1 x 0 5 0 0 0 0 0");
  bad("void metal p 0 0 6 0 0 0 0 0 0");
  ok("void trans t 0 0 7 0 0 0 0 0 0 0");
  ok("void glass g 0 0 3 1 1 1");
  ok("void glass g 0 0 4 1 1 1 1.5");
  bad("void glass g 0 0 5 1 1 1 1.5 1");
  bad("void dielectric d 0 0 4 1 1 1 1.5");
  ok("void interface d 0 0 8 1 1 1 1.5 1 1 1 1");
  bad("void light l 0 0 4 1 1 1 1");
  bad("void glow l 0 0 3 1 1 1");
  ok("void spotlight l 0 0 7 1 1 1 30 0 0 -1");
  ok("void illum i 1 void 0 3 1 1 1");
  bad("void illum i 2 a b 0 3 1 1 1");
  ok("void mirror m 0 0 3 1 1 1");
  ok("void mist m 0 0 0");
  bad("void mist m 0 0 8 1 1 1 1 1 1 1 1");
  ok("void antimatter a 1 void 0 0");
  bad("void antimatter a 0 0 0");
  ok("void plastic2 p 4 1 0 0 . 0 6 1 1 1 0 .1 .2");
  bad("void plastic2 p 3 1 0 0 0 6 1 1 1 0 .1 .2");
  bad("void trans2 p 4 1 0 0 . 0 6 1 1 1 0 .1 .2");
  ok("void BRTDfunc b 10 0 0 0 0 0 0 0 0 0 . 0 9 0 0 0 0 0 0 0 0 0");
  ok("void BSDF b 6 0 f.xml 0 0 1 . 0 3 .1 .1 .1");
  bad("void BSDF b 6 0 f.xml 0 0 1 . 0 2 .1 .1");
  bad("void aBSDF b 4 f.xml 0 0 1 0 0");
  ok("void brightfunc b 2 f f.cal 0 0");
  ok("void brightfunc b 2 f . 0 0");
  ok("void brightfunc b 8 f f.cal -rz 90 -t 1 1 1 0 0");
  bad("void brightfunc b 1 f 0 0");
  bad("void brightfunc b 3 f f.cal -rz 0 0", "bad transform");
  bad("void colorfunc c 6 r g b f.cal -s 0 0 0", "bad transform");
  ok("void colorpict p 7 r g b x.hdr picture.cal -u v 0 0"); // u/v expressions may be negative
  bad("void colorpict p 6 r g b x.hdr picture.cal u 0 0");
  ok("void brightdata d 5 f d.dat f.cal -Dx -rz 0 0"); // data coordinates: not checked
  ok("void texfunc t 4 x y z t.cal 0 0");
  ok("void mixfunc m 4 a b c m.cal 0 0");
  bad("void mixfunc m 3 a b c 0 0");
  ok("void brighttext t 2 helvet.fnt hi 0 11 0 0 0 1 0 0 0 -1 0 1 0");
  bad("void colortext t 2 helvet.fnt hi 0 11 0 0 0 1 0 0 0 -1 0 1 0");
  ok("void mixtext t 4 a b helvet.fnt hi 0 9 0 0 0 1 0 0 0 -1 0");
  ok("void prism1 p 5 c x y z . 0 0");
  bad("void prism2 p 5 c x y z . 0 0");
}

TEST_F(RadReader, LongWordsAndCommentLines) {
  // A word keeps at most 511 characters; the rest starts the next word.
  std::string name(600, 'n');
  auto e = error_of("void plastic " + name + " 0 0 5 0 0 0 0 0");
  EXPECT_NE(e.find("bad arguments for plastic \"" + std::string(511, 'n') + "\""),
            std::string::npos);
  // A comment line is discarded up to 2047 characters; what is left is read as scene input.
  auto s = read("#" + std::string(2047, 'c') + "void light l 0 0 3 1 1 1\n");
  EXPECT_EQ(s.objects.size(), 1u);
  auto t = read("#" + std::string(2046, 'c') + "\nvoid light l 0 0 3 1 1 1\n");
  EXPECT_EQ(t.objects.size(), 1u);
}

TEST_F(RadReader, EmptyInputWarns) {
  read("# nothing here\n\n", "e.rad");
  ASSERT_EQ(warnings.list().size(), 1u);
  EXPECT_EQ(warnings.list()[0], "(e.rad): empty file");
  warnings.list().clear();
  read("", "f.rad");
  EXPECT_EQ(warnings.list(), (std::vector<std::string>{"(f.rad): empty file"}));
}

TEST_F(RadReader, Commands) {
  ScratchDir dir;
  dir.write("sub.rad", "void plastic from_file 0 0 5 1 1 1 0 0\n");
  dir.write("main.rad",
            "void light l 0 0 3 1 1 1\n"
            "!cat sub.rad\n" // relative to the current directory
            "!echo void plastic \\\n continued 0 0 5 1 1 1 0 0\n" // backslash-newline
            "!printf '!echo void glow nested 0 0 4 1 1 1 0\\n'\n" // commands in output
            "!true\n"
            "from_file sphere s 0 0 4 0 0 0 1\n");
  SceneDescription s;
  read_rad_file(s, "main.rad");
  ASSERT_EQ(s.objects.size(), 5u);
  EXPECT_EQ(s.objects[1].name, "from_file");
  EXPECT_EQ(s.objects[2].name, "continued");
  EXPECT_EQ(s.objects[3].name, "nested");
  EXPECT_EQ(s.objects[4].modifier, 1);
  EXPECT_EQ(s.files[s.objects[0].file], "main.rad");
  EXPECT_EQ(s.files[s.objects[1].file], "!cat sub.rad");
  EXPECT_EQ(s.files[s.objects[2].file], "!echo void plastic \\\n continued 0 0 5 1 1 1 0 0");
  EXPECT_EQ(s.files[s.objects[3].file], "!echo void glow nested 0 0 4 1 1 1 0");
  EXPECT_EQ(s.objects[4].line, 7);
  EXPECT_EQ(warnings.list(), (std::vector<std::string>{"(!true): empty file"}));

  // A name starting with '!' is itself a command.
  SceneDescription t;
  read_rad_file(t, "!cat sub.rad main.rad");
  EXPECT_EQ(t.objects.size(), 6u);

  // Errors inside command output name the command and the line within its output.
  SceneDescription u;
  try {
    read_rad_file(u, "!printf 'void light a 0 0 3 1 1 1\\nvoid plastik b'");
    ADD_FAILURE() << "no error";
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "(!printf 'void light a 0 0 3 1 1 1\\nvoid plastik b' line 2): "
                           "unknown type \"plastik\"");
  }
}

// ReadPolicy (what the fuzz targets use): a refused command or file is a FatalError, and the
// command is never run.
TEST_F(RadReader, PolicyRefusesCommandsAndFiles) {
  ScratchDir dir;
  dir.write("sub.rad", "void plastic p 0 0 5 1 1 1 0 0\n");
  ReadPolicy no_commands;
  no_commands.run_commands = false;
  SceneDescription s;
  std::istringstream in("void light l 0 0 3 1 1 1\n!touch ran\n");
  try {
    read_rad_stream(s, in, "t.rad", no_commands);
    ADD_FAILURE() << "no error";
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "cannot execute \"!touch ran\": commands are disabled");
  }
  EXPECT_FALSE(fs::exists("ran"));
  EXPECT_THROW(read_rad_file(s, "!touch ran", no_commands), FatalError);
  EXPECT_FALSE(fs::exists("ran"));
  SceneDescription t;
  read_rad_file(t, "sub.rad", no_commands); // files are still allowed
  EXPECT_EQ(t.objects.size(), 1u);

  ReadPolicy no_files;
  no_files.open_files = false;
  try {
    read_rad_file(t, "sub.rad", no_files);
    ADD_FAILURE() << "no error";
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "cannot open scene file \"sub.rad\": reading files is disabled");
  }
}

TEST_F(RadReader, FailingCommandsAreFatal) {
  ScratchDir dir;
  SceneDescription s;
  EXPECT_THROW(read_rad_file(s, "!exit 3"), FatalError);
  try {
    read_rad_file(s, "!echo void light l 0 0 3 1 1 1; exit 2");
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "(!echo void light l 0 0 3 1 1 1; exit 2): command failed with "
                           "exit status 2");
  }
  dir.write("a.rad", "!cat missing.rad 2>/dev/null\n");
  EXPECT_THROW(read_rad_file(s, "a.rad"), FatalError);
  try {
    read_rad_file(s, "missing.rad");
    ADD_FAILURE() << "no error";
  } catch (const FatalError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open scene file \"missing.rad\""),
              std::string::npos);
  }
  // A command that reads itself forever is stopped.
  dir.write("self.rad", "!cat self.rad\n");
  EXPECT_THROW(read_rad_file(s, "self.rad"), FatalError);
}

TEST_F(RadReader, MultipleFilesShareOneScene) {
  ScratchDir dir;
  dir.write("a.rad", "void plastic m 0 0 5 1 1 1 0 0\n");
  dir.write("b.rad", "\nm sphere s 0 0 4 0 0 0 1\n");
  SceneDescription s;
  read_rad_file(s, "a.rad");
  read_rad_file(s, "b.rad");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[1].modifier, 0);
  EXPECT_EQ(s.objects[1].file, 1);
  EXPECT_EQ(s.objects[1].line, 2);
  EXPECT_EQ(s.files, (std::vector<std::string>{"a.rad", "b.rad"}));
}

// The reference scenes. Expected object counts are the ones Radiance's oconv stored in the
// matching octrees (the object count after the file list in tests/data/scenes/*.oct), and
// agree with counting primitive header lines:
//   awk '!/^[ \t]*#/ && NF>=3 && $1 !~ /^[-+.0-9]/ {n++; t[$2]++} END {...}' FILE.rad
struct RefScene {
  std::vector<std::string> files;
  std::size_t objects;
  std::map<std::string, int> types;
};

TEST_F(RadReader, ReferenceScenesLoad) {
  const std::vector<RefScene> scenes = {
      {{"cornell.rad"},
       21,
       {{"polygon", 13}, {"sphere", 2}, {"plastic", 3}, {"metal", 1}, {"glass", 1}, {"light", 1}}},
      {{"luminaires.rad"},
       23,
       {{"polygon", 11},
        {"sphere", 2},
        {"plastic", 3},
        {"spotlight", 1},
        {"ring", 1},
        {"glass", 1},
        {"light", 2},
        {"illum", 1},
        {"glow", 1}}},
      {{"materials.rad"},
       30,
       {{"mirror", 1},
        {"brightfunc", 1},
        {"polygon", 2},
        {"dielectric", 1},
        {"cup", 1},
        {"trans", 1},
        {"sphere", 7},
        {"source", 2},
        {"metal", 2},
        {"plastic", 3},
        {"cone", 1},
        {"ring", 1},
        {"glass", 1},
        {"bubble", 1},
        {"cylinder", 1},
        {"light", 1},
        {"glow", 2},
        {"tube", 1}}},
      {{"materials_plain.rad"}, 29, {{"sphere", 7}, {"source", 2}, {"glow", 2}}},
      {{"sphere.rad"}, 4, {{"sphere", 1}, {"bubble", 1}, {"plastic", 1}, {"light", 1}}},
      {{"chair.rad"}, 37, {{"polygon", 36}, {"plastic", 1}}},
      {{"office_mat.rad", "office_geom.rad", "office_desk.rad", "office_sky_clear.rad"},
       46,
       {{"polygon", 30},
        {"ring", 1},
        {"cylinder", 1},
        {"source", 3},
        {"glow", 2},
        {"brightfunc", 1},
        {"light", 1},
        {"plastic", 5},
        {"metal", 1},
        {"glass", 1}}},
      {{"office_mat.rad", "office_geom.rad", "office_desk.rad", "office_sky_overcast.rad"},
       44,
       {{"source", 2}, {"glow", 2}, {"brightfunc", 1}}},
      {{"office_mat.rad", "office_geom.rad", "office_desk.rad", "office_sky_clear.rad",
        "furnished.rad"},
       52,
       {{"instance", 3}, {"mesh", 1}, {"plastic", 7}}},
  };
  for (const auto& ref : scenes) {
    SceneDescription s;
    for (const auto& f : ref.files)
      ASSERT_NO_THROW(read_rad_file(s, radcl::test::data("scenes/" + f))) << f;
    EXPECT_EQ(s.objects.size(), ref.objects) << ref.files.back();
    std::map<std::string, int> count;
    for (const auto& o : s.objects)
      ++count[std::string(type_name(o.type))];
    for (const auto& [type, n] : ref.types)
      EXPECT_EQ(count[type], n) << ref.files.back() << " " << type;
    // Every surface's modifier is a modifier defined before it.
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
      std::int32_t m = s.objects[i].modifier;
      if (m == kVoid) continue;
      EXPECT_LT(m, static_cast<std::int32_t>(i));
      EXPECT_TRUE(is_modifier(s.objects[m].type));
    }
  }
  EXPECT_TRUE(warnings.list().empty());
}

TEST_F(RadReader, ReferenceSceneDetails) {
  SceneDescription s;
  read_rad_file(s, radcl::test::data("scenes/cornell.rad"));
  // Object 6 is the floor (after five materials... counted in the file: white, red, green,
  // ceiling_light, brass, clear_glass are objects 0-5).
  EXPECT_EQ(s.objects[6].name, "floor");
  EXPECT_EQ(s.objects[6].type, RC_OBJ_POLYGON);
  EXPECT_EQ(s.objects[6].modifier, 0);
  EXPECT_EQ(s.objects[6].fargs.size(), 12u);
  EXPECT_EQ(s.objects[6].line, 32);

  SceneDescription f;
  read_rad_file(f, radcl::test::data("scenes/furnished.rad"));
  ASSERT_EQ(f.objects.size(), 6u);
  EXPECT_EQ(f.objects[3].sargs,
            (std::vector<std::string>{"chair.oct", "-rz", "180", "-t", "3.5", "3.8", "0"}));
  EXPECT_EQ(f.objects[5].type, RC_OBJ_MESH);
  EXPECT_EQ(f.objects[5].sargs[0], "octa.rtm");

  SceneDescription sky;
  read_rad_file(sky, radcl::test::data("scenes/office_sky_clear.rad"));
  ASSERT_EQ(sky.objects.size(), 7u);
  EXPECT_EQ(sky.objects[2].sargs, (std::vector<std::string>{"skybr", "skybright.cal"}));
  EXPECT_EQ(sky.objects[2].fargs.size(), 7u);
  EXPECT_DOUBLE_EQ(sky.objects[2].fargs[1], 10.2);
  EXPECT_EQ(sky.objects[4].modifier, 3); // sky_glow source sky
  EXPECT_EQ(sky.objects[3].modifier, 2); // skyfunc glow sky_glow
}
