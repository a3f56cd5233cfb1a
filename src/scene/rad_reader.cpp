// Radiance scene files (../shared/docs/radiance/scene-format.md §1): the top-level loop of
// readobj(), primitives, alias, and the modifier index with its "identical redefinition" rule.
#include "radcl/scene/rad_reader.h"
#include "radcl/scene/command.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

#include "lexer.h"
#include "radcl/util/error.h"
#include "stdio_buf.h"
#include "words.h"

namespace radcl::scene {
namespace {

using detail::Lexer;

constexpr int kMaxCommandDepth = 64; // a command whose output runs itself again

class Reader {
public:
  Reader(SceneDescription& scene, const ReadPolicy& policy) : scene_(scene), policy_(policy) {}

  void read_path(const std::string& path);
  // Parses one input; returns whether it (with its commands) added any object.
  bool parse(std::streambuf* sb, const std::string& name);

private:
  struct Where {
    const std::string& name;
    int line;
  };
  [[noreturn]] static void fail(const Where& at, const std::string& msg) {
    throw FatalError("(" + at.name + " line " + std::to_string(at.line) + "): " + msg);
  }
  [[noreturn]] static void fail(const Where& at, const std::string& msg, const Object& o) {
    fail(at, msg + " for " + std::string(type_name(o.type)) + " \"" + o.name + "\"");
  }

  void read_primitive(Lexer& lx, const Where& at, std::int32_t file);
  static bool read_arguments(Lexer& lx, Object& o);
  void index_modifier(std::int32_t obj);
  bool same_objects(std::int32_t a, std::int32_t b) const;

  SceneDescription& scene_;
  const ReadPolicy& policy_;
  int depth_ = 0;
};

void Reader::read_path(const std::string& path) {
  if (path.empty() || path[0] != '!') {
    if (!policy_.open_files)
      throw FatalError("cannot open scene file \"" + path + "\": reading files is disabled");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) // it would open, then fail to read
      throw FatalError("cannot open scene file \"" + path + "\": " + std::strerror(EISDIR));
    std::filebuf fb;
    if (!fb.open(path, std::ios::in | std::ios::binary))
      throw FatalError("cannot open scene file \"" + path + "\": " + std::strerror(errno));
    if (!parse(&fb, path)) warning("(" + path + "): empty file");
    return;
  }
  if (!policy_.run_commands)
    throw FatalError("cannot execute \"" + path + "\": commands are disabled");
  if (depth_ >= kMaxCommandDepth) throw FatalError("(" + path + "): commands nested too deeply");
  std::fflush(nullptr); // nothing of ours may reach the command's output twice
  std::FILE* pipe = open_command(path.substr(1));
  if (!pipe) throw FatalError("cannot execute \"" + path + "\": " + std::strerror(errno));
  struct Closer { // the child is reaped even when parsing its output fails
    std::FILE* f;
    ~Closer() {
      if (f) pclose(f);
    }
  } closer{pipe};
  ++depth_;
  bool any;
  try {
    detail::StdioBuf buf(pipe);
    any = parse(&buf, path);
  } catch (...) {
    --depth_;
    throw;
  }
  --depth_;
  int status = pclose(pipe);
  closer.f = nullptr;
  if (status == -1) throw FatalError("(" + path + "): cannot get command status");
  if (WIFSIGNALED(status))
    throw FatalError("(" + path + "): command killed by signal " +
                     std::to_string(WTERMSIG(status)));
  if (WEXITSTATUS(status) != 0)
    throw FatalError("(" + path + "): command failed with exit status " +
                     std::to_string(WEXITSTATUS(status)));
  if (!any) warning("(" + path + "): empty file");
}

bool Reader::parse(std::streambuf* sb, const std::string& name) {
  const auto file = static_cast<std::int32_t>(scene_.files.size());
  scene_.files.push_back(name);
  const std::size_t first = scene_.objects.size();
  Lexer lx(sb);
  for (int c; (c = lx.get()) != Lexer::kEof;) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r') continue;
    if (c == '#') {
      lx.skip_comment();
    } else if (c == '!') {
      lx.unget(c);
      read_path(lx.command_line());
    } else {
      Where at{name, lx.line()};
      lx.unget(c);
      read_primitive(lx, at, file);
    }
  }
  return scene_.objects.size() != first;
}

