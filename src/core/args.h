#pragma once
// The command line of every subcommand, with the same --help format (defaults shown) and the same
// errors. Each option is declared once, bound to the field it sets (CLI11's style): its default is the
// field's value, --help shows it, and parse() writes the field; nothing looks an option up by name
// afterwards. Settings that also live in files (run.json, run-tiles.json) are declared in an
// OptionList (core/option_list.h), which declares its options here.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/option_codec.h"

namespace cls {

class Args {
 public:
  // --help prints "usage: <program> <command> ..."; tools outside the CLI pass program = "".
  Args(std::string command, std::string summary, std::string program = "citylangsplat");

  // --name VALUE (or --name=VALUE) into `field`.
  template <class T>
  Args& bind(const std::string& name, T& field, const std::string& help, Codec<T> codec = default_codec<T>()) {
    return add_option(name, codec.text(field), help, false, [&field, parse = codec.parse](const std::string& s) {
      field = parse(s);
    });
  }
  // --name without a value: sets `field` to `value`.
  Args& flag(const std::string& name, bool& field, const std::string& help, bool value = true);
  // A positional argument into `field` (required unless optional() follows).
  template <class T>
  Args& positional(const std::string& name, T& field, const std::string& help, Codec<T> codec = default_codec<T>()) {
    return add_positional(name, help, false, [&field, parse = codec.parse](const std::string& s) { field = parse(s); });
  }
  // The remaining positional arguments (required unless optional() follows).
  Args& rest(const std::string& name, std::vector<std::string>& values, const std::string& help);

  // Modifiers of the option or positional declared last.
  Args& required();                              // an option that must be given
  Args& optional();                              // a positional that may be absent
  Args& short_name(const std::string& letter);   // -r as well as --resolution
  Args& default_text(const std::string& text);   // --help's default when the field's value is not it

  // Returns false when --help was printed (the caller exits 0). Throws cls::UsageError.
  bool parse(int argc, char** argv);
  bool parse(const std::vector<std::string>& args);  // without the program name (tests)

  std::string help() const;
  const std::string& command() const { return command_; }

  // For OptionList: an option it applies itself, and what the command line gave for it.
  Args& declare(const std::string& name, const std::string& def, const std::string& help, bool is_flag);
  Args& declare_positional(const std::string& name, const std::string& help);
  bool given(const std::string& name) const { return given_.count(name) > 0; }
  const std::string& given_value(const std::string& name) const;

 private:
  using Assign = std::function<void(const std::string&)>;
  struct Spec {
    std::string name, short_name, def, help;
    bool is_flag = false, required = false;
    Assign assign;  // empty: applied by an OptionList
  };
  struct Pos {
    std::string name, help;
    bool required = true, repeated = false;
    Assign assign;
  };
  Args& add_option(const std::string& name, const std::string& def, const std::string& help, bool is_flag,
                   Assign assign);
  Args& add_positional(const std::string& name, const std::string& help, bool repeated, Assign assign);
  const Spec* find_spec(const std::string& token) const;
  void assign(const std::string& what, const Assign& to, const std::string& value) const;

  std::string command_, summary_, program_;
  std::vector<Spec> specs_;
  std::vector<Pos> positionals_;
  bool last_is_positional_ = false;
  // Option or positional name -> the value given ("1" for a flag; a repeated positional is not kept).
  std::map<std::string, std::string> given_;
};

}  // namespace cls
