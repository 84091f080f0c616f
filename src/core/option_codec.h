#pragma once
// How one option's value goes to and from text (the command line, --help's default) and JSON (run.json,
// run-tiles.json, stage fingerprints): the one conversion an option is declared with (core/args.h,
// core/option_list.h), so that its spellings cannot drift apart.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cls {

template <class T>
struct Codec {
  std::function<std::string(const T&)> text;            // as a person writes it (--help's default)
  std::function<T(const std::string&)> parse;           // std::invalid_argument saying what is expected
  std::function<nlohmann::json(const T&)> to_json;
  std::function<T(const nlohmann::json&)> from_json;    // std::invalid_argument or nlohmann's exceptions
};

// Text and JSON codecs of the plain types (std::string, bool, int, int64_t, uint64_t, double,
// std::filesystem::path, and std::vector<std::string> as a comma-separated list).
template <class T>
Codec<T> default_codec();

template <> Codec<std::string> default_codec<std::string>();
template <> Codec<bool> default_codec<bool>();
template <> Codec<int> default_codec<int>();
template <> Codec<int64_t> default_codec<int64_t>();
template <> Codec<uint64_t> default_codec<uint64_t>();
template <> Codec<double> default_codec<double>();
template <> Codec<std::filesystem::path> default_codec<std::filesystem::path>();
template <> Codec<std::vector<std::string>> default_codec<std::vector<std::string>>();

// The JSON key of an option: its name with '-' as '_' ("lambda-sam" -> "lambda_sam").
std::string option_key(const std::string& name);

// "a, b or c" of a list of names.
std::string one_of(const std::vector<std::string>& names);

// An enumeration by its names, in text and JSON alike.
template <class E>
Codec<E> enum_codec(std::vector<std::pair<std::string, E>> names) {
  auto shared = std::make_shared<const std::vector<std::pair<std::string, E>>>(std::move(names));
  Codec<E> c;
  c.text = [shared](const E& v) {
    for (const auto& [name, value] : *shared)
      if (value == v) return name;
    return std::string("?");
  };
  c.parse = [shared](const std::string& s) {
    std::vector<std::string> known;
    for (const auto& [name, value] : *shared) {
      if (name == s) return value;
      known.push_back(name);
    }
    throw std::invalid_argument("must be " + one_of(known) + ", not '" + s + "'");
  };
  c.to_json = [text = c.text](const E& v) { return nlohmann::json(text(v)); };
  c.from_json = [parse = c.parse](const nlohmann::json& j) { return parse(j.get<std::string>()); };
  return c;
}

// A value that may be absent (text "" and JSON null for none): an option without a default.
template <class T>
Codec<std::optional<T>> optional_codec(Codec<T> inner = default_codec<T>()) {
  Codec<std::optional<T>> c;
  c.text = [text = inner.text](const std::optional<T>& v) { return v ? text(*v) : std::string(); };
  c.parse = [parse = inner.parse](const std::string& s) { return std::optional<T>(parse(s)); };
  c.to_json = [to = inner.to_json](const std::optional<T>& v) { return v ? to(*v) : nlohmann::json(nullptr); };
  c.from_json = [from = inner.from_json](const nlohmann::json& j) {
    return j.is_null() ? std::optional<T>() : std::optional<T>(from(j));
  };
  return c;
}

// A string restricted to the names given (one vocabulary, e.g. --align off|refine|auto).
Codec<std::string> choice_codec(std::vector<std::string> names);

}  // namespace cls
