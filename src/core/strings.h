#pragma once
#include <string>
#include <vector>

namespace cls {

// The non-empty items of a comma-separated list ("a,,b," -> {"a", "b"}).
std::vector<std::string> split_commas(const std::string& s);
// `s` without leading and trailing spaces, tabs and line breaks.
std::string trim_space(const std::string& s);
// A number as a person writes it, for --help defaults: 0.2, 5, 0.0001 (ostream's shortest form).
std::string format_number(double v);

}  // namespace cls
