#include "citymodel/gml_coordinates.h"

#include <charconv>
#include <cmath>

namespace cls {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// One xs:double token (a leading '+' is allowed, as in XML Schema). Returns "" or the problem.
std::string parse_number(std::string_view token, double& value) {
  std::string_view digits = token;
  if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
  const char* end = digits.data() + digits.size();
  const auto r = std::from_chars(digits.data(), end, value);
  if (digits.empty() || r.ec != std::errc() || r.ptr != end) return "unparsable number \"" + std::string(token) + "\"";
  if (!std::isfinite(value)) return "non-finite number \"" + std::string(token) + "\"";
  return "";
}

// Splits `text` at `sep` (any whitespace if sep is whitespace), skipping empty pieces.
template <class F>
std::string for_each_piece(std::string_view text, char sep, F&& f) {
  const bool ws = is_space(sep);
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (ws ? is_space(text[i]) : text[i] == sep)) ++i;
    size_t j = i;
    while (j < text.size() && !(ws ? is_space(text[j]) : text[j] == sep)) ++j;
    if (j > i) {
      std::string err = f(text.substr(i, j - i));
      if (!err.empty()) return err;
    }
    i = j;
  }
  return "";
}

}  // namespace

std::string parse_double_list(std::string_view text, std::vector<double>& out) {
  return for_each_piece(text, ' ', [&](std::string_view token) {
    double v = 0;
    std::string err = parse_number(token, v);
    if (err.empty()) out.push_back(v);
    return err;
  });
}

std::string parse_gml_coordinates(std::string_view text, char decimal, char cs, char ts,
                                  std::vector<std::array<double, 3>>& out) {
  return for_each_piece(text, ts, [&](std::string_view tuple) -> std::string {
    std::array<double, 3> p{0, 0, 0};
    int n = 0;
    std::string err = for_each_piece(tuple, cs, [&](std::string_view token) -> std::string {
      if (n == 3) return "coordinate tuple \"" + std::string(tuple) + "\" has more than 3 values";
      std::string number(token);
      for (char& c : number)
        if (c == decimal) c = '.';
      return parse_number(number, p[n++]);
    });
    if (!err.empty()) return err;
    if (n < 2) return "coordinate tuple \"" + std::string(tuple) + "\" has fewer than 2 values";
    out.push_back(p);
    return "";
  });
}

}  // namespace cls
