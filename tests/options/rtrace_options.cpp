// rtrace's command line: defaults, every option kind, errors with Radiance's messages, and
// the -defaults listing of Radiance 5.4a (docs/radiance/cli-rtrace-rpict.md §3.10).
#include "radcl/options/rtrace_options.h"
#include "radcl/util/error.h"
#include "temp_dir.h"
#include "warnings.h"

#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

using namespace radcl::options;

namespace {

const char* const kRtraceDefaults =
    "-n 1 \t\t\t\t# number of rendering processes\n"
    "-x 0        \t\t\t# flush interval\n"
    "-y 0        \t\t\t# y resolution\n"
    "-ld-\t\t\t\t# limit distance off\n"
    "-h+\t\t\t\t# output header\n"
    "-faa\t\t\t\t# format input/output = ascii/ascii\n"
    "-ov        \t\t\t# output value\n"
    "-w+\t\t\t\t# warning messages on\n"
    "-i-\t\t\t\t# irradiance calculation off\n"
    "-u+\t\t\t\t# uncorrelated Monte Carlo sampling\n"
    "-bv+\t\t\t\t# back face visibility on\n"
    "-dt 0.030000\t\t\t# direct threshold\n"
    "-dc 0.750000\t\t\t# direct certainty\n"
    "-dj 0.000000\t\t\t# direct jitter\n"
    "-ds 0.200000\t\t\t# direct sampling\n"
    "-dr 2        \t\t\t# direct relays\n"
    "-dp 512      \t\t\t# direct pretest density\n"
    "-dv+\t\t\t\t# direct visibility on\n"
    "-ss 1.000000\t\t\t# specular sampling\n"
    "-st 0.150000\t\t\t# specular threshold\n"
    "-av 0.000000 0.000000 0.000000\t# ambient value\n"
    "-aw 0        \t\t\t# ambient value weight\n"
    "-ab 0        \t\t\t# ambient bounces\n"
    "-aa 0.100000\t\t\t# ambient accuracy\n"
    "-ar 256      \t\t\t# ambient resolution\n"
    "-ad 1024     \t\t\t# ambient divisions\n"
    "-as 512      \t\t\t# ambient super-samples\n"
    "-me 0.00e+00 0.00e+00 0.00e+00\t# mist extinction coefficient\n"
    "-ma 0.000000 0.000000 0.000000\t# mist scattering albedo\n"
    "-mg 0.000000\t\t\t# mist scattering eccentricity\n"
    "-ms 0.000000\t\t\t# mist sampling distance\n"
    "-lr -10      \t\t\t# limit reflection (Russian roulette)\n"
    "-lw 2.00e-03\t\t\t# limit weight\n"
    "-am 0.0\t\t\t\t# max photon search radius\n";

RtraceCommand parse(std::vector<std::string> args) {
  args.insert(args.begin(), "rtrace");
  return parse_rtrace_command_line(args);
}

std::string error_of(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const radcl::FatalError& e) {
    return e.what();
  }
  return "(no error)";
}

} // namespace

TEST(RtraceOptions, Defaults) {
  RtraceCommand c = parse({"scene.oct"});
  const RtraceOptions& o = c.opt;
  EXPECT_EQ(c.action, ParsedCommand::Action::Run);
  EXPECT_EQ(rtrace_octree(c), "scene.oct");
  EXPECT_EQ(o.nproc, 1);
  EXPECT_EQ(o.output_spec, "v");
  EXPECT_EQ(o.in_format, 'a');
  EXPECT_EQ(o.out_format, 'a');
  EXPECT_TRUE(o.header);
  EXPECT_TRUE(o.render.uncorrelated);
  EXPECT_EQ(o.render.max_depth, -10);
  EXPECT_DOUBLE_EQ(o.render.min_weight, 2e-3);
  EXPECT_EQ(o.render.ambient_divisions, 1024);
}

TEST(RtraceOptions, DefaultsListingMatchesRadiance) {
  RtraceCommand c = parse({"-defaults"});
  EXPECT_EQ(c.action, ParsedCommand::Action::PrintDefaults);
  EXPECT_EQ(format_rtrace_defaults(c.opt), kRtraceDefaults);
  EXPECT_EQ(parse({"-help"}).action, ParsedCommand::Action::PrintDefaults);
  EXPECT_EQ(parse({"-version", "-bogus"}).action, ParsedCommand::Action::PrintVersion);
}

