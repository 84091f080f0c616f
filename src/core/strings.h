#pragma once
#include <string>
#include <utility>
#include <vector>

namespace cls {

// The non-empty items of a comma-separated list ("a,,b," -> {"a", "b"}).
std::vector<std::string> split_commas(const std::string& s);
// `s` without leading and trailing spaces, tabs and line breaks.
std::string trim_space(const std::string& s);
// ASCII letters lower-cased (file extensions, names); other bytes unchanged.
std::string ascii_lower(std::string s);
// A number as a person writes it, for --help defaults: 0.2, 5, 0.0001 (ostream's shortest form).
std::string format_number(double v);
// "k=1.5,m=2" -> {{"k", 1.5}, {"m", 2}}, spaces around items ignored; cls::UsageError "<usage>: ..." for an
// item without "=" or a value that is not one finite number.
std::vector<std::pair<std::string, double>> key_numbers(const std::string& text, const std::string& usage);

}  // namespace cls
