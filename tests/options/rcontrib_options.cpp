// rcontrib's command line: defaults, every option, the modifier rules, the .cal hooks in
// command-line order, errors with Radiance's messages, and the -defaults listing of Radiance
// 5.4's rcontrib (checked against its binary).
#include "radcl/options/rcontrib_options.h"
#include "radcl/util/error.h"
#include "temp_dir.h"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>

using namespace radcl::options;

namespace {

const char* const kRcontribDefaults =
    "-c 1    \t\t\t# accumulated rays per record\n"
    "-V-\t\t\t\t# output coefficients\n"
    "-n 1 \t\t\t\t# number of rendering processes\n"
    "-x 0        \t\t\t# flush interval\n"
    "-y 0        \t\t\t# y resolution\n"
    "-ld-\t\t\t\t# limit distance off\n"
    "-h+\t\t\t\t# output header\n"
    "-faa\t\t\t\t# format input/output = ascii/ascii\n"
    "-w+\t\t\t\t# warning messages on\n"
    "-i-\t\t\t\t# irradiance calculation off\n"
    "-u+\t\t\t\t# uncorrelated Monte Carlo sampling\n"
    "-bv+\t\t\t\t# back face visibility on\n"
    "-dt 0.000000\t\t\t# direct threshold\n"
    "-dc 0.750000\t\t\t# direct certainty\n"
    "-dj 0.900000\t\t\t# direct jitter\n"
    "-ds 0.200000\t\t\t# direct sampling\n"
    "-dr 3        \t\t\t# direct relays\n"
    "-dp 512      \t\t\t# direct pretest density\n"
    "-dv+\t\t\t\t# direct visibility on\n"
    "-ss 1.000000\t\t\t# specular sampling\n"
    "-st 0.020000\t\t\t# specular threshold\n"
    "-av 0.000000 0.000000 0.000000\t# ambient value\n"
    "-aw 0        \t\t\t# ambient value weight\n"
    "-ab 1        \t\t\t# ambient bounces\n"
    "-aa 0.000000\t\t\t# ambient accuracy\n"
    "-ar 256      \t\t\t# ambient resolution\n"
    "-ad 350      \t\t\t# ambient divisions\n"
    "-as 0        \t\t\t# ambient super-samples\n"
    "-me 0.00e+00 0.00e+00 0.00e+00\t# mist extinction coefficient\n"
    "-ma 0.000000 0.000000 0.000000\t# mist scattering albedo\n"
    "-mg 0.000000\t\t\t# mist scattering eccentricity\n"
    "-ms 0.000000\t\t\t# mist sampling distance\n"
    "-lr -10      \t\t\t# limit reflection (Russian roulette)\n"
    "-lw 2.00e-03\t\t\t# limit weight\n"
    "-am 0.0\t\t\t\t# max photon search radius\n";

// Hooks that log each call ("file:x", "expr:x", "params:x", "eval:x"); eval knows a few names.
struct FakeCal {
  std::vector<std::string> calls;
  CalHooks hooks() {
    CalHooks h;
    h.load_file = [this](const std::string& f) { calls.push_back("file:" + f); };
    h.load_expr = [this](const std::string& s) { calls.push_back("expr:" + s); };
    h.set_params = [this](const std::string& p) { calls.push_back("params:" + p); };
    h.eval = [this](const std::string& e) {
      calls.push_back("eval:" + e);
      if (e == "Nrbins") return 577.0;
      if (e == "Ntiny") return 0.4;
      return std::atof(e.c_str());
    };
    return h;
  }
};

RcontribCommand parse(std::vector<std::string> args, FakeCal* cal = nullptr) {
  args.insert(args.begin(), "rcontrib");
  FakeCal local;
  return parse_rcontrib_command_line(args, (cal ? cal : &local)->hooks());
}

std::string error_of(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const radcl::FatalError& e) {
    return e.what();
  }
  return "(no error)";
}

// The message of a malformed command line, which must come with the usage line.
std::string usage_error_of(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const RcontribUsageError& e) {
    return e.what();
  } catch (const radcl::FatalError& e) {
    return std::string("(not a usage error) ") + e.what();
  }
  return "(no error)";
}

} // namespace

