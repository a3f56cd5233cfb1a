// The -o letters: counts, cast-only detection, trace mode and Radiance's errors and warnings.
#include "radcl/options/ray_io.h"
#include "radcl/util/error.h"
#include "warnings.h"

#include <gtest/gtest.h>

using namespace radcl::options;

namespace {
std::string error_of(const char* spec) {
  try {
    parse_output_spec(spec);
  } catch (const radcl::FatalError& e) {
    return e.what();
  }
  return "(no error)";
}
} // namespace

TEST(OutputSpec, CountsAndCastOnly) {
  OutputSpec s = parse_output_spec("oodvVwWlLcpnNsmMrxRX~");
  EXPECT_EQ(s.per_ray, "oodvVwWlLcpnNsmMrxRX~");
  // 5.4a's setrtoutput() counts one component per name letter (s m M), unlike its man page.
  EXPECT_EQ(s.ncomp, 3 * 11 + 1 * 8 + 2);
  EXPECT_FALSE(s.cast_only);
  EXPECT_FALSE(s.trace_mode());
  for (const char* geometric :
       {"o", "d", "w", "L", "c", "p", "N", "s", "m", "M", "~", "odwLcpNsmM~"})
    EXPECT_TRUE(parse_output_spec(geometric).cast_only) << geometric;
  for (const char* shaded : {"v", "V", "W", "l", "n", "r", "x", "R", "X"})
    EXPECT_FALSE(parse_output_spec(shaded).cast_only) << shaded;
  EXPECT_EQ(parse_output_spec("smM").ncomp, 3);
  EXPECT_EQ(parse_output_spec("~").ncomp, 0);
}

TEST(OutputSpec, TraceMode) {
  OutputSpec s = parse_output_spec("vtod");
  EXPECT_EQ(s.per_ray, "v");
  EXPECT_EQ(s.per_traced, "od");
  EXPECT_TRUE(s.trace_mode());
  EXPECT_EQ(s.ncomp, 0);
  EXPECT_FALSE(s.trace_sources);
  s = parse_output_spec("Tp");
  EXPECT_TRUE(s.trace_sources);
  EXPECT_FALSE(s.cast_only);   // tracing needs the renderer
  s = parse_output_spec("vt"); // a final t asks for nothing
  EXPECT_FALSE(s.trace_mode());
  EXPECT_EQ(s.ncomp, 3);
  EXPECT_EQ(parse_output_spec("otd").per_ray, "o");
  s = parse_output_spec("vtdto"); // a second t restarts the traced list
  EXPECT_EQ(s.per_traced, "o");
}

// radcl's own letter e: the value's standard error, three numbers, once per input ray.
TEST(OutputSpec, StandardError) {
  OutputSpec s = parse_output_spec("ve");
  EXPECT_EQ(s.per_ray, "ve");
  EXPECT_EQ(s.ncomp, 6);
  EXPECT_FALSE(parse_output_spec("e").cast_only);
  EXPECT_EQ(parse_output_spec("etv").per_ray, "e");
  EXPECT_EQ(error_of("vte"), "-oe is not a traced ray's output");
  RenderOptions r = RenderOptions::rtrace_defaults();
  r.ambient_bounces = 1; // -aa 0.1: the cache
  try {
    check_output_spec("ve", parse_output_spec("ve"), r, true);
    ADD_FAILURE() << "-oe with the cache";
  } catch (const radcl::FatalError& e) {
    EXPECT_STREQ(e.what(), "-oe requires -aa 0 (no irradiance cache)");
  }
  r.ambient_accuracy = 0;
  EXPECT_NO_THROW(check_output_spec("ve", parse_output_spec("ve"), r, true));
  r.ambient_accuracy = 0.1;
  r.ambient_bounces = 0; // no ambient bounce: no cache either
  EXPECT_NO_THROW(check_output_spec("ve", parse_output_spec("ve"), r, true));
}

TEST(OutputSpec, Errors) {
  EXPECT_EQ(error_of(""), "empty output specification");
  EXPECT_EQ(error_of("vq"), "unrecognized output option 'q'");
  EXPECT_EQ(error_of("-"), "unrecognized output option '-'");
}

TEST(OutputSpec, ChecksAgainstOptions) {
  radcl::test::CapturedWarnings warnings;
  RenderOptions r = RenderOptions::rtrace_defaults();
  check_output_spec("v", parse_output_spec("v"), r, false);
  EXPECT_TRUE(warnings.list().empty());
  check_output_spec("VW", parse_output_spec("VW"), r, false);
  EXPECT_EQ(warnings.list(), (std::vector<std::string>{"-oVW options require trace mode",
                                                       "-oVW options require trace mode"}));
  warnings.list().clear();
  r.ambient_bounces = 1;
  check_output_spec("vtV", parse_output_spec("vtV"), r, false);
  EXPECT_EQ(warnings.list(), (std::vector<std::string>{"-otV accuracy depends on -aa 0 -as 0"}));
  warnings.list().clear();
  r.ambient_accuracy = 0;
  r.ambient_supersamples = 0;
  check_output_spec("vtVW", parse_output_spec("vtVW"), r, false);
  EXPECT_TRUE(warnings.list().empty());
  check_output_spec("vr", parse_output_spec("vr"), r, true);
  EXPECT_EQ(warnings.list(),
            (std::vector<std::string>{"-orRxX options incompatible with -I+ and -i+"}));
  r.irradiance = true;
  try {
    check_output_spec("od", parse_output_spec("od"), r, false);
    FAIL();
  } catch (const radcl::FatalError& e) {
    EXPECT_STREQ(e.what(), "-I+ and -i+ options require some value output");
  }
}

TEST(OutputSpec, ColourFormat) {
  for (const char* ok : {"v", "r", "x"})
    EXPECT_NO_THROW(check_output_format(ok, 'c'));
  for (const char* bad : {"vv", "o", "vr", "l"}) {
    try {
      check_output_format(bad, 'c');
      FAIL() << bad;
    } catch (const radcl::FatalError& e) {
      EXPECT_STREQ(e.what(), "color format only with -ov, -or, -ox");
    }
  }
  EXPECT_NO_THROW(check_output_format("oodv", 'f'));
  EXPECT_STREQ(format_name('a'), "ascii");
  EXPECT_STREQ(format_name('f'), "float");
  EXPECT_STREQ(format_name('d'), "double");
  EXPECT_STREQ(format_name('c'), "32-bit_rle_rgbe");
}
