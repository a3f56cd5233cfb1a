#include "radcl/options/rtrace_options.h"

#include "cformat.h"
#include "radcl/options/ray_io.h"
#include "radcl/util/error.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace radcl::options {
namespace {

// -te/-ti/-tE/-tI: the trace list, like the ambient list.
void add_trace_name(ModifierList& list, char letter, const std::string& value,
                    const FileFinder& find_file) {
  const bool include = letter == 'i' || letter == 'I';
  const auto kind = include ? ModifierList::Kind::Include : ModifierList::Kind::Exclude;
  if (list.kind != kind) {
    list.kind = kind;
    list.names.clear();
  }
  if (letter == 'i' || letter == 'e') {
    list.names.push_back(value);
    return;
  }
  std::string path = find_file(value);
  std::ifstream in(path, std::ios::binary);
  if (path.empty() || !in)
    throw FatalError(std::string("cannot open trace ") + (include ? "include" : "exclude") +
                     " file \"" + value + "\"");
  std::ostringstream ss;
  ss << in.rdbuf();
  for (auto& w : split_words(ss.str()))
    list.names.push_back(std::move(w));
}

// Handles rtrace's own option at args[i]; returns the number of values consumed.
int parse_own_option(RtraceOptions& o, const ArgList& a, std::size_t i,
                     const FileFinder& find_file) {
  const std::string& w = a[i];
  auto bad = [&]() -> int { command_line_error(w); };
  auto check = [&](std::size_t len, const char* types) {
    if (w.size() != len || !a.values_ok(i, types)) bad();
  };
  auto boolean = [&](std::size_t pos, bool& v) {
    if (!apply_bool_suffix(w, pos, v)) bad();
    return 0;
  };
  const char c2 = w.size() > 2 ? w[2] : '\0';
  switch (w.size() > 1 ? w[1] : '\0') {
  case 'n':
    check(2, "i");
    o.nproc = std::atoi(a[i + 1].c_str());
    if (o.nproc <= 0) throw FatalError("bad number of processes");
    return 1;
  case 'x':
    check(2, "i");
    o.xres = std::atoi(a[i + 1].c_str());
    return 1;
  case 'y':
    check(2, "i");
    o.yres = std::atoi(a[i + 1].c_str());
    return 1;
  case 'w':
    return boolean(2, o.warnings);
  case 'e':
    check(2, "s");
    o.error_file = a[i + 1];
    return 1;
  case 'l':
    if (c2 != 'd') bad();
    return boolean(3, o.limit_distance);
  case 'I':
    return boolean(2, o.immediate_irradiance);
  case 'f': {
    if (c2 != 'a' && c2 != 'f' && c2 != 'd') bad();
    o.in_format = c2;
    const char c3 = w.size() > 3 ? w[3] : '\0';
    if (c3 == '\0') {
      o.out_format = o.in_format;
    } else if (c3 == 'a' || c3 == 'f' || c3 == 'd' || c3 == 'c') {
      if (w.size() != 4) bad();
      o.out_format = c3;
    } else {
      bad();
    }
    return 0;
  }
  case 'o':
    o.output_spec = w.substr(2);
    return 0;
  case 'h':
    return boolean(2, o.header);
  case 't':
    if (c2 != 'i' && c2 != 'I' && c2 != 'e' && c2 != 'E') bad();
    check(3, "s");
    add_trace_name(o.trace_list, c2, a[i + 1], find_file);
    return 1;
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
  default:
    return bad();
  }
}

} // namespace

RtraceCommand parse_rtrace_command_line(std::vector<std::string> argv,
                                        const FileFinder& find_file) {
  RtraceCommand cmd;
  ArgList a(std::move(argv));
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
    if (n < 0) n = parse_own_option(cmd.opt, a, i, find_file);
    i += static_cast<std::size_t>(n);
  }
  if (cmd.action == ParsedCommand::Action::Run && cmd.opt.nproc > 1 &&
      cmd.opt.persist != RtraceOptions::Persist::None)
    throw FatalError("multiprocessing incompatible with persist file");
  cmd.operand = i < a.size() ? i : a.size();
  cmd.args = a.words();
  return cmd;
}

std::string rtrace_octree(const RtraceCommand& cmd) {
  const std::size_t n = cmd.args.size();
  if (cmd.operand >= n) throw FatalError("missing octree argument");
  if (cmd.operand + 1 < n) command_line_error(cmd.args[cmd.operand]);
  return cmd.args[cmd.operand];
}

std::string format_rtrace_defaults(const RtraceOptions& o) {
  std::string s;
  if (o.immediate_irradiance) s += "-I+\t\t\t\t# immediate irradiance on\n";
  s += cformat("-n %-2d\t\t\t\t# number of rendering processes\n", o.nproc);
  s += cformat("-x %-9d\t\t\t# %s\n", o.xres, o.yres && o.xres ? "x resolution" : "flush interval");
  s += cformat("-y %-9d\t\t\t# y resolution\n", o.yres);
  s +=
      o.limit_distance ? "-ld+\t\t\t\t# limit distance on\n" : "-ld-\t\t\t\t# limit distance off\n";
  s += cformat("-h%c\t\t\t\t# %s header\n", o.header ? '+' : '-', o.header ? "output" : "no");
  s += cformat("-f%c%c\t\t\t\t# format input/output = %s/%s\n", o.in_format, o.out_format,
               format_name(o.in_format), format_name(o.out_format));
  s += cformat("-o%-9s\t\t\t# output", o.output_spec.c_str());
  for (char c : o.output_spec) {
    switch (c) {
    case 't':
    case 'T':
      s += " trace";
      break;
    case 'o':
      s += " origin";
      break;
    case 'd':
      s += " direction";
      break;
    case 'r':
      s += " reflect_contrib";
      break;
    case 'R':
      s += " reflect_length";
      break;
    case 'x':
      s += " unreflect_contrib";
      break;
    case 'X':
      s += " unreflect_length";
      break;
    case 'e':
      s += " std_error";
      break;
    case 'v':
      s += " value";
      break;
    case 'V':
      s += " contribution";
      break;
    case 'l':
      s += " length";
      break;
    case 'L':
      s += " first_length";
      break;
    case 'p':
      s += " point";
      break;
    case 'n':
      s += " normal";
      break;
    case 'N':
      s += " unperturbed_normal";
      break;
    case 's':
      s += " surface";
      break;
    case 'w':
      s += " weight";
      break;
    case 'W':
      s += " coefficient";
      break;
    case 'm':
      s += " modifier";
      break;
    case 'M':
      s += " material";
      break;
    case '-':
      s += " stroke";
      break;
    }
  }
  s += '\n';
  s += o.warnings ? "-w+\t\t\t\t# warning messages on\n" : "-w-\t\t\t\t# warning messages off\n";
  s += format_render_defaults(o.render);
  return s;
}

} // namespace radcl::options