TEST(RcontribOptions, Defaults) {
  RcontribCommand c = parse({"-m", "sky", "scene.oct"});
  const RcontribOptions& o = c.opt;
  EXPECT_EQ(c.action, RcontribCommand::Action::Run);
  EXPECT_EQ(c.operand, 3u);
  EXPECT_EQ(c.args[c.operand], "scene.oct");
  EXPECT_EQ(o.nproc, 1);
  EXPECT_FALSE(o.contributions);
  EXPECT_EQ(o.accumulate, 1);
  EXPECT_EQ(o.xres, 0);
  EXPECT_EQ(o.yres, 0);
  EXPECT_TRUE(o.warnings);
  EXPECT_FALSE(o.limit_distance);
  EXPECT_FALSE(o.immediate_irradiance);
  EXPECT_FALSE(o.force_open);
  EXPECT_FALSE(o.recover);
  EXPECT_TRUE(o.header);
  EXPECT_EQ(o.in_format, 'a');
  EXPECT_EQ(o.out_format, 'a');
  EXPECT_EQ(o.report_interval, 0);
  EXPECT_TRUE(o.cal.empty());
  ASSERT_EQ(o.modifiers.size(), 1u);
  const RcontribModifier& m = o.modifiers[0];
  EXPECT_EQ(m.name, "sky");
  EXPECT_FALSE(m.outspec.has_value());
  EXPECT_EQ(m.params, "");
  EXPECT_EQ(m.bin_expr, "0");
  EXPECT_EQ(m.nbins, 1);
  const RenderOptions& r = o.render;
  EXPECT_DOUBLE_EQ(r.direct_jitter, 0.9);
  EXPECT_EQ(r.direct_relays, 3);
  EXPECT_DOUBLE_EQ(r.specular_threshold, 0.02);
  EXPECT_EQ(r.ambient_bounces, 1);
  EXPECT_EQ(r.ambient_divisions, 350);
  EXPECT_TRUE(r.uncorrelated);
  EXPECT_EQ(format_rcontrib_defaults(o), kRcontribDefaults);
}

TEST(RcontribOptions, DefaultsListingMatchesRadiance) {
  RcontribCommand c = parse({"-defaults"});
  EXPECT_EQ(c.action, RcontribCommand::Action::PrintDefaults);
  EXPECT_EQ(format_rcontrib_defaults(c.opt), kRcontribDefaults);
  EXPECT_EQ(parse({"-help"}).action, RcontribCommand::Action::PrintDefaults);
  EXPECT_EQ(parse({"-version", "-bogus"}).action, RcontribCommand::Action::PrintVersion);
  // Radiance overrides -dt/-as/-aa before listing, and drops -x/-y when -c is not positive.
  c = parse({"-dt", ".5", "-as", "9", "-aa", ".3", "-c", "0", "-x", "5", "-y", "4", "-I", "-V",
             "-defaults", "ignored"});
  std::string s = format_rcontrib_defaults(c.opt);
  EXPECT_EQ(s.substr(0, s.find("-ld")), "-c 0    \t\t\t# accumulated rays per record\n"
                                        "-V+\t\t\t\t# output contributions\n"
                                        "-I+\t\t\t\t# immediate irradiance on\n"
                                        "-n 1 \t\t\t\t# number of rendering processes\n"
                                        "-x 0        \t\t\t# flush interval\n"
                                        "-y 0        \t\t\t# y resolution\n");
  for (const char* line :
       {"-dt 0.000000\t\t\t# direct threshold\n", "-aa 0.000000\t\t\t# ambient accuracy\n",
        "-as 0        \t\t\t# ambient super-samples\n"})
    EXPECT_NE(s.find(line), std::string::npos) << line;
}

