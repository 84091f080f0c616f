#include "core/strings.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace cls {

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string trim_space(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::vector<std::pair<std::string, double>> key_numbers(const std::string& text, const std::string& usage) {
  std::vector<std::pair<std::string, double>> out;
  for (const std::string& part : split_commas(text)) {
    const size_t eq = part.find('=');
    if (eq == std::string::npos) throw UsageError(usage + ": \"" + part + "\" is not KEY=NUMBER");
    const std::string key = trim_space(part.substr(0, eq)), value = trim_space(part.substr(eq + 1));
    double x = 0;
    size_t used = 0;
    try {
      x = std::stod(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != value.size() || !std::isfinite(x)) throw UsageError(usage + ": \"" + value + "\" is not a number");
    out.emplace_back(key, x);
  }
  return out;
}

std::string ascii_lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace cls
