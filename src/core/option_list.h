#pragma once
// The options of a settings struct, each declared once: its name, help, field and role. From that one
// list come the command line (declare / apply on Args), the JSON of a run's record and of files that
// carry settings to other processes (to_json / from_json), and the part of a stage's fingerprint that
// its settings make (to_json with OptionRole::Setting). COLMAP's option manager and PDAL's stage
// options follow the same idea; docs/development.md ("Options") says how to add one.
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/args.h"
#include "core/error.h"
#include "core/option_codec.h"

namespace cls {

enum class OptionRole {
  Setting,   // the results depend on it: part of the fingerprint of every stage that uses it
  Location,  // where an input or output is (inputs' contents are fingerprinted, not their paths)
  Control,   // how a job runs, not what it computes (resume, device, stop after a stage)
};

template <class S>
class OptionList {
 public:
  struct Binding {
    std::string name, short_name, help, default_text;
    std::string positional;  // the argument's name when it is positional (SCENE_DIR), else ""
    OptionRole role = OptionRole::Setting;
    bool flag = false;       // a bool option written without a value (its default is false)
    bool per_scene = false;  // differs between scenes of one job (run-tiles does not carry it)
    bool required = false;   // the command line must give it
    std::function<std::string(const S&)> text;
    std::function<void(S&, const std::string&)> parse;
    std::function<nlohmann::json(const S&)> to_json;
    std::function<void(S&, const nlohmann::json&)> from_json;
  };

  // `field` is a pointer to a member of S, or a function of S& returning the field (a nested member).
  template <class Field, class T = std::decay_t<std::invoke_result_t<Field, S&>>>
  OptionList& add(std::string name, Field field, std::string help, OptionRole role = OptionRole::Setting,
                  Codec<T> codec = default_codec<T>()) {
    auto get = [field](S& s) -> T& { return std::invoke(field, s); };
    Binding b;
    b.name = std::move(name);
    b.help = std::move(help);
    b.role = role;
    b.flag = std::is_same_v<T, bool>;
    // Reading a field through the accessor of a non-const S: it is only read.
    b.text = [get, text = codec.text](const S& s) { return text(get(const_cast<S&>(s))); };
    b.parse = [get, parse = codec.parse](S& s, const std::string& v) { get(s) = parse(v); };
    b.to_json = [get, to = codec.to_json](const S& s) { return to(get(const_cast<S&>(s))); };
    b.from_json = [get, from = codec.from_json](S& s, const nlohmann::json& j) { get(s) = from(j); };
    push(std::move(b));
    return *this;
  }
  // Options of another list, of the T that `get` (a member pointer or accessor, as in add) gives: the
  // ones named, in that order, declared where they are declared.
  template <class T, class Get>
  OptionList& include(const OptionList<T>& other, Get get, const std::vector<std::string>& names) {
    for (const std::string& name : names) {
      const typename OptionList<T>::Binding* found = nullptr;
      for (const auto& ob : other.bindings())
        if (ob.name == name) found = &ob;
      if (!found) throw std::logic_error("include: no option --" + name);
      auto part = [get](const S& s) -> T& { return std::invoke(get, const_cast<S&>(s)); };
      Binding b;
      b.name = found->name;
      b.short_name = found->short_name;
      b.help = found->help;
      b.default_text = found->default_text;
      b.role = found->role;
      b.flag = found->flag;
      b.positional = found->positional;
      b.per_scene = found->per_scene;
      b.required = found->required;
      b.text = [part, text = found->text](const S& s) { return text(part(s)); };
      b.parse = [part, parse = found->parse](S& s, const std::string& v) { parse(part(s), v); };
      b.to_json = [part, to = found->to_json](const S& s) { return to(part(s)); };
      b.from_json = [part, from = found->from_json](S& s, const nlohmann::json& j) { from(part(s), j); };
      push(std::move(b));
    }
    return *this;
  }
  // Modifiers of the option added last.
  OptionList& short_name(std::string letter) { return last().short_name = std::move(letter), *this; }
  OptionList& default_text(std::string text) { return last().default_text = std::move(text), *this; }
  OptionList& positional(std::string argument) { return last().positional = std::move(argument), *this; }
  OptionList& per_scene() { return last().per_scene = true, *this; }
  OptionList& required() { return last().required = true, *this; }

  const std::vector<Binding>& bindings() const { return bindings_; }

  // Each option (those `keep` accepts) into `args`, with `defaults`' value as its default.
  void declare(Args& args, const S& defaults, const std::function<bool(const Binding&)>& keep = {}) const {
    for (const Binding& b : bindings_) {
      if (keep && !keep(b)) continue;
      if (!b.positional.empty()) {
        args.declare_positional(b.positional, b.help);
        continue;
      }
      args.declare(b.name, b.default_text.empty() ? b.text(defaults) : b.default_text, b.help, b.flag);
      if (!b.short_name.empty()) args.short_name(b.short_name);
      if (b.required) args.required();
    }
  }
  // The fields of the options the command line gave (after Args::parse), of those declared with `keep`.
  void apply(const Args& args, S& s, const std::function<bool(const Binding&)>& keep = {}) const {
    for (const Binding& b : bindings_) {
      if (keep && !keep(b)) continue;
      const std::string& key = b.positional.empty() ? b.name : b.positional;
      if (!args.given(key)) continue;
      try {
        b.parse(s, args.given_value(key));
      } catch (const std::invalid_argument& e) {
        throw UsageError(args.command() + ": " + (b.positional.empty() ? "--" + b.name : b.positional) + " " +
                         e.what());
      }
    }
  }

  // Every option's value (or those of one role: OptionRole::Setting for fingerprints).
  nlohmann::json to_json(const S& s, const std::function<bool(const Binding&)>& keep = {}) const {
    nlohmann::json j = nlohmann::json::object();
    for (const Binding& b : bindings_)
      if (!keep || keep(b)) j[option_key(b.name)] = b.to_json(s);
    return j;
  }
  nlohmann::json settings_json(const S& s) const {
    return to_json(s, [](const Binding& b) { return b.role == OptionRole::Setting; });
  }
  // The options `j` holds; an unknown key or a value of the wrong kind is a cls::Error naming `file`.
  void from_json(const nlohmann::json& j, S& s, const std::string& file) const {
    if (!j.is_object()) fail(file, "settings must be a JSON object");
    for (const auto& [key, value] : j.items()) {
      const Binding* b = find_key(key);
      if (!b) fail(file, "unknown setting \"" + key + "\"");
      try {
        b->from_json(s, value);
      } catch (const std::exception& e) {
        fail(file, "setting \"" + key + "\": " + e.what());
      }
    }
  }

 private:
  void push(Binding b) {
    for (const Binding& other : bindings_)
      if (other.name == b.name) throw std::logic_error("option --" + b.name + " declared twice");
    bindings_.push_back(std::move(b));
  }
  Binding& last() {
    if (bindings_.empty()) throw std::logic_error("an option modifier before any option");
    return bindings_.back();
  }
  const Binding* find_key(const std::string& key) const {
    for (const Binding& b : bindings_)
      if (option_key(b.name) == key) return &b;
    return nullptr;
  }

  std::vector<Binding> bindings_;
};

}  // namespace cls