TEST(RcontribOptions, DefaultsListingShowsChangedValues) {
  RcontribCommand c = parse({"-c", "2", "-x", "5", "-y", "4", "-n", "3", "-ld", "-h-", "-ffc",
                             "-w-", "-i", "-ab", "2", "-defaults"});
  std::string s = format_rcontrib_defaults(c.opt);
  EXPECT_EQ(s.substr(0, s.find("-i+")),
            "-c 2    \t\t\t# accumulated rays per record\n"
            "-V-\t\t\t\t# output coefficients\n"
            "-n 3 \t\t\t\t# number of rendering processes\n"
            "-x 5        \t\t\t# x resolution\n"
            "-y 4        \t\t\t# y resolution\n"
            "-ld+\t\t\t\t# limit distance on\n"
            "-h-\t\t\t\t# no header\n"
            "-ffc\t\t\t\t# format input/output = float/32-bit_rle_rgbe\n"
            "-w-\t\t\t\t# warning messages off\n");
  EXPECT_NE(s.find("-ab 2        \t\t\t# ambient bounces\n"), std::string::npos);
}

TEST(RcontribOptions, EveryOption) {
  RcontribCommand c =
      parse({"-n", "4",  "-V",  "-c", "8",  "-x", "10", "-y",  "20", "-w",  "-ld+", "-I+",  "-fo",
             "-r", "-h", "-fd", "-t", "30", "-m", "a",  "-lr", "-5", "-ms", "0.5",  "x.oct"});
  const RcontribOptions& o = c.opt;
  EXPECT_EQ(o.nproc, 4);
  EXPECT_TRUE(o.contributions);
  EXPECT_EQ(o.accumulate, 8);
  EXPECT_EQ(o.xres, 10);
  EXPECT_EQ(o.yres, 20);
  EXPECT_FALSE(o.warnings);
  EXPECT_TRUE(o.limit_distance);
  EXPECT_TRUE(o.immediate_irradiance);
  EXPECT_TRUE(o.force_open);
  EXPECT_TRUE(o.recover);
  EXPECT_FALSE(o.header);
  EXPECT_EQ(o.in_format, 'd');
  EXPECT_EQ(o.out_format, 'd');
  EXPECT_EQ(o.report_interval, 30);
  EXPECT_EQ(o.render.max_depth, -5); // rendering options go on after the modifiers
  EXPECT_DOUBLE_EQ(o.render.mist_sampling, 0.5);
  EXPECT_EQ(c.args[c.operand], "x.oct");
  EXPECT_EQ(parse({"-faf", "-m", "a", "x"}).opt.out_format, 'f');
  EXPECT_EQ(parse({"-ffa", "-m", "a", "x"}).opt.in_format, 'f');
  EXPECT_EQ(parse({"-fac", "-m", "a", "x"}).opt.out_format, 'c');
  EXPECT_FALSE(parse({"-fo", "-fo-", "-m", "a", "x"}).opt.force_open);
  EXPECT_TRUE(parse({"-V-", "-Vy", "-m", "a", "x"}).opt.contributions);
}

TEST(RcontribOptions, RenderOptionsComeFirst) {
  // -me/-ma/-mg/-ms, -lr/-lw, -bv, -i and -u are Radiance's rendering options, not -m/-l/-b.
  RcontribCommand c =
      parse({"-me",  "1",    "2",  "3",   "-ma", ".1", ".2",  ".3",   "-mg", ".4", "-lw",
             "1e-4", "-bv-", "-i", "-u-", "-ab", "3",  "-ad", "1000", "-m",  "a",  "x"});
  const RenderOptions& r = c.opt.render;
  EXPECT_EQ(r.mist_extinction, (Rgb{1, 2, 3}));
  EXPECT_EQ(r.mist_albedo, (Rgb{.1, .2, .3}));
  EXPECT_DOUBLE_EQ(r.mist_eccentricity, .4);
  EXPECT_DOUBLE_EQ(r.min_weight, 1e-4);
  EXPECT_FALSE(r.back_visible);
  EXPECT_TRUE(r.irradiance);
  EXPECT_FALSE(r.uncorrelated);
  EXPECT_EQ(r.ambient_bounces, 3);
  EXPECT_EQ(r.ambient_divisions, 1000);
  ASSERT_EQ(c.opt.modifiers.size(), 1u);
}