TEST(RtraceOptions, DefaultsListingShowsChangedValues) {
  RtraceCommand c =
      parse({"-I",   "-n",        "3",   "-x",  "16",   "-y",   "8",    "-ld",       "-h-",
             "-ffc", "-ovodTnW~", "-w-", "-i+", "-u-",  "-bv-", "-dv0", "-dt",       "0.5",
             "-dr",  "3",         "-av", "1",   "2",    "3",    "-me",  "1e-3",      "0",
             "2",    "-lr",       "5",   "-lw", "1e-4", "-am",  "0.25", "-defaults", "ignored"});
  std::string s = format_rtrace_defaults(c.opt);
  EXPECT_EQ(s.substr(0, s.find("-i+")),
            "-I+\t\t\t\t# immediate irradiance on\n"
            "-n 3 \t\t\t\t# number of rendering processes\n"
            "-x 16       \t\t\t# x resolution\n"
            "-y 8        \t\t\t# y resolution\n"
            "-ld+\t\t\t\t# limit distance on\n"
            "-h-\t\t\t\t# no header\n"
            "-ffc\t\t\t\t# format input/output = float/32-bit_rle_rgbe\n"
            "-ovodTnW~  \t\t\t# output value origin direction trace normal coefficient\n"
            "-w-\t\t\t\t# warning messages off\n");
  for (const char* line :
       {"-i+\t\t\t\t# irradiance calculation on\n",
        "-u-\t\t\t\t# correlated quasi-Monte Carlo sampling\n",
        "-bv-\t\t\t\t# back face visibility off\n", "-dv-\t\t\t\t# direct visibility off\n",
        "-dt 0.500000\t\t\t# direct threshold\n", "-dr 3        \t\t\t# direct relays\n",
        "-av 1.000000 2.000000 3.000000\t# ambient value\n",
        "-me 1.00e-03 0.00e+00 2.00e+00\t# mist extinction coefficient\n",
        "-lr 5        \t\t\t# limit reflection\n", "-lw 1.00e-04\t\t\t# limit weight\n",
        "-am 0.2\t\t\t\t# max photon search radius\n"})
    EXPECT_NE(s.find(line), std::string::npos) << line;
}

TEST(RtraceOptions, EveryRenderOption) {
  RtraceCommand c = parse(
      {"-u",    "-bv-", "-dt", ".1",  "-dc",  ".2",  "-dj", ".3",  "-ds",      ".4",  "-dr", "5",
       "-dp",   "6",    "-dv", "-ss", "7",    "-st", ".8",  "-av", "1",        "2",   "3",   "-aw",
       "9",     "-ab",  "10",  "-aa", ".11",  "-ar", "12",  "-ad", "13",       "-as", "14",  "-af",
       "a.amb", "-me",  "1",   "2",   "3",    "-ma", ".4",  ".5",  ".6",       "-mg", ".7",  "-ms",
       ".8",    "-lr",  "-3",  "-lw", "1e-5", "-i",  "-am", "2.5", "scene.oct"});
  const RenderOptions& r = c.opt.render;
  EXPECT_FALSE(r.uncorrelated);
  EXPECT_FALSE(r.back_visible);
  EXPECT_DOUBLE_EQ(r.direct_threshold, .1);
  EXPECT_DOUBLE_EQ(r.direct_certainty, .2);
  EXPECT_DOUBLE_EQ(r.direct_jitter, .3);
  EXPECT_DOUBLE_EQ(r.direct_sampling, .4);
  EXPECT_EQ(r.direct_relays, 5);
  EXPECT_EQ(r.direct_pretest, 6);
  EXPECT_FALSE(r.direct_visible);
  EXPECT_DOUBLE_EQ(r.specular_sampling, 7);
  EXPECT_DOUBLE_EQ(r.specular_threshold, .8);
  EXPECT_EQ(r.ambient_value, (Rgb{1, 2, 3}));
  EXPECT_EQ(r.ambient_value_weight, 9);
  EXPECT_EQ(r.ambient_bounces, 10);
  EXPECT_DOUBLE_EQ(r.ambient_accuracy, .11);
  EXPECT_EQ(r.ambient_resolution, 12);
  EXPECT_EQ(r.ambient_divisions, 13);
  EXPECT_EQ(r.ambient_supersamples, 14);
  EXPECT_EQ(r.ambient_file, "a.amb");
  EXPECT_EQ(r.mist_extinction, (Rgb{1, 2, 3}));
  EXPECT_EQ(r.mist_albedo, (Rgb{.4, .5, .6}));
  EXPECT_DOUBLE_EQ(r.mist_eccentricity, .7);
  EXPECT_DOUBLE_EQ(r.mist_sampling, .8);
  EXPECT_EQ(r.max_depth, -3);
  EXPECT_DOUBLE_EQ(r.min_weight, 1e-5);
  EXPECT_TRUE(r.irradiance);
  EXPECT_DOUBLE_EQ(r.photon_max_radius, 2.5);
  EXPECT_EQ(rtrace_octree(c), "scene.oct");
}

