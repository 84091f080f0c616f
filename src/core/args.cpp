#include "core/args.h"

#include <cstdlib>
#include <iostream>
#include <sstream>

#include "core/error.h"

namespace cls {

Args::Args(std::string command, std::string summary, std::string program)
    : command_(std::move(command)), summary_(std::move(summary)), program_(std::move(program)) {
  flag("help", "show this help and exit", "h");
}

Args& Args::option(const std::string& name, const std::string& def, const std::string& help,
                   const std::string& short_name) {
  specs_.push_back({name, short_name, def, help, false});
  values_[name] = def;
  return *this;
}

Args& Args::flag(const std::string& name, const std::string& help, const std::string& short_name) {
  specs_.push_back({name, short_name, "", help, true});
  return *this;
}

Args& Args::positional(const std::string& name, const std::string& help, bool required, bool repeated) {
  positionals_.push_back({name, help, required, repeated});
  return *this;
}

const Args::Spec* Args::find_spec(const std::string& token) const {
  for (const auto& s : specs_)
    if (token == "--" + s.name || (!s.short_name.empty() && token == "-" + s.short_name)) return &s;
  return nullptr;
}

bool Args::parse(int argc, char** argv) {
  std::vector<std::string> a;
  for (int i = 1; i < argc; ++i) a.emplace_back(argv[i]);
  return parse(a);
}

bool Args::parse(const std::vector<std::string>& args) {
  size_t pos_index = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string tok = args[i];
    if (tok.size() > 1 && tok[0] == '-' && !(tok.size() > 1 && (std::isdigit(tok[1]) || tok[1] == '.'))) {
      std::string value;
      bool inline_value = false;
      const auto eq = tok.find('=');
      if (tok.rfind("--", 0) == 0 && eq != std::string::npos) {
        value = tok.substr(eq + 1);
        tok = tok.substr(0, eq);
        inline_value = true;
      }
      const Spec* s = find_spec(tok);
      if (!s) throw UsageError(command_ + ": unknown option '" + tok + "' (see --help)");
      if (s->name == "help") {
        std::cout << help();
        return false;
      }
      if (s->is_flag) {
        if (inline_value) throw UsageError(command_ + ": option --" + s->name + " takes no value");
        values_[s->name] = "1";
      } else {
        if (!inline_value) {
          if (i + 1 >= args.size()) throw UsageError(command_ + ": option --" + s->name + " needs a value");
          value = args[++i];
        }
        values_[s->name] = value;
      }
      continue;
    }
    if (pos_index >= positionals_.size())
      throw UsageError(command_ + ": unexpected argument '" + tok + "' (see --help)");
    const Pos& p = positionals_[pos_index];
    if (p.repeated) {
      rest_.push_back(tok);
      if (!values_.count(p.name)) values_[p.name] = tok;
    } else {
      values_[p.name] = tok;
      ++pos_index;
    }
  }
  for (const auto& p : positionals_)
    if (p.required && !values_.count(p.name))
      throw UsageError(command_ + ": missing argument " + p.name + " (see --help)");
  return true;
}

std::string Args::help() const {
  std::ostringstream s;
  s << "usage: " << (program_.empty() ? "" : program_ + " ") << command_;
  for (const auto& p : positionals_)
    s << " " << (p.required ? "" : "[") << p.name << (p.repeated ? "..." : "") << (p.required ? "" : "]");
  s << " [options]\n\n" << summary_ << "\n";
  if (!positionals_.empty()) {
    s << "\narguments:\n";
    for (const auto& p : positionals_) s << "  " << p.name << "\n      " << p.help << "\n";
  }
  s << "\noptions:\n";
  for (const auto& sp : specs_) {
    s << "  " << (sp.short_name.empty() ? "" : "-" + sp.short_name + ", ") << "--" << sp.name
      << (sp.is_flag ? "" : " VALUE") << "\n      " << sp.help;
    if (!sp.is_flag) s << (sp.def.empty() ? " (no default)" : " (default: " + sp.def + ")");
    s << "\n";
  }
  return s.str();
}

const std::string& Args::get(const std::string& name) const {
  static const std::string empty;
  auto it = values_.find(name);
  return it == values_.end() ? empty : it->second;
}

bool Args::has(const std::string& name) const {
  auto it = values_.find(name);
  return it != values_.end() && !it->second.empty();
}

bool Args::flag_set(const std::string& name) const { return has(name); }

int Args::get_int(const std::string& name) const {
  const std::string& v = get(name);
  char* end = nullptr;
  const long r = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0') throw UsageError(command_ + ": --" + name + " expects an integer, got '" + v + "'");
  return static_cast<int>(r);
}

double Args::get_double(const std::string& name) const {
  const std::string& v = get(name);
  char* end = nullptr;
  const double r = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0') throw UsageError(command_ + ": --" + name + " expects a number, got '" + v + "'");
  return r;
}

}  // namespace cls