void Reader::read_primitive(Lexer& lx, const Where& at, std::int32_t file) {
  Object o;
  o.file = file;
  o.line = at.line;

  std::string word = lx.word().value_or("EOF");
  if (word.find('\t') != std::string::npos) fail(at, "illegal tab in modifier \"" + word + "\"");
  const bool inherit = word == "inherit";
  if (!inherit && word != "void") {
    auto it = scene_.modifier_index.find(word);
    if (it == scene_.modifier_index.end()) fail(at, "undefined modifier \"" + word + "\"");
    o.modifier = it->second;
  }

  word = lx.word().value_or("EOF");
  auto type = type_from_name(word);
  if (!type) fail(at, "unknown type \"" + word + "\"");
  o.type = *type;

  o.name = lx.word().value_or("");
  if (o.name.find('\t') != std::string::npos)
    fail(at, "illegal tab in identifier \"" + o.name + "\"");

  if (o.type == RC_OBJ_ALIAS) {
    // "mod alias new ref": no argument counts. The reference is looked up in the index
    // as is (a modifier may even be called "void").
    word = lx.word().value_or("EOF");
    auto it = scene_.modifier_index.find(word);
    if (it == scene_.modifier_index.end()) fail(at, "bad reference \"" + word + "\"", o);
    const std::int32_t ref = it->second;
    // Pass-through form: the alias's modifier is the referenced object itself; otherwise it
    // keeps its own modifier and names the reference, resolved again at render time.
    if (inherit || o.modifier == scene_.objects[ref].modifier)
      o.modifier = ref;
    else
      o.sargs.push_back(word);
  } else {
    if (!read_arguments(lx, o)) fail(at, "bad arguments", o);
    if (inherit) fail(at, "inappropriate use of 'inherit' modifier", o);
    if (std::string problem = check_arguments(o); !problem.empty()) fail(at, problem, o);
  }

  scene_.objects.push_back(std::move(o));
  index_modifier(static_cast<std::int32_t>(scene_.objects.size() - 1));
}

// nS strings, nI = 0 integers, nR reals; false on a malformed count or number or early EOF.
bool Reader::read_arguments(Lexer& lx, Object& o) {
  auto count = [&lx](long long& n) {
    auto w = lx.word();
    if (!w || !detail::is_int_word(*w)) return false;
    n = detail::int_value(*w);
    return n >= 0;
  };
  long long n;
  if (!count(n)) return false;
  for (long long i = 0; i < n; ++i) {
    auto w = lx.word();
    if (!w) return false;
    o.sargs.push_back(std::move(*w));
  }
  if (!count(n) || n != 0) return false; // integer arguments do not exist in standard builds
  if (!count(n)) return false;
  for (long long i = 0; i < n; ++i) {
    auto w = lx.word();
    if (!w || !detail::is_real_word(*w)) return false;
    // A well-formed word can still overflow to Inf ("1e999"), which Radiance takes as is.
    double v = detail::real_value(*w);
    if (!std::isfinite(v)) return false;
    o.fargs.push_back(v);
  }
  return true;
}

// Radiance's insertobject(): a modifier replaces the index entry for its name unless it is
// identical to the object indexed now, in which case the older object stays indexed.
void Reader::index_modifier(std::int32_t obj) {
  const Object& o = scene_.objects[obj];
  if (!is_modifier(o.type)) return;
  auto [it, fresh] = scene_.modifier_index.try_emplace(o.name, obj);
  if (!fresh && !same_objects(obj, it->second)) it->second = obj;
}

// Radiance's eqobjects(): same type, arguments (reals to a relative 1e-6) and modifier chain;
// string arguments that name modifiers compare what they resolve to.
bool Reader::same_objects(std::int32_t a, std::int32_t b) const {
  auto same_real = [](double x, double y) {
    if (y != 0.0) x = x / y - 1.0;
    return -1e-6 <= x && x <= 1e-6;
  };
  while (a != b) {
    if (a == kVoid || b == kVoid) return false;
    const Object& x = scene_.objects[a];
    const Object& y = scene_.objects[b];
    if (x.type != y.type || x.sargs.size() != y.sargs.size() || x.fargs.size() != y.fargs.size())
      return false;
    for (std::size_t i = 0; i < x.fargs.size(); ++i)
      if (!same_real(x.fargs[i], y.fargs[i])) return false;
    std::size_t refs = 0; // leading string arguments that are modifier names
    switch (x.type) {
    case RC_OBJ_ALIAS:
    case RC_OBJ_ILLUM:
    case RC_OBJ_MIRROR:
      refs = x.sargs.empty() ? 0 : 1;
      break;
    case RC_OBJ_MIXFUNC:
    case RC_OBJ_MIXDATA:
    case RC_OBJ_MIXTEXT:
    case RC_OBJ_MIXPICT:
      refs = x.sargs.size() >= 2 ? 2 : 0;
      break;
    case RC_OBJ_ANTIMATTER:
      refs = x.sargs.size();
      break;
    default:
      break;
    }
    for (std::size_t i = refs; i < x.sargs.size(); ++i)
      if (x.sargs[i] != y.sargs[i]) return false;
    for (std::size_t i = 0; i < refs; ++i)
      if (!same_objects(scene_.last_modifier(a, x.sargs[i]), scene_.last_modifier(b, y.sargs[i])))
        return false;
    a = x.modifier;
    b = y.modifier;
  }
  return true;
}

} // namespace

void read_rad_file(SceneDescription& scene, const std::string& path, const ReadPolicy& policy) {
  Reader(scene, policy).read_path(path);
}

void read_rad_stream(SceneDescription& scene, std::istream& in, const std::string& name,
                     const ReadPolicy& policy) {
  if (!Reader(scene, policy).parse(in.rdbuf(), name)) warning("(" + name + "): empty file");
}

} // namespace radcl::scene
