#include "core/option_codec.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <type_traits>
#include <limits>

#include "core/strings.h"

namespace cls {
namespace {

// A value JSON holds natively. A number from a file goes through the command line's parser, so that a
// file is held to the same rules (1.5 is no integer, -1 no seed).
template <class T>
Codec<T> json_native(std::function<std::string(const T&)> text, std::function<T(const std::string&)> parse) {
  Codec<T> c;
  c.text = std::move(text);
  c.parse = std::move(parse);
  c.to_json = [](const T& v) { return nlohmann::json(v); };
  c.from_json = [parse = c.parse](const nlohmann::json& j) {
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      if (!j.is_number()) throw std::invalid_argument("expects a number, got " + j.dump());
      return parse(j.dump());
    } else {
      return j.get<T>();
    }
  };
  return c;
}

// The whole text as one integer in [lo, hi].
long long parse_integer(const std::string& s, long long lo, long long hi, const char* what) {
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi)
    throw std::invalid_argument(std::string("expects ") + what + ", got '" + s + "'");
  return v;
}

}  // namespace

std::string option_key(const std::string& name) {
  std::string key = name;
  for (char& c : key)
    if (c == '-') c = '_';
  return key;
}

std::string one_of(const std::vector<std::string>& names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i)
    s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return s;
}

template <>
Codec<std::string> default_codec<std::string>() {
  return json_native<std::string>([](const std::string& v) { return v; }, [](const std::string& s) { return s; });
}

template <>
Codec<bool> default_codec<bool>() {
  return json_native<bool>([](const bool& v) { return std::string(v ? "true" : "false"); },
                           [](const std::string& s) {
                             if (s == "1" || s == "true" || s == "yes" || s == "on") return true;
                             if (s == "0" || s == "false" || s == "no" || s == "off") return false;
                             throw std::invalid_argument("expects true or false, got '" + s + "'");
                           });
}

template <>
Codec<int> default_codec<int>() {
  return json_native<int>([](const int& v) { return std::to_string(v); },
                          [](const std::string& s) {
                            return int(parse_integer(s, std::numeric_limits<int>::min(),
                                                     std::numeric_limits<int>::max(), "an integer"));
                          });
}

template <>
Codec<int64_t> default_codec<int64_t>() {
  return json_native<int64_t>([](const int64_t& v) { return std::to_string(v); },
                              [](const std::string& s) {
                                return int64_t(parse_integer(s, std::numeric_limits<int64_t>::min(),
                                                             std::numeric_limits<int64_t>::max(), "an integer"));
                              });
}

template <>
Codec<uint64_t> default_codec<uint64_t>() {
  return json_native<uint64_t>([](const uint64_t& v) { return std::to_string(v); },
                               [](const std::string& s) {
                                 char* end = nullptr;
                                 errno = 0;
                                 const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
                                 if (s.empty() || !std::isdigit(static_cast<unsigned char>(s[0])) || *end != '\0' ||
                                     errno == ERANGE)
                                   throw std::invalid_argument("expects a non-negative integer, got '" + s + "'");
                                 return uint64_t(v);
                               });
}

template <>
Codec<double> default_codec<double>() {
  return json_native<double>([](const double& v) { return format_number(v); },
                             [](const std::string& s) {
                               char* end = nullptr;
                               const double v = std::strtod(s.c_str(), &end);
                               if (s.empty() || *end != '\0') throw std::invalid_argument("expects a number, got '" + s + "'");
                               return v;
                             });
}

template <>
Codec<std::filesystem::path> default_codec<std::filesystem::path>() {
  Codec<std::filesystem::path> c;
  c.text = [](const std::filesystem::path& p) { return p.string(); };
  c.parse = [](const std::string& s) { return std::filesystem::path(s); };
  c.to_json = [](const std::filesystem::path& p) { return nlohmann::json(p.string()); };
  c.from_json = [](const nlohmann::json& j) { return std::filesystem::path(j.get<std::string>()); };
  return c;
}

template <>
Codec<std::vector<std::string>> default_codec<std::vector<std::string>>() {
  Codec<std::vector<std::string>> c;
  c.text = [](const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& item : v) s += (s.empty() ? "" : ",") + item;
    return s;
  };
  c.parse = [](const std::string& s) { return split_commas(s); };
  c.to_json = [](const std::vector<std::string>& v) { return nlohmann::json(v); };
  c.from_json = [](const nlohmann::json& j) { return j.get<std::vector<std::string>>(); };
  return c;
}

Codec<std::string> choice_codec(std::vector<std::string> names) {
  Codec<std::string> c = default_codec<std::string>();
  c.parse = [names](const std::string& s) {
    for (const std::string& n : names)
      if (n == s) return s;
    throw std::invalid_argument("must be " + one_of(names) + ", not '" + s + "'");
  };
  c.from_json = [parse = c.parse](const nlohmann::json& j) { return parse(j.get<std::string>()); };
  return c;
}

}  // namespace cls
