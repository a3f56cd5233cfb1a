// A set of loaded .cal definitions: parsing of files and expressions, contexts (scopes) and
// name lookup as Radiance's renderers do it (../shared/docs/radiance/calc-language.md §2, §3.3,
// §5.3).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "radcl/calc/ast.h"

namespace radcl::calc {

class Program {
public:
  Program();
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  // Parses `text` as a sequence of `;`-separated statements; definitions are made in
  // `context` ("" = global). `source` names the text in error messages (a file name).
  // Syntax errors throw FatalError ("source, line N:\n<line>\n   ^ message").
  void load_string(std::string_view text, const std::string& source,
                   const std::string& context = "");
  // Reads and loads a file ("<path>: cannot open" if it cannot be read).
  void load_file(const std::string& path, const std::string& context = "");
  // Loads rayinit.cal into the global context, as the renderers do first.
  void load_rayinit();
  // Where that file is: on RAYPATH, else radcl's own library (util/library_path.h).
  static std::string rayinit_path();

  // Parses one expression (a scene string argument, a command-line expression).
  Expression parse_expression(std::string_view text, const std::string& context = "",
                              const std::string& source = "");

  // The definition `name` refers to from `context`: explicit qualified names (a`b) as written,
  // `name = local only, name` = global only, otherwise the context's own then the global one.
  // nullptr when none.
  const Definition* lookup(std::string_view name, const std::string& context) const;

  // The context a function file gets: its name without directories and a trailing ".cal",
  // characters not allowed in names replaced by '_'; "" for "." (no file).
  static std::string context_for_file(std::string_view file);

  // Every definition, in order of (latest) definition.
  std::vector<const Definition*> definitions() const;

  // Adds a parsed definition (replacing any previous one of that qualified name), with
  // Radiance's redefinition warnings.
  void define(Definition def);
  // `name` = value in `context`, replacing any definition silently (Radiance's varset, as
  // rcontrib's -p parameters are set).
  void set_parameter(std::string_view name, const std::string& context, double value);

private:
  std::unordered_map<std::string, std::unique_ptr<Definition>> defs_;
  int next_id_ = 0;
};

// Qualified storage name for a definition named `name` in `context`.
std::string qualify(std::string_view name, const std::string& context);

} // namespace radcl::calc