TEST(RtraceOptions, EveryRtraceOption) {
  RtraceCommand c = parse({"-n", "4", "-x", "10", "-y", "20", "-w", "-e", "err.log", "-ld+", "-I+",
                           "-fd", "-ooL", "-ov~p", "-h", "scene.oct"});
  const RtraceOptions& o = c.opt;
  EXPECT_EQ(o.nproc, 4);
  EXPECT_EQ(o.xres, 10);
  EXPECT_EQ(o.yres, 20);
  EXPECT_FALSE(o.warnings);
  EXPECT_EQ(o.error_file, "err.log");
  EXPECT_TRUE(o.limit_distance);
  EXPECT_TRUE(o.immediate_irradiance);
  EXPECT_EQ(o.in_format, 'd');
  EXPECT_EQ(o.out_format, 'd');
  EXPECT_EQ(o.output_spec, "v~p"); // the last -o wins
  EXPECT_FALSE(o.header);
  EXPECT_EQ(parse({"-faf", "x"}).opt.out_format, 'f');
  EXPECT_EQ(parse({"-ffa", "x"}).opt.in_format, 'f');
  EXPECT_EQ(parse({"-fac", "x"}).opt.out_format, 'c');
  EXPECT_EQ(parse({"-P", "pf", "x"}).opt.persist, RtraceOptions::Persist::Single);
  EXPECT_EQ(parse({"-PP", "pf", "x"}).opt.persist_file, "pf");
  EXPECT_EQ(parse({"-o", "x"}).opt.output_spec, ""); // rejected later, by parse_output_spec
}

TEST(RtraceOptions, ModifierLists) {
  const radcl::test::TempFolder dir("opt");
  std::string f = (dir / "names.txt").string();
  std::ofstream(f) << "glass\n  window \tdoor\n";
  RtraceCommand c = parse({"-ae", "a", "-ae", "b", "x"});
  EXPECT_EQ(c.opt.render.ambient_list.kind, ModifierList::Kind::Exclude);
  EXPECT_EQ(c.opt.render.ambient_list.names, (std::vector<std::string>{"a", "b"}));
  // Switching to include restarts the list; a file adds its words.
  c = parse({"-ae", "a", "-ai", "b", "-aI", f, "x"});
  EXPECT_EQ(c.opt.render.ambient_list.kind, ModifierList::Kind::Include);
  EXPECT_EQ(c.opt.render.ambient_list.names,
            (std::vector<std::string>{"b", "glass", "window", "door"}));
  c = parse({"-aE", f, "-ae", "x1", "x"});
  EXPECT_EQ(c.opt.render.ambient_list.names,
            (std::vector<std::string>{"glass", "window", "door", "x1"}));
  c = parse({"-ti", "t1", "-tE", f, "-te", "t2", "x"});
  EXPECT_EQ(c.opt.trace_list.kind, ModifierList::Kind::Exclude);
  EXPECT_EQ(c.opt.trace_list.names, (std::vector<std::string>{"glass", "window", "door", "t2"}));
  EXPECT_EQ(error_of({"-aI", "/no/such/file", "x"}),
            "cannot open ambient include file \"/no/such/file\"");
  EXPECT_EQ(error_of({"-aE", "/no/such/file", "x"}),
            "cannot open ambient exclude file \"/no/such/file\"");
  EXPECT_EQ(error_of({"-tI", "/no/such/file", "x"}),
            "cannot open trace include file \"/no/such/file\"");
  EXPECT_EQ(error_of({"-tE", "/no/such/file", "x"}),
            "cannot open trace exclude file \"/no/such/file\"");
  // Files are looked up with the caller's finder (RAYPATH in the front end).
  RtraceCommand found =
      parse_rtrace_command_line({"rtrace", "-aI", "names.txt", "x"}, [&](const std::string& n) {
        return n == "names.txt" ? f : std::string();
      });
  EXPECT_EQ(found.opt.render.ambient_list.names.size(), 3u);
}