TEST(RcontribOptions, OverriddenOptions) {
  // Radiance forces these whatever the command line says (override_options).
  RcontribCommand c =
      parse({"-dt", ".1", "-as", "64", "-aa", ".2", "-c", "0", "-x", "8", "-m", "a", "x"});
  EXPECT_DOUBLE_EQ(c.opt.render.direct_threshold, 0);
  EXPECT_EQ(c.opt.render.ambient_supersamples, 0);
  EXPECT_DOUBLE_EQ(c.opt.render.ambient_accuracy, 0);
  EXPECT_EQ(c.opt.xres, 0); // no flushing for a single record
  EXPECT_EQ(parse({"-c", "-1", "-y", "8", "-m", "a", "x"}).opt.yres, 0);
  EXPECT_EQ(parse({"-c", "2", "-x", "8", "-m", "a", "x"}).opt.xres, 8);
}

TEST(RcontribOptions, ModifiersTakeTheSettingsInForce) {
  FakeCal cal;
  RcontribCommand c =
      parse({"-m", "a",  "-o",   "out_%s.dat", "-p", "MF=2", "-m",         "b",   "-bn",
             "4",  "-b", "rbin", "-m",         "c",  "-o",   "second.dat", "-bn", "2.6",
             "-m", "d",  "-b",   "0",          "-m", "e",    "x"},
            &cal);
  const auto& m = c.opt.modifiers;
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[0].name, "a");
  EXPECT_FALSE(m[0].outspec);
  EXPECT_EQ(m[0].params, "");
  EXPECT_EQ(m[1].name, "b");
  EXPECT_EQ(m[1].outspec, "out_%s.dat");
  EXPECT_EQ(m[1].params, "MF=2");
  EXPECT_EQ(m[1].bin_expr, "0");
  EXPECT_EQ(m[1].nbins, 1); // -bn comes after
  EXPECT_EQ(m[2].bin_expr, "rbin");
  EXPECT_EQ(m[2].nbins, 4);
  EXPECT_EQ(m[3].outspec, "second.dat");
  EXPECT_EQ(m[3].params, "MF=2");
  EXPECT_EQ(m[3].bin_expr, "rbin");
  EXPECT_EQ(m[3].nbins, 3); // (int)(2.6 + .5)
  EXPECT_EQ(m[4].bin_expr, "0");
  EXPECT_EQ(m[4].nbins, 1); // a constant bin is one bin whatever -bn says
  EXPECT_EQ(cal.calls, (std::vector<std::string>{"params:MF=2", "eval:4", "eval:2.6"}));
}

TEST(RcontribOptions, CalHooksInCommandLineOrder) {
  FakeCal cal;
  RcontribCommand c = parse({"-e", "a=1;", "-p", "MF=2", "-f", "reinhartb.cal", "-bn", "Nrbins",
                             "-b", "rbin", "-m", "sky", "-e", "b=2;", "x"},
                            &cal);
  EXPECT_EQ(cal.calls, (std::vector<std::string>{"expr:a=1;", "params:MF=2", "file:reinhartb.cal",
                                                 "eval:Nrbins", "expr:b=2;"}));
  ASSERT_EQ(c.opt.cal.size(), 3u);
  EXPECT_FALSE(c.opt.cal[0].is_file);
  EXPECT_EQ(c.opt.cal[0].text, "a=1;");
  EXPECT_TRUE(c.opt.cal[1].is_file);
  EXPECT_EQ(c.opt.cal[1].text, "reinhartb.cal");
  EXPECT_EQ(c.opt.cal[2].text, "b=2;");
  ASSERT_EQ(c.opt.modifiers.size(), 1u);
  EXPECT_EQ(c.opt.modifiers[0].nbins, 577);
  EXPECT_EQ(c.opt.modifiers[0].params, "MF=2");
  // Without hooks the sources are still recorded, and -bn takes a plain number.
  c = parse_rcontrib_command_line(
      {"rcontrib", "-f", "a.cal", "-bn", "3", "-b", "rbin", "-m", "sky", "x"}, CalHooks{});
  EXPECT_EQ(c.opt.cal.size(), 1u);
  EXPECT_EQ(c.opt.modifiers[0].nbins, 3);
}

