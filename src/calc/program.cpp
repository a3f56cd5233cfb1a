#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "radcl/calc/library.h"
#include "radcl/calc/program.h"
#include "radcl/util/error.h"

namespace radcl::calc {

std::string qualify(std::string_view name, const std::string& context) {
  std::string n(name);
  if (n.empty()) return n;
  if (n.back() == '`') return n.substr(0, n.size() - 1); // name` : global
  if (n.front() == '`')
    n.erase(0, 1); // `name : local
  else if (n.find('`') != std::string::npos)
    return n; // explicit a`b
  return context.empty() ? n : n + "`" + context;
}

Program::Program() = default;
Program::~Program() = default;

const Definition* Program::lookup(std::string_view name, const std::string& context) const {
  std::string n(name);
  auto find = [&](const std::string& key) -> const Definition* {
    auto it = defs_.find(key);
    return it == defs_.end() ? nullptr : it->second.get();
  };
  if (n.empty()) return nullptr;
  if (n.front() == '`' || n.back() == '`' || n.find('`') != std::string::npos)
    return find(qualify(n, context));
  if (!context.empty())
    if (const Definition* d = find(n + "`" + context)) return d;
  return find(n);
}

void Program::define(Definition def) {
  def.id = next_id_++;
  auto it = defs_.find(def.name);
  if (it != defs_.end()) {
    const Definition& old = *it->second;
    bool same = old.constant == def.constant && old.function == def.function &&
                old.params == def.params && old.body == def.body;
    if (!same)
      warning(def.name + (old.constant ? ": redefined constant expression" : ": redefined"));
  } else if (def.function && find_library(def.name)) {
    warning(def.name + ": definition hides library function");
  }
  std::string key = def.name;
  defs_[key] = std::make_unique<Definition>(std::move(def));
}

void Program::set_parameter(std::string_view name, const std::string& context, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  Definition def;
  def.name = qualify(name, context);
  def.context = context;
  def.body = parse_expression(text, context, "parameter").root;
  def.id = next_id_++;
  std::string key = def.name;
  defs_[key] = std::make_unique<Definition>(std::move(def));
}

std::vector<const Definition*> Program::definitions() const {
  std::vector<const Definition*> out;
  for (const auto& [name, d] : defs_)
    out.push_back(d.get());
  std::sort(out.begin(), out.end(), [](auto* a, auto* b) { return a->id < b->id; });
  return out;
}

void Program::load_file(const std::string& path, const std::string& context) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FatalError(path + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  load_string(text.str(), path, context);
}

std::string Program::context_for_file(std::string_view file) {
  if (file == ".") return "";
  std::size_t slash = file.find_last_of('/');
  if (slash != std::string_view::npos) file.remove_prefix(slash + 1);
  if (file.size() > 4 && file.substr(file.size() - 4) == ".cal") file.remove_suffix(4);
  std::string ctx(file);
  for (char& c : ctx)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) c = '_';
  return ctx;
}

} // namespace radcl::calc
