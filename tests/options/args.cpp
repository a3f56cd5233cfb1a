// Radiance's argument conventions: number syntax, @file/$VAR expansion, boolean suffixes.
#include "radcl/options/args.h"
#include "radcl/util/error.h"
#include "temp_dir.h"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

using namespace radcl::options;

TEST(Args, IntegerSyntax) {
  EXPECT_TRUE(is_int("12"));
  EXPECT_TRUE(is_int("-3"));
  EXPECT_TRUE(is_int("+7"));
  EXPECT_TRUE(is_int("  5"));
  EXPECT_FALSE(is_int("1.0"));
  EXPECT_FALSE(is_int(""));
  EXPECT_FALSE(is_int("-"));
  EXPECT_FALSE(is_int("4x"));
  EXPECT_FALSE(is_int("5 "));
  EXPECT_TRUE(is_int("5 ", true));
  EXPECT_TRUE(is_int("5\tx", true));
}

TEST(Args, RealSyntax) {
  for (const char* ok : {"1", "1.", ".5", "-.5", "+2.5e3", "1e-3", "1E+07", "0.000"})
    EXPECT_TRUE(is_real(ok)) << ok;
  for (const char* bad : {".", "-", "e5", "1e", "1e+", "1.5x", "inf", "nan", "1e 5", "", "--1"})
    EXPECT_FALSE(is_real(bad)) << bad;
  EXPECT_TRUE(is_real("2.5 -vd", true));
  EXPECT_FALSE(is_real("2.5,", true));
}

TEST(Args, SplitWords) {
  EXPECT_EQ(split_words("  a\tb\n\nc  "), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_TRUE(split_words(" \n").empty());
}

TEST(Args, BoolSuffix) {
  bool v = false;
  EXPECT_TRUE(apply_bool_suffix("-u", 2, v));
  EXPECT_TRUE(v);
  EXPECT_TRUE(apply_bool_suffix("-u", 2, v));
  EXPECT_FALSE(v);
  for (const char* on : {"-u+", "-uy", "-uY", "-ut", "-uT", "-u1"}) {
    v = false;
    EXPECT_TRUE(apply_bool_suffix(on, 2, v));
    EXPECT_TRUE(v) << on;
  }
  for (const char* off : {"-u-", "-un", "-uN", "-uf", "-uF", "-u0"}) {
    v = true;
    EXPECT_TRUE(apply_bool_suffix(off, 2, v));
    EXPECT_FALSE(v) << off;
  }
  EXPECT_FALSE(apply_bool_suffix("-ux", 2, v));
  v = false;
  EXPECT_TRUE(apply_bool_suffix("-u+junk", 2, v)); // Radiance looks at one character only
  EXPECT_TRUE(v);
}

TEST(Args, ValuesOk) {
  ArgList a({"rtrace", "-av", "1", "2.5", ".3", "-ab", "1.0", "-af", "", "-x"});
  EXPECT_TRUE(a.values_ok(1, "fff"));
  EXPECT_FALSE(a.values_ok(1, "ffff")); // "-ab" is not a number
  EXPECT_TRUE(a.values_ok(1, "iff"));
  EXPECT_FALSE(a.values_ok(5, "i"));
  EXPECT_TRUE(a.values_ok(5, "f"));
  EXPECT_FALSE(a.values_ok(7, "s")); // empty string
  EXPECT_FALSE(a.values_ok(9, "i")); // missing
  EXPECT_TRUE(a.values_ok(9, ""));
}

TEST(Args, ExpandFileAndEnvironment) {
  const radcl::test::TempFolder dir("opt");
  std::string f1 = (dir / "a.opt").string(), f2 = (dir / "b.opt").string();
  std::ofstream(f1) << "-ab 2\n  @" << f2 << "\t-aa .1\n";
  std::ofstream(f2) << "-ad 64 $RADCL_OPT_TEST";
  setenv("RADCL_OPT_TEST", " -as  8 ", 1);
  ArgList a({"rtrace", "@" + f1, "x.oct"});
  a.expand(1);
  EXPECT_EQ(a.words(),
            (std::vector<std::string>{"rtrace", "-ab", "2", "@" + f2, "-aa", ".1", "x.oct"}));
  a.expand(3); // repeats at the same position: the file, then the variable inside it
  EXPECT_EQ(a.words(), (std::vector<std::string>{"rtrace", "-ab", "2", "-ad", "64",
                                                 "$RADCL_OPT_TEST", "-aa", ".1", "x.oct"}));
  a.expand(5);
  EXPECT_EQ(a[5], "-as");
  EXPECT_EQ(a[6], "8");
  a.expand(8); // plain words stay
  EXPECT_EQ(a[8], ".1");

  unsetenv("RADCL_OPT_UNSET");
  ArgList bad({"rtrace", "$RADCL_OPT_UNSET", "@/nonexistent/file"});
  try {
    bad.expand(1);
    FAIL();
  } catch (const radcl::SystemError& e) { // Radiance's "system -" error, exit status 2
    EXPECT_STREQ(e.what(), "cannot expand '$RADCL_OPT_UNSET'");
  }
  try {
    bad.expand(2);
    FAIL();
  } catch (const radcl::FatalError& e) {
    EXPECT_STREQ(e.what(), "cannot expand '@/nonexistent/file': No such file or directory");
  }
  // An empty file expands to nothing.
  std::ofstream(f1, std::ios::trunc) << "  \n";
  ArgList empty({"rtrace", "@" + f1, "x.oct"});
  empty.expand(1);
  EXPECT_EQ(empty.words(), (std::vector<std::string>{"rtrace", "x.oct"}));
}

// Words are split at white space as Radiance's wordfile() does: quotes stay in the words, any
// number of words and lines expand, and a file that names itself stops with an error.
TEST(Args, FileExpansionLimits) {
  const radcl::test::TempFolder dir("args");
  const std::string many = (dir / "many.opt").string(), self = (dir / "self.opt").string();
  {
    std::ofstream f(many);
    f << "-av \"0.1 '0.2\"\n";
    for (int i = 0; i < 5000; ++i)
      f << "-ab " << i % 3 << (i % 7 == 0 ? "\n" : " ");
  }
  ArgList a({"rpict", "@" + many, "x.oct"});
  a.expand(1);
  ASSERT_EQ(a.size(), 1u + 3u + 10000u + 1u);
  EXPECT_EQ(a[2], "\"0.1");
  EXPECT_EQ(a[3], "'0.2\"");
  EXPECT_EQ(a[a.size() - 2], "1"); // 4999 % 3
  EXPECT_EQ(a[a.size() - 1], "x.oct");

  std::ofstream(self) << "@" << self << "\n";
  ArgList loop({"rtrace", "@" + self, "x.oct"});
  try {
    loop.expand(1);
    FAIL();
  } catch (const radcl::FatalError& e) {
    EXPECT_NE(std::string(e.what()).find("nested expansions"), std::string::npos) << e.what();
  }
}