TEST(RcontribOptions, ConstantBinExpressions) {
  // Radiance reduces number-only expressions and wants (int)(value + 1.5) == 1.
  for (const char* ok : {"0", "0.4", "-0.5", "(0)", " 1 - 1 ", "2*3-6", "-2^2-4", "1e-3", "+0"}) {
    RcontribCommand c = parse({"-b", ok, "-m", "a", "x"});
    EXPECT_EQ(c.opt.modifiers[0].nbins, 1) << ok;
    EXPECT_EQ(c.opt.modifiers[0].bin_expr, ok);
  }
  for (const char* bad : {"1", "0.5", "-0.6", "-2^2+4", "2^-1+.25"})
    EXPECT_EQ(error_of({"-bn", "5", "-b", bad, "-m", "a", "x"}),
              std::string("illegal non-zero constant for bin (") + bad + ")")
        << bad;
  // Radiance calls 1/0 a bad constant expression; an error here too.
  EXPECT_NE(error_of({"-b", "1/0", "-m", "a", "x"}), "(no error)");
  // Anything with a name (or that is not plain arithmetic) needs the bin count.
  for (const char* expr : {"rbin", "2*x", "$1", "--1"}) {
    EXPECT_EQ(parse({"-bn", "2", "-b", expr, "-m", "a", "x"}).opt.modifiers[0].nbins, 2) << expr;
    EXPECT_EQ(error_of({"-b", expr, "-m", "a", "x"}),
              "unspecified or illegal bin count for modifier 'a'")
        << expr;
  }
  EXPECT_EQ(error_of({"-bn", "Ntiny", "-b", "rbin", "-m", "a", "x"}),
            "unspecified or illegal bin count for modifier 'a'"); // (int)(0.4 + .5) == 0
  EXPECT_EQ(error_of({"-bn", "-3", "-b", "rbin", "-m", "a", "x"}),
            "unspecified or illegal bin count for modifier 'a'");
  EXPECT_EQ(error_of({"-bn", "1e300", "-b", "rbin", "-m", "a", "x"}),
            "unspecified or illegal bin count for modifier 'a'");
}

TEST(RcontribOptions, ModifierFile) {
  const radcl::test::TempFolder dir("rcontrib");
  const std::string f = (dir / "mods.txt").string();
  std::ofstream(f) << "wall  floor\n\t'two words'\"q\"x\n";
  RcontribCommand c = parse({"-m", "sky", "-o", "%s.dat", "-M", f, "-m", "ceiling", "x"});
  std::vector<std::string> names;
  for (const auto& m : c.opt.modifiers)
    names.push_back(m.name);
  // Quotes group a word as Radiance's fgetword() does.
  EXPECT_EQ(names,
            (std::vector<std::string>{"sky", "wall", "floor", "two words", "q", "x", "ceiling"}));
  EXPECT_EQ(c.opt.modifiers[1].outspec, "%s.dat");
  EXPECT_FALSE(c.opt.modifiers[0].outspec);
  // The file is found with the caller's finder (RAYPATH in the front end).
  c = parse_rcontrib_command_line({"rcontrib", "-M", "mods.txt", "x"}, CalHooks{},
                                  [&](const std::string& n) { return n == "mods.txt" ? f : ""; });
  EXPECT_EQ(c.opt.modifiers.size(), 5u);
  EXPECT_EQ(error_of({"-m", "wall", "-M", f, "x"}), "duplicate modifier 'wall'");
  std::ofstream(f) << "a void b\n";
  EXPECT_EQ(error_of({"-M", f, "x"}), "cannot track 'void' modifier");
  try {
    parse({"-M", "/no/such/mods", "x"});
    FAIL();
  } catch (const radcl::SystemError& e) {
    EXPECT_STREQ(e.what(), "cannot find modifier file '/no/such/mods': No such file or directory");
  }
  try {
    parse_rcontrib_command_line({"rcontrib", "-M", "m", "x"}, CalHooks{},
                                [](const std::string&) { return "/no/such/path"; });
    FAIL();
  } catch (const radcl::SystemError& e) {
    EXPECT_STREQ(e.what(), "cannot load modifier file '/no/such/path': No such file or directory");
  }
  try {
    parse({"-M", dir.str(), "x"});
    FAIL();
  } catch (const radcl::SystemError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot load modifier file '" + dir.str() + "': Is a directory");
  }
}