TEST(RtraceOptions, PhotonMaps) {
  radcl::test::CapturedWarnings warnings;
  RtraceCommand c = parse({"-ap", "g.pm", "x"});
  ASSERT_EQ(c.opt.render.photon_maps.size(), 1u);
  EXPECT_EQ(c.opt.render.photon_maps[0].min_gather, 40);
  EXPECT_EQ(c.opt.render.ambient_bounces, 1); // a photon map implies -ab 1
  EXPECT_EQ(warnings.list(),
            (std::vector<std::string>{"missing photon lookup bandwidth, defaulting to 40"}));
  c = parse({"-ab", "3", "-ap", "g.pm", "50", "-ap", "c.pm", "20", "80", "x"});
  ASSERT_EQ(c.opt.render.photon_maps.size(), 2u);
  EXPECT_EQ(c.opt.render.ambient_bounces, 3);
  EXPECT_EQ(c.opt.render.photon_maps[0].max_gather, 50);
  EXPECT_EQ(c.opt.render.photon_maps[1].min_gather, 20);
  EXPECT_EQ(c.opt.render.photon_maps[1].max_gather, 80);
  EXPECT_EQ(rtrace_octree(c), "x");
  EXPECT_EQ(error_of({"-ap", "g.pm", "80", "20", "x"}), "command line error at '-ap'");
  EXPECT_EQ(error_of({"-ap", "g.pm", "0", "x"}), "command line error at '-ap'");
  EXPECT_EQ(error_of({"-am", "0", "x"}), "invalid max photon search radius");
  EXPECT_EQ(error_of({"-am", "x"}), "invalid max photon search radius");
}

TEST(RtraceOptions, Errors) {
  EXPECT_EQ(error_of({"-ab", "1.0", "x"}), "command line error at '-ab'");
  EXPECT_EQ(error_of({"-ab2", "x"}), "command line error at '-ab2'");
  EXPECT_EQ(error_of({"-ab"}), "command line error at '-ab'");
  EXPECT_EQ(error_of({"-av", "1", "2", "x"}), "command line error at '-av'");
  EXPECT_EQ(error_of({"-dt", "inf", "x"}), "command line error at '-dt'");
  EXPECT_EQ(error_of({"-zz", "x"}), "command line error at '-zz'");
  EXPECT_EQ(error_of({"-", "x"}), "command line error at '-'");
  EXPECT_EQ(error_of({"-u2", "x"}), "command line error at '-u2'");
  EXPECT_EQ(error_of({"-lx", "x"}), "command line error at '-lx'");
  EXPECT_EQ(error_of({"-fx", "x"}), "command line error at '-fx'");
  EXPECT_EQ(error_of({"-fa", "x"}), "(no error)");
  EXPECT_EQ(error_of({"-facx", "x"}), "command line error at '-facx'");
  EXPECT_EQ(error_of({"-faq", "x"}), "command line error at '-faq'");
  EXPECT_EQ(error_of({"-af", "", "x"}), "command line error at '-af'");
  EXPECT_EQ(error_of({"-n", "0", "x"}), "bad number of processes");
  EXPECT_EQ(error_of({"-n", "2", "-P", "pf", "x"}),
            "multiprocessing incompatible with persist file");
  EXPECT_EQ(error_of({"$RADCL_SURELY_UNSET_VAR", "x"}), "cannot expand '$RADCL_SURELY_UNSET_VAR'");
  try {
    rtrace_octree(parse({"-ab", "1"}));
    FAIL();
  } catch (const radcl::FatalError& e) {
    EXPECT_STREQ(e.what(), "missing octree argument");
  }
  try {
    rtrace_octree(parse({"a.oct", "b.oct"}));
    FAIL();
  } catch (const radcl::FatalError& e) {
    EXPECT_STREQ(e.what(), "command line error at 'a.oct'");
  }
}

TEST(RtraceOptions, ParsingStopsAtFirstOperand) {
  RtraceCommand c = parse({"-ab", "2", "scene.oct", "-ab", "3"});
  EXPECT_EQ(c.opt.render.ambient_bounces, 2);
  EXPECT_EQ(c.operand, 3u);
  EXPECT_EQ(c.args.size(), 6u);
}

TEST(RtraceOptions, ArgumentFileExpansion) {
  const radcl::test::TempFolder dir("opt");
  std::string f = (dir / "opts").string();
  std::ofstream(f) << "-ab 2 -ad 256\n-aa 0.2\n";
  setenv("RADCL_OPT_OCT", "scene.oct", 1);
  RtraceCommand c = parse({"@" + f, "-as", "32", "$RADCL_OPT_OCT"});
  EXPECT_EQ(c.opt.render.ambient_bounces, 2);
  EXPECT_EQ(c.opt.render.ambient_divisions, 256);
  EXPECT_DOUBLE_EQ(c.opt.render.ambient_accuracy, 0.2);
  EXPECT_EQ(c.opt.render.ambient_supersamples, 32);
  EXPECT_EQ(rtrace_octree(c), "scene.oct"); // the operand is expanded too
  EXPECT_EQ(c.args, (std::vector<std::string>{"rtrace", "-ab", "2", "-ad", "256", "-aa", "0.2",
                                              "-as", "32", "scene.oct"}));
}
