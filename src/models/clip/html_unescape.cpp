#include "models/clip/html_unescape.h"

#include <string_view>
#include <unordered_map>

#include "models/clip/unicode_text.h"

namespace cls::clip {
namespace {

struct Entity {
  const char* name;
  const char* utf8;
};
const Entity kEntities[] = {
#include "models/clip/html_entities.inc"
};

const std::unordered_map<std::string, std::u32string>& entity_table() {
  static const std::unordered_map<std::string, std::u32string> table = [] {
    std::unordered_map<std::string, std::u32string> t;
    for (const Entity& e : kEntities) t.emplace(e.name, utf8_to_utf32(e.utf8));
    return t;
  }();
  return table;
}

const std::u32string* find_entity(const std::u32string& name) {
  std::string key;
  for (char32_t c : name) {
    if (c >= 0x80) return nullptr;  // every entity name is ASCII
    key.push_back(static_cast<char>(c));
  }
  const auto& t = entity_table();
  auto it = t.find(key);
  return it == t.end() ? nullptr : &it->second;
}

bool is_invalid_codepoint(uint64_t n) {
  return (n >= 0x1 && n <= 0x8) || n == 0xB || (n >= 0xE && n <= 0x1F) || (n >= 0x7F && n <= 0x9F) ||
         (n >= 0xFDD0 && n <= 0xFDEF) || (n <= 0x10FFFF && (n & 0xFFFE) == 0xFFFE);
}

// html._replace_charref for a numeric reference: digits without the '#', '#x' and ';'.
std::u32string numeric_reference(const std::u32string& digits, int base) {
  uint64_t n = 0;
  for (char32_t c : digits) {
    const int d = c <= '9' ? int(c - '0') : c >= 'a' ? int(c - 'a' + 10) : int(c - 'A' + 10);
    n = n * base + d;
    if (n > 0x10FFFF) n = 0x110000;  // saturate: anything larger is the same case
  }
  if (n == 0) return U"\uFFFD";
  if (n == 0x0D) return U"\r";
  if (n >= 0x80 && n <= 0x9F) return std::u32string(1, cp1252_char(static_cast<unsigned char>(n)));
  if ((n >= 0xD800 && n <= 0xDFFF) || n > 0x10FFFF) return U"\uFFFD";
  if (is_invalid_codepoint(n)) return U"";
  return std::u32string(1, static_cast<char32_t>(n));
}

bool is_digit(char32_t c) { return c >= '0' && c <= '9'; }
bool is_hex(char32_t c) {
  return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}
bool is_ascii_alnum(char32_t c) {
  return is_digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

}  // namespace

char32_t cp1252_char(unsigned char b) {
  static const char16_t k80[32] = {
      0x20AC, 0x81,   0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
      0x2039, 0x0152, 0x8D,   0x017D, 0x8F,   0x90,   0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
      0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0x9D,   0x017E, 0x0178};
  return (b >= 0x80 && b <= 0x9F) ? k80[b - 0x80] : b;
}

// Mirrors the regex &(#[0-9]+;?|#[xX][0-9a-fA-F]+;?|[^\t\n\f <&#;]{1,32};?) and _replace_charref.
std::u32string html_unescape(const std::u32string& s) {
  if (s.find(U'&') == std::u32string::npos) return s;
  std::u32string out;
  out.reserve(s.size());
  const size_t n = s.size();
  size_t i = 0;
  while (i < n) {
    if (s[i] != U'&') { out.push_back(s[i++]); continue; }
    size_t j = i + 1;
    if (j < n && s[j] == U'#') {
      size_t k = j + 1;
      int base = 10;
      if (k < n && (s[k] == U'x' || s[k] == U'X')) {
        base = 16;
        ++k;
      }
      const size_t d0 = k;
      while (k < n && (base == 16 ? is_hex(s[k]) : is_digit(s[k]))) ++k;
      if (k == d0) { out.push_back(s[i++]); continue; }  // "&#" with no digits: literal
      const std::u32string digits = s.substr(d0, k - d0);
      if (k < n && s[k] == U';') ++k;
      out += numeric_reference(digits, base);
      i = k;
      continue;
    }
    size_t k = j;
    while (k < n && k - j < 32) {
      const char32_t c = s[k];
      if (c == U'\t' || c == U'\n' || c == U'\f' || c == U' ' || c == U'<' || c == U'&' ||
          c == U'#' || c == U';')
        break;
      ++k;
    }
    if (k == j) { out.push_back(s[i++]); continue; }
    if (k < n && s[k] == U';') ++k;
    const std::u32string name = s.substr(j, k - j);
    if (const std::u32string* rep = find_entity(name)) {
      out += *rep;
    } else {
      bool found = false;
      for (size_t x = name.size() - 1; x > 1; --x) {  // longest legacy prefix, e.g. "&copy2024"
        if (const std::u32string* r = find_entity(name.substr(0, x))) {
          out += *r;
          out += name.substr(x);
          found = true;
          break;
        }
      }
      if (!found) {
        out.push_back(U'&');
        out += name;
      }
    }
    i = k;
  }
  return out;
}

std::u32string ftfy_unescape_html(const std::u32string& s) {
  if (s.find(U'&') == std::u32string::npos) return s;
  std::u32string out;
  out.reserve(s.size());
  const size_t n = s.size();
  size_t i = 0;
  while (i < n) {
    if (s[i] != U'&') { out.push_back(s[i++]); continue; }
    size_t k = i + 1;
    const bool numeric = k < n && s[k] == U'#';
    if (numeric) ++k;
    const size_t b = k;
    while (k < n && k - b < 24 && is_ascii_alnum(s[k])) ++k;
    if (k == b || k >= n || s[k] != U';') { out.push_back(s[i++]); continue; }
    const std::u32string match = s.substr(i, k + 1 - i);  // "&...;"
    const std::u32string name = s.substr(b, k + 1 - b);   // "...;" without '&' / '&#'
    std::u32string rep = match;
    if (numeric) {
      const std::u32string u = html_unescape(match);
      if (u.find(U';') == std::u32string::npos) rep = u;
    } else if (const std::u32string* r = find_entity(name)) {
      rep = *r;
    } else {
      // ftfy adds "&NAME;" for every lower-case name whose upper-case spelling html.unescape
      // leaves alone, decoding to the upper-cased character(s).
      std::u32string lower = name;
      bool all_upper = true;
      for (char32_t& c : lower) {
        if (c >= 'a' && c <= 'z') all_upper = false;
        if (c >= 'A' && c <= 'Z') c = c - 'A' + 'a';
      }
      const std::u32string* lower_entity = all_upper ? find_entity(lower) : nullptr;
      if (lower_entity && html_unescape(match) == match) rep = to_upper(*lower_entity);
    }
    out += rep;
    i = k + 1;
  }
  return out;
}

}  // namespace cls::clip