TEST(RcontribOptions, ModifierErrors) {
  EXPECT_EQ(error_of({"-m", "a", "-m", "a", "x"}), "duplicate modifier 'a'");
  EXPECT_EQ(error_of({"-m", "void", "x"}), "cannot track 'void' modifier");
  EXPECT_EQ(error_of({"x.oct"}), "missing required modifier argument");
  EXPECT_EQ(error_of({"-ab", "2"}), "missing required modifier argument");
  // -o takes the next word whatever it is, so "a" is the octree here, as in Radiance.
  EXPECT_EQ(error_of({"-o", "-m", "a", "x"}), "missing required modifier argument");
}

TEST(RcontribOptions, Operand) {
  RcontribCommand c = parse({"-m", "a"});
  EXPECT_EQ(c.operand, c.args.size()); // "missing octree argument" is the caller's
  EXPECT_EQ(usage_error_of({"-m", "a", "x.oct", "y.oct"}), "command line error at 'x.oct'");
  EXPECT_EQ(usage_error_of({"-m", "a", "x.oct", "-ab", "2"}), "command line error at 'x.oct'");
}

TEST(RcontribOptions, CommandLineErrors) {
  for (const char* w : {"-zz", "-",   "-ab", "-n",  "-x",  "-c",  "-t",   "-m",  "-M",   "-e",
                        "-o",  "-p",  "-b",  "-bn", "-bx", "-f",  "-foq", "-Vx", "-ldq", "-lx",
                        "-ti", "-w2", "-rx", "-hx", "-Ix", "-nx", "-mx",  "-ex"})
    EXPECT_EQ(usage_error_of({w}), std::string("command line error at '") + w + "'") << w;
  EXPECT_EQ(usage_error_of({"-ab", "1.0", "-m", "a", "x"}), "command line error at '-ab'");
  EXPECT_EQ(usage_error_of({"-x", "1.5", "-m", "a", "x"}), "command line error at '-x'");
  EXPECT_EQ(usage_error_of({"-c", "n", "-m", "a", "x"}), "command line error at '-c'");
  EXPECT_EQ(usage_error_of({"-m", "", "x"}), "command line error at '-m'");
  EXPECT_EQ(error_of({"-n", "0", "-m", "a", "x"}), "bad number of processes");
  for (const char* f : {"-fx", "-fax", "-facd", "-fca"})
    EXPECT_EQ(usage_error_of({f, "-m", "a", "x"}),
              std::string("(not a usage error) Illegal i/o format: ") + f)
        << f;
  EXPECT_EQ(error_of({"$RADCL_SURELY_UNSET_VAR", "x"}), "cannot expand '$RADCL_SURELY_UNSET_VAR'");
  EXPECT_EQ(rcontrib_usage("rcontrib"),
            "Usage: rcontrib [-n nprocs][-V][-c count][-r][-e expr][-f source][-o ospec]"
            "[-p p1=V1,p2=V2][-b binv][-bn N] {-m mod | -M file} [rtrace options] octree\n");
}

TEST(RcontribOptions, ArgumentFileExpansion) {
  const radcl::test::TempFolder dir("rcontrib");
  const std::string f = (dir / "opts").string();
  std::ofstream(f) << "-ab 2 -ad 256\n-bn 3 -b rbin\n";
  setenv("RADCL_RCONTRIB_OCT", "scene.oct", 1);
  FakeCal cal;
  RcontribCommand c = parse({"@" + f, "-m", "sky", "$RADCL_RCONTRIB_OCT"}, &cal);
  EXPECT_EQ(c.opt.render.ambient_bounces, 2);
  EXPECT_EQ(c.opt.render.ambient_divisions, 256);
  EXPECT_EQ(c.opt.modifiers[0].nbins, 3);
  EXPECT_EQ(c.args, (std::vector<std::string>{"rcontrib", "-ab", "2", "-ad", "256", "-bn", "3",
                                              "-b", "rbin", "-m", "sky", "scene.oct"}));
  EXPECT_EQ(c.args[c.operand], "scene.oct"); // the operand is expanded too
}
