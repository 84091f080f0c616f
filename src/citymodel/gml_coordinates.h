#pragma once
// Number lists of GML geometry: gml:posList / gml:pos (whitespace-separated xs:double) and the
// older gml:coordinates (tuples with configurable separators). Parsed in double, locale-free.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace cls {

// Appends the whitespace-separated numbers of `text` to `out`. Returns "" on success, else what is
// wrong ("unparsable number \"1.2x\"", "non-finite number \"NaN\"").
std::string parse_double_list(std::string_view text, std::vector<double>& out);

// Appends the points of a gml:coordinates text: tuples separated by `ts`, coordinates by `cs`,
// decimal point `decimal` (GML defaults: ts ' ' (any whitespace), cs ',', decimal '.').
// Tuples of 2 coordinates get z = 0. Returns "" or what is wrong.
std::string parse_gml_coordinates(std::string_view text, char decimal, char cs, char ts,
                                  std::vector<std::array<double, 3>>& out);

}  // namespace cls
