#pragma once
// A small declarative argument parser so that every subcommand has the same --help format
// (with defaults) and the same error messages.
#include <map>
#include <string>
#include <vector>

namespace cls {

class Args {
 public:
  // --help prints "usage: <program> <command> ..."; tools outside the CLI pass program = "".
  Args(std::string command, std::string summary, std::string program = "citylangsplat");

  // --name VALUE (or --name=VALUE). `def` is shown in --help; "" means no default.
  Args& option(const std::string& name, const std::string& def, const std::string& help,
               const std::string& short_name = "");
  // --name (boolean).
  Args& flag(const std::string& name, const std::string& help, const std::string& short_name = "");
  // Positional argument; the last one may be `repeated` (collects the rest).
  Args& positional(const std::string& name, const std::string& help, bool required = true,
                   bool repeated = false);

  // Returns false when --help was printed (the caller exits 0). Throws cls::UsageError.
  bool parse(int argc, char** argv);
  // For tests: parse from a vector of arguments (without the program name).
  bool parse(const std::vector<std::string>& args);

  std::string help() const;

  const std::string& get(const std::string& name) const;  // option or positional
  bool has(const std::string& name) const;                // option given/defaulted non-empty, or positional present
  bool flag_set(const std::string& name) const;
  int get_int(const std::string& name) const;
  double get_double(const std::string& name) const;
  const std::vector<std::string>& rest() const { return rest_; }  // values of a repeated positional

 private:
  struct Spec {
    std::string name, short_name, def, help;
    bool is_flag = false;
  };
  struct Pos {
    std::string name, help;
    bool required = true, repeated = false;
  };
  const Spec* find_spec(const std::string& token) const;

  std::string command_, summary_, program_;
  std::vector<Spec> specs_;
  std::vector<Pos> positionals_;
  std::map<std::string, std::string> values_;
  std::vector<std::string> rest_;
};

}  // namespace cls
