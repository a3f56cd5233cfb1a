#include "radcl/options/rpict_options.h"

#include "cformat.h"
#include "radcl/util/error.h"

#include <cstdlib>

namespace radcl::options {
namespace {

int parse_own_option(RpictOptions& o, const ArgList& a, std::size_t i, const std::string& progname,
                     std::istream* stdin_in) {
  const std::string& w = a[i];
  auto bad = [&]() -> int { command_line_error(w); };
  auto check = [&](std::size_t len, const char* types) {
    if (w.size() != len || !a.values_ok(i, types)) bad();
  };
  auto real = [&](double& v) {
    check(3, "f");
    v = std::atof(a[i + 1].c_str());
    return 1;
  };
  auto integer = [&](std::size_t len, int& v) {
    check(len, "i");
    v = std::atoi(a[i + 1].c_str());
    return 1;
  };
  auto word = [&](std::size_t len, std::string& v) {
    check(len, "s");
    v = a[i + 1];
    return 1;
  };
  const char c2 = w.size() > 2 ? w[2] : '\0';
  switch (w.size() > 1 ? w[1] : '\0') {
  case 'v': {
    if (c2 != 'f') return bad();
    check(3, "s");
    const std::string& file = a[i + 1];
    int n = read_view_file(file, o.view, progname, stdin_in);
    if (n < 0) throw FatalError("cannot open view file \"" + file + "\"");
    if (n == 0) throw FatalError("bad view file \"" + file + "\"");
    return 1;
  }
  case 'p':
    switch (c2) {
    case 's':
      return integer(3, o.pixel_sample);
    case 't':
      return real(o.pixel_threshold);
    case 'j':
      return real(o.pixel_jitter);
    case 'a':
      return real(o.pixel_aspect);
    case 'm':
      return real(o.pixel_motion);
    case 'd':
      return real(o.pixel_aperture);
    }
    return bad();
  case 'x':
    return integer(2, o.xres);
  case 'y':
    return integer(2, o.yres);
  case 'S':
    return integer(2, o.sequence_start);
  case 'o':
    return word(2, o.output_file);
  case 'z':
    return word(2, o.z_file);
  case 'r':
    if (c2 == 'o') {
      check(3, "s");
      o.output_file = a[i + 1];
    } else {
      check(2, "s");
    }
    o.recover_file = a[i + 1];
    return 1;
  case 't':
    return integer(2, o.report_interval);
  case 'P':
    if (c2 == 'P') {
      check(3, "s");
      o.persist = RtraceOptions::Persist::Parallel;
    } else {
      check(2, "s");
      o.persist = RtraceOptions::Persist::Single;
    }
    o.persist_file = a[i + 1];
    return 1;
  case 'w':
    if (!apply_bool_suffix(w, 2, o.warnings)) bad();
    return 0;
  case 'e':
    return word(2, o.error_file);
  default:
    return bad();
  }
}

} // namespace

RpictCommand parse_rpict_command_line(std::vector<std::string> argv, const FileFinder& find_file,
                                      std::istream* stdin_in) {
  RpictCommand cmd;
  ArgList a(std::move(argv));
  const std::string progname = a.size() ? a[0] : "rpict";
  std::size_t i = 1;
  for (; i < a.size(); ++i) {
    a.expand(i);
    if (i >= a.size() || a[i].empty() || a[i][0] != '-') break;
    if (a[i] == "-version") {
      cmd.action = ParsedCommand::Action::PrintVersion;
      break;
    }
    if (a[i] == "-defaults" || a[i] == "-help") {
      cmd.action = ParsedCommand::Action::PrintDefaults;
      break;
    }
    int n = parse_render_option(cmd.opt.render, a, i, find_file);
    if (n < 0) n = parse_view_option(cmd.opt.view, a, i);
    if (n < 0) n = parse_own_option(cmd.opt, a, i, progname, stdin_in);
    i += static_cast<std::size_t>(n);
  }
  cmd.operand = i < a.size() ? i : a.size();
  cmd.args = a.words();
  if (cmd.action == ParsedCommand::Action::Run) {
    std::string err = setup_view(cmd.opt.view);
    if (!err.empty()) throw FatalError(err);
  }
  return cmd;
}

std::string rpict_octree(const RpictCommand& cmd) {
  const std::size_t n = cmd.args.size();
  if (cmd.operand + 1 < n) command_line_error(cmd.args[cmd.operand]);
  std::string oct = cmd.operand < n ? cmd.args[cmd.operand] : "";
  if (cmd.opt.sequence_start > 0 && oct.empty()) throw FatalError("missing octree argument");
  return oct;
}

std::string format_rpict_defaults(const RpictOptions& o) {
  const View& v = o.view;
  const char* type = v.type == 'v'   ? "perspective"
                     : v.type == 'l' ? "parallel"
                     : v.type == 'h' ? "hemispherical"
                     : v.type == 'a' ? "angular"
                     : v.type == 'c' ? "cylindrical"
                     : v.type == 's' ? "planisphere"
                                     : "unknown";
  std::string s;
  s += cformat("-vt%c\t\t\t\t# view type %s\n", v.type, type);
  s += cformat("-vp %f %f %f\t# view point\n", v.point[0], v.point[1], v.point[2]);
  s += cformat("-vd %f %f %f\t# view direction\n", v.direction[0], v.direction[1], v.direction[2]);
  s += cformat("-vu %f %f %f\t# view up\n", v.up[0], v.up[1], v.up[2]);
  s += cformat("-vh %f\t\t\t# view horizontal size\n", v.horiz);
  s += cformat("-vv %f\t\t\t# view vertical size\n", v.vert);
  s += cformat("-vo %f\t\t\t# view fore clipping plane\n", v.fore);
  s += cformat("-va %f\t\t\t# view aft clipping plane\n", v.aft);
  s += cformat("-vs %f\t\t\t# view shift\n", v.shift);
  s += cformat("-vl %f\t\t\t# view lift\n", v.lift);
  s += cformat("-x  %-9d\t\t\t# x resolution\n", o.xres);
  s += cformat("-y  %-9d\t\t\t# y resolution\n", o.yres);
  s += cformat("-pa %f\t\t\t# pixel aspect ratio\n", o.pixel_aspect);
  s += cformat("-pj %f\t\t\t# pixel jitter\n", o.pixel_jitter);
  s += cformat("-pm %f\t\t\t# pixel motion\n", o.pixel_motion);
  s += cformat("-pd %f\t\t\t# pixel depth-of-field\n", o.pixel_aperture);
  s += cformat("-ps %-9d\t\t\t# pixel sample\n", o.pixel_sample);
  s += cformat("-pt %f\t\t\t# pixel threshold\n", o.pixel_threshold);
  s += cformat("-t  %-9d\t\t\t# time between reports\n", o.report_interval);
  s += o.warnings ? "-w+\t\t\t\t# warning messages on\n" : "-w-\t\t\t\t# warning messages off\n";
  s += format_render_defaults(o.render);
  return s;
}

} // namespace radcl::options
