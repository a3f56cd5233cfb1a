// rpict's command line: view and picture options, -vf, and the -defaults listing of Radiance
// 5.4a (docs/radiance/cli-rtrace-rpict.md §4.6).
#include "radcl/options/rpict_options.h"
#include "radcl/util/error.h"

#include "test_env.h"

#include <gtest/gtest.h>
#include <sstream>

using namespace radcl::options;

namespace {

const char* const kRpictDefaults = "-vtv\t\t\t\t# view type perspective\n"
                                   "-vp 0.000000 0.000000 0.000000\t# view point\n"
                                   "-vd 0.000000 1.000000 0.000000\t# view direction\n"
                                   "-vu 0.000000 0.000000 1.000000\t# view up\n"
                                   "-vh 45.000000\t\t\t# view horizontal size\n"
                                   "-vv 45.000000\t\t\t# view vertical size\n"
                                   "-vo 0.000000\t\t\t# view fore clipping plane\n"
                                   "-va 0.000000\t\t\t# view aft clipping plane\n"
                                   "-vs 0.000000\t\t\t# view shift\n"
                                   "-vl 0.000000\t\t\t# view lift\n"
                                   "-x  512      \t\t\t# x resolution\n"
                                   "-y  512      \t\t\t# y resolution\n"
                                   "-pa 1.000000\t\t\t# pixel aspect ratio\n"
                                   "-pj 0.670000\t\t\t# pixel jitter\n"
                                   "-pm 0.000000\t\t\t# pixel motion\n"
                                   "-pd 0.000000\t\t\t# pixel depth-of-field\n"
                                   "-ps 4        \t\t\t# pixel sample\n"
                                   "-pt 0.050000\t\t\t# pixel threshold\n"
                                   "-t  0        \t\t\t# time between reports\n"
                                   "-w+\t\t\t\t# warning messages on\n"
                                   "-i-\t\t\t\t# irradiance calculation off\n"
                                   "-u-\t\t\t\t# correlated quasi-Monte Carlo sampling\n"
                                   "-bv+\t\t\t\t# back face visibility on\n"
                                   "-dt 0.050000\t\t\t# direct threshold\n"
                                   "-dc 0.500000\t\t\t# direct certainty\n"
                                   "-dj 0.000000\t\t\t# direct jitter\n"
                                   "-ds 0.250000\t\t\t# direct sampling\n"
                                   "-dr 1        \t\t\t# direct relays\n"
                                   "-dp 512      \t\t\t# direct pretest density\n"
                                   "-dv+\t\t\t\t# direct visibility on\n"
                                   "-ss 1.000000\t\t\t# specular sampling\n"
                                   "-st 0.150000\t\t\t# specular threshold\n"
                                   "-av 0.000000 0.000000 0.000000\t# ambient value\n"
                                   "-aw 0        \t\t\t# ambient value weight\n"
                                   "-ab 0        \t\t\t# ambient bounces\n"
                                   "-aa 0.200000\t\t\t# ambient accuracy\n"
                                   "-ar 64       \t\t\t# ambient resolution\n"
                                   "-ad 512      \t\t\t# ambient divisions\n"
                                   "-as 128      \t\t\t# ambient super-samples\n"
                                   "-me 0.00e+00 0.00e+00 0.00e+00\t# mist extinction coefficient\n"
                                   "-ma 0.000000 0.000000 0.000000\t# mist scattering albedo\n"
                                   "-mg 0.000000\t\t\t# mist scattering eccentricity\n"
                                   "-ms 0.000000\t\t\t# mist sampling distance\n"
                                   "-lr 7        \t\t\t# limit reflection\n"
                                   "-lw 1.00e-03\t\t\t# limit weight\n"
                                   "-am 0.0\t\t\t\t# max photon search radius\n";

RpictCommand parse(std::vector<std::string> args, std::istream* in = nullptr) {
  args.insert(args.begin(), "rpict");
  return parse_rpict_command_line(args, default_find_file, in);
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

TEST(RpictOptions, DefaultsListingMatchesRadiance) {
  RpictCommand c = parse({"-defaults"});
  EXPECT_EQ(c.action, ParsedCommand::Action::PrintDefaults);
  EXPECT_EQ(format_rpict_defaults(c.opt), kRpictDefaults);
}

TEST(RpictOptions, DefaultsListingShowsChangedValues) {
  // The view is listed as given (not normalized), as Radiance prints it before setview().
  RpictCommand c = parse({"-vth", "-vd", "0", "2", "0", "-x", "64", "-ps", "2", "-t", "30", "-pj",
                          "0", "-w", "-help"});
  std::string s = format_rpict_defaults(c.opt);
  for (const char* line :
       {"-vth\t\t\t\t# view type hemispherical\n",
        "-vd 0.000000 2.000000 0.000000\t# view direction\n", "-x  64       \t\t\t# x resolution\n",
        "-ps 2        \t\t\t# pixel sample\n", "-t  30       \t\t\t# time between reports\n",
        "-pj 0.000000\t\t\t# pixel jitter\n", "-w-\t\t\t\t# warning messages off\n"})
    EXPECT_NE(s.find(line), std::string::npos) << line;
  EXPECT_NE(format_rpict_defaults(parse({"-vtq", "-defaults"}).opt).find("# view type unknown"),
            std::string::npos);
}

TEST(RpictOptions, EveryOption) {
  RpictCommand c =
      parse({"-vtl", "-vp", "1",  "2",   "3",         "-vd", "0",        "0",   "-2",      "-vu",
             "0",    "1",   "0",  "-vh", "10",        "-vv", "5",        "-vo", "1",       "-va",
             "9",    "-vs", ".1", "-vl", "-.2",       "-x",  "100",      "-y",  "50",      "-pa",
             "0",    "-ps", "2",  "-pt", ".1",        "-pj", ".5",       "-pm", ".3",      "-pd",
             ".05",  "-S",  "3",  "-o",  "f%03d.hdr", "-z",  "z.dpt",    "-r",  "old.hdr", "-t",
             "60",   "-w-", "-e", "err", "-ab",       "2",   "scene.oct"});
  const RpictOptions& o = c.opt;
  EXPECT_EQ(o.view.type, 'l');
  EXPECT_EQ(o.view.point, (Vec3{1, 2, 3}));
  EXPECT_EQ(o.view.direction, (Vec3{0, 0, -1})); // normalized by the view setup
  EXPECT_DOUBLE_EQ(o.view.focal, 2.0);
  EXPECT_DOUBLE_EQ(o.view.horiz, 10);
  EXPECT_DOUBLE_EQ(o.view.fore, 1);
  EXPECT_DOUBLE_EQ(o.view.aft, 9);
  EXPECT_DOUBLE_EQ(o.view.shift, .1);
  EXPECT_DOUBLE_EQ(o.view.lift, -.2);
  EXPECT_EQ(o.xres, 100);
  EXPECT_EQ(o.yres, 50);
  EXPECT_DOUBLE_EQ(o.pixel_aspect, 0);
  EXPECT_EQ(o.pixel_sample, 2);
  EXPECT_DOUBLE_EQ(o.pixel_threshold, .1);
  EXPECT_DOUBLE_EQ(o.pixel_jitter, .5);
  EXPECT_DOUBLE_EQ(o.pixel_motion, .3);
  EXPECT_DOUBLE_EQ(o.pixel_aperture, .05);
  EXPECT_EQ(o.sequence_start, 3);
  EXPECT_EQ(o.output_file, "f%03d.hdr");
  EXPECT_EQ(o.z_file, "z.dpt");
  EXPECT_EQ(o.recover_file, "old.hdr");
  EXPECT_EQ(o.report_interval, 60);
  EXPECT_FALSE(o.warnings);
  EXPECT_EQ(o.error_file, "err");
  EXPECT_EQ(o.render.ambient_bounces, 2);
  EXPECT_FALSE(o.render.uncorrelated);
  EXPECT_EQ(rpict_octree(c), "scene.oct");

  RpictCommand ro = parse({"-ro", "pic.hdr"});
  EXPECT_EQ(ro.opt.recover_file, "pic.hdr");
  EXPECT_EQ(ro.opt.output_file, "pic.hdr");
  EXPECT_EQ(rpict_octree(ro), ""); // octree from stdin
}

TEST(RpictOptions, ViewFiles) {
  // A view file written by rview, then a picture header: both its rpict command line and its
  // VIEW= line are view lines.
  RpictCommand c = parse({"-vf", radcl::test::data("scenes/materials.vf"), "-vh", "50"});
  EXPECT_EQ(format_view(c.opt.view),
            " -vtv -vp 0 -7 2.2 -vd 0 1 -0.25 -vu 0 0 1 -vh 50 -vv 40 -vo 0 -va 0 -vs 0 -vl 0");
  c = parse({"-vh", "10", "-vf", radcl::test::data("results/materials_view_header.txt")});
  EXPECT_EQ(format_view(c.opt.view),
            " -vtv -vp 0 -7 2.2 -vd 0 1 -0.25 -vu 0 0 1 -vh 60 -vv 40 -vo 0 -va 0 -vs 0 -vl 0");
  std::istringstream in("rvu -vta -vp 1 1 1 -vh 180 -vv 180\n\nrvu -vtl\n");
  c = parse({"-vf", "-"}, &in);
  EXPECT_EQ(c.opt.view.type, 'a');
  EXPECT_EQ(error_of({"-vf", "/no/such.vf"}), "cannot open view file \"/no/such.vf\"");
  EXPECT_EQ(error_of({"-vf", radcl::test::data("scenes/materials.rad")}),
            "bad view file \"" + radcl::test::data("scenes/materials.rad") + "\"");
}

TEST(RpictOptions, Errors) {
  EXPECT_EQ(error_of({"-vh", "180"}), "illegal horizontal view size");
  EXPECT_EQ(error_of({"-vtx"}), "unknown view type");
  EXPECT_EQ(error_of({"-vu", "0", "1", "0"}), "view up parallel to view direction");
  EXPECT_EQ(error_of({"-vp", "1", "2"}), "command line error at '-vp'");
  EXPECT_EQ(error_of({"-vt"}), "command line error at '-vt'");
  EXPECT_EQ(error_of({"-vtvv"}), "command line error at '-vtvv'");
  EXPECT_EQ(error_of({"-pq", "1"}), "command line error at '-pq'");
  EXPECT_EQ(error_of({"-x", "1.5"}), "command line error at '-x'");
  EXPECT_EQ(error_of({"-vf"}), "command line error at '-vf'");
  try {
    rpict_octree(parse({"a.oct", "b"}));
    FAIL();
  } catch (const radcl::FatalError& e) {
    EXPECT_STREQ(e.what(), "command line error at 'a.oct'");
  }
  try {
    rpict_octree(parse({"-S", "1"}));
    FAIL();
  } catch (const radcl::FatalError& e) {
    EXPECT_STREQ(e.what(), "missing octree argument");
  }
}
