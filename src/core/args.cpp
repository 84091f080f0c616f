#include "core/args.h"

#include <cctype>
#include <iostream>
#include <sstream>

#include "core/error.h"

namespace cls {

Args::Args(std::string command, std::string summary, std::string program)
    : command_(std::move(command)), summary_(std::move(summary)), program_(std::move(program)) {
  specs_.push_back({"help", "h", "", "show this help and exit", true, false, {}});
}

Args& Args::add_option(const std::string& name, const std::string& def, const std::string& help, bool is_flag,
                       Assign assign) {
  for (const Spec& s : specs_)
    if (s.name == name) throw std::logic_error(command_ + ": option --" + name + " declared twice");
  specs_.push_back({name, "", def, help, is_flag, false, std::move(assign)});
  last_is_positional_ = false;
  return *this;
}

Args& Args::add_positional(const std::string& name, const std::string& help, bool repeated, Assign assign) {
  positionals_.push_back({name, help, true, repeated, std::move(assign)});
  last_is_positional_ = true;
  return *this;
}

Args& Args::flag(const std::string& name, bool& field, const std::string& help, bool value) {
  return add_option(name, "", help, true, [&field, value](const std::string&) { field = value; });
}

Args& Args::rest(const std::string& name, std::vector<std::string>& values, const std::string& help) {
  return add_positional(name, help, true, [&values](const std::string& s) { values.push_back(s); });
}

Args& Args::declare(const std::string& name, const std::string& def, const std::string& help, bool is_flag) {
  return add_option(name, def, help, is_flag, {});
}

Args& Args::declare_positional(const std::string& name, const std::string& help) {
  return add_positional(name, help, false, {});
}

Args& Args::required() {
  if (last_is_positional_) positionals_.back().required = true;
  else specs_.back().required = true;
  return *this;
}

Args& Args::optional() {
  if (!last_is_positional_) throw std::logic_error(command_ + ": optional() must follow a positional");
  positionals_.back().required = false;
  return *this;
}

Args& Args::short_name(const std::string& letter) {
  if (last_is_positional_) throw std::logic_error(command_ + ": short_name() must follow an option");
  specs_.back().short_name = letter;
  return *this;
}

Args& Args::default_text(const std::string& text) {
  if (last_is_positional_) throw std::logic_error(command_ + ": default_text() must follow an option");
  specs_.back().def = text;
  return *this;
}

const std::string& Args::given_value(const std::string& name) const {
  static const std::string empty;
  const auto it = given_.find(name);
  return it == given_.end() ? empty : it->second;
}

const Args::Spec* Args::find_spec(const std::string& token) const {
  for (const auto& s : specs_)
    if (token == "--" + s.name || (!s.short_name.empty() && token == "-" + s.short_name)) return &s;
  return nullptr;
}

void Args::assign(const std::string& what, const Assign& to, const std::string& value) const {
  try {
    to(value);
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception& e) {
    throw UsageError(command_ + ": " + what + " " + e.what());
  }
}

bool Args::parse(int argc, char** argv) {
  std::vector<std::string> a;
  for (int i = 1; i < argc; ++i) a.emplace_back(argv[i]);
  return parse(a);
}

bool Args::parse(const std::vector<std::string>& args) {
  size_t pos_index = 0;
  std::vector<std::pair<const Pos*, std::string>> positional_values;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string tok = args[i];
    // "-2.5" is a value (a negative number), not an option.
    if (tok.size() > 1 && tok[0] == '-' && !(std::isdigit(static_cast<unsigned char>(tok[1])) || tok[1] == '.')) {
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
        value = "1";
      } else if (!inline_value) {
        if (i + 1 >= args.size()) throw UsageError(command_ + ": option --" + s->name + " needs a value");
        value = args[++i];
      }
      // An empty value is no value: `--out "$OUT"` with OUT unset keeps the default (or is refused when
      // the option is required) instead of writing into the working directory.
      if (!s->is_flag && value.empty()) {
        given_.erase(s->name);
        continue;
      }
      given_[s->name] = value;
      continue;
    }
    if (pos_index >= positionals_.size())
      throw UsageError(command_ + ": unexpected argument '" + tok + "' (see --help)");
    const Pos& p = positionals_[pos_index];
    positional_values.emplace_back(&p, tok);
    if (!p.repeated) {
      given_[p.name] = tok;
      ++pos_index;
    }
  }
  for (const Pos& p : positionals_) {
    bool present = false;
    for (const auto& [pos, value] : positional_values) present = present || pos == &p;
    if (p.required && !present) throw UsageError(command_ + ": missing argument " + p.name + " (see --help)");
  }
  for (const Spec& s : specs_)
    if (s.required && !given(s.name)) throw UsageError(command_ + ": --" + s.name + " is required (see --help)");
  // Fields are written once everything was read, in the order of the command line's positionals and the
  // declaration's options, so that the first error reported does not depend on the arguments' order.
  for (const auto& [p, value] : positional_values)
    if (p->assign) assign(p->name + ":", p->assign, value);
  for (const Spec& s : specs_)
    if (s.assign && given(s.name)) assign("--" + s.name, s.assign, given_value(s.name));
  return true;
}

std::string Args::help() const {
  // A help text's own line breaks continue under its first line.
  const auto indented = [](const std::string& text) {
    std::string out;
    for (const char c : text) out += c == '\n' ? std::string("\n      ") : std::string(1, c);
    return out;
  };
  std::ostringstream s;
  s << "usage: " << (program_.empty() ? "" : program_ + " ") << command_;
  for (const auto& p : positionals_)
    s << " " << (p.required ? "" : "[") << p.name << (p.repeated ? "..." : "") << (p.required ? "" : "]");
  s << " [options]\n\n" << summary_ << "\n";
  if (!positionals_.empty()) {
    s << "\narguments:\n";
    for (const auto& p : positionals_) s << "  " << p.name << "\n      " << indented(p.help) << "\n";
  }
  s << "\noptions:\n";
  for (const auto& sp : specs_) {
    s << "  " << (sp.short_name.empty() ? "" : "-" + sp.short_name + ", ") << "--" << sp.name
      << (sp.is_flag ? "" : " VALUE") << "\n      " << indented(sp.help);
    if (sp.required) s << " (required)";
    else if (!sp.is_flag && !sp.def.empty()) s << " (default: " + sp.def + ")";
    // A help text that says its default in words ("default: the built-in one") needs no second note.
    else if (!sp.is_flag && sp.help.find("default:") == std::string::npos) s << " (no default)";
    s << "\n";
  }
  return s.str();
}

}  // namespace cls
